#!/usr/bin/env bash
# weft vs Jolt Physics' XPBD soft-body cloth, in one run, interleaved, on this machine.
# For each case (128 calm, 128 hard_hand, 256 calm, 256 hard_hand), REPS rounds of:
#   weft on 1 thread, weft on 2 threads (WEFT_THREADS), Jolt at 5 iterations, Jolt at 20 iterations.
# weft: ms/step = the --profile "all" line (steps only); also wall time of the process / 180.
# Jolt: ms/frame = steady_clock around PhysicsSystem::Update, median over the 180 frames.
# Usage: ./compare.sh [REPS] [REPS_256]      (defaults 5 5)
set -euo pipefail
cd "$(dirname "$0")"
REPS=${1:-5}
REPS_256=${2:-$REPS}
WEFT_SRC=${WEFT_BIN:-../../build/release/src/app/weft}
SESS=../../assets/sessions
JOLT=./build/jolt_cloth
JOLT_RECIPE=(--compliance weft --bend distance --lra none --hold vertex)
OUT=out/compare_$(date -u +%Y%m%dT%H%M%SZ)
mkdir -p "$OUT"
RAW=$OUT/raw.tsv
: > "$RAW"
# weft's binary is rebuilt by others while we run: time one snapshot of it, copied here first.
WEFT=$OUT/weft
for try in 1 2 3 4 5; do
    cp "$WEFT_SRC" "$WEFT" 2>/dev/null && "$WEFT" --version > /dev/null 2>&1 && break
    sleep 5
done
"$WEFT" --version > /dev/null || { echo "cannot snapshot $WEFT_SRC"; exit 1; }

echo "# $(date -u '+%Y-%m-%d %H:%M UTC')  $(lscpu | grep 'Model name' | sed 's/  */ /g')  cores: $(nproc)"
echo "# weft snapshot of $WEFT_SRC (mtime $(date -u -r "$WEFT_SRC" '+%F %T'), sha256 $(sha256sum "$WEFT" | cut -c1-16)); HEAD $(git -C ../.. log -1 --format=%h) ($(git -C ../.. status --short | wc -l) paths modified/untracked)"
echo "# load before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "# weft:  WEFT_THREADS={1,2} $WEFT --headless --replay $SESS/cloth_<N>_<case>.toml --profile"
echo "# jolt:  $JOLT --size <N> --session <case> ${JOLT_RECIPE[*]} --iterations {5,20}   (1 thread: JobSystemSingleThreaded)"
echo "# reps: $REPS for 128, $REPS_256 for 256"

now_ns() { date +%s%N; }

run_weft() {  # N case threads rep
    local n=$1 c=$2 t=$3 rep=$4 t0 t1 log=$OUT/weft_${1}_${2}_t${3}_r${4}.txt
    t0=$(now_ns)
    WEFT_THREADS=$t "$WEFT" --headless --replay "$SESS/cloth_${n}_${c}.toml" --profile > "$log" 2>&1 || { echo "weft failed: see $log"; exit 1; }
    t1=$(now_ns)
    local prof steps
    prof=$(awk '$1=="all"{print $3}' "$log")
    steps=$(sed -n 's/^profile: \([0-9]*\) steps.*/\1/p' "$log")
    grep -q 'matches the recording' "$log" || echo "WARNING: weft replay did not match: $log"
    printf '%s\t%s\tweft_%st\t%s\t%s\n' "$n" "$c" "$t" "$prof" "$(awk -v a="$t0" -v b="$t1" -v s="$steps" 'BEGIN{printf "%.4f", (b-a)/1e6/s}')" >> "$RAW"
}

run_jolt() {  # N case iterations rep
    local n=$1 c=$2 it=$3 rep=$4 log=$OUT/jolt_${1}_${2}_i${3}_r${4}.txt
    "$JOLT" --size "$n" --session "$c" "${JOLT_RECIPE[@]}" --iterations "$it" > "$log" 2>&1 || echo "NOTE: jolt exit $? (non-finite state): $log"
    local med stretch
    med=$(sed -n 's/^RESULT median_ms=\([0-9.]*\).*/\1/p' "$log")
    stretch=$(sed -n 's/.*max_structural_stretch=\([0-9.naife+-]*\).*/\1/p' "$log")
    grep -q 'finite=NO' "$log" && stretch=NaN
    printf '%s\t%s\tjolt_i%s\t%s\t%s\n' "$n" "$c" "$it" "$med" "$stretch" >> "$RAW"
}

for n in ${SIZES:-128 256}; do
    reps=$REPS; [ "$n" = 256 ] && reps=$REPS_256
    for c in calm hard_hand; do
        for ((r = 1; r <= reps; r++)); do
            run_weft "$n" "$c" 1 "$r"
            run_jolt "$n" "$c" 5 "$r"
            run_weft "$n" "$c" 2 "$r"
            run_jolt "$n" "$c" 20 "$r"
        done
        # weft's end state, untimed, for its stretch
        WEFT_THREADS=2 "$WEFT" --headless --replay "$SESS/cloth_${n}_${c}.toml" --dump "$OUT/weft_${n}_${c}.csv" > /dev/null
        sp=$([ "$n" = 128 ] && echo 0.009055 || echo 0.0045098)
        printf '%s\t%s\tweft_stretch\t%s\t-\n' "$n" "$c" "$(python3 stretch.py "$OUT/weft_${n}_${c}.csv" "$sp" | awk '{print $2}')" >> "$RAW"
        rm -f "$OUT/weft_${n}_${c}.csv"
    done
done
echo "# load after: $(cut -d' ' -f1-3 /proc/loadavg)"

python3 - "$RAW" <<'EOF'
import sys, statistics as st
rows = [l.rstrip('\n').split('\t') for l in open(sys.argv[1]) if l.strip()]
def vals(n, c, who, col):
    return [float(r[col]) for r in rows if r[0] == n and r[1] == c and r[2] == who]
def fmt(v):
    return f"{st.median(v):8.2f} ({min(v):.2f}-{max(v):.2f})" if v else "-"
print()
print("ms per step/frame: median (min-max) over the reps; weft = profile 'all' ms/step [wall/step median]")
print(f"{'case':16} {'weft 1 thread':>24} {'weft 2 threads':>24} {'Jolt 5 it':>22} {'Jolt 20 it':>22} {'w1/J5':>6} {'w1/J20':>6} {'w2/J20':>6}")
for n in ("128", "256"):
    for c in ("calm", "hard_hand"):
        w1, w2 = vals(n, c, "weft_1t", 3), vals(n, c, "weft_2t", 3)
        w1w, w2w = vals(n, c, "weft_1t", 4), vals(n, c, "weft_2t", 4)
        j5, j20 = vals(n, c, "jolt_i5", 3), vals(n, c, "jolt_i20", 3)
        if not w1: continue
        r = lambda a, b: f"{st.median(a) / st.median(b):6.2f}" if a and b else "   -"
        print(f"{n + ' ' + c:16} {fmt(w1):>24} {fmt(w2):>24} {fmt(j5):>22} {fmt(j20):>22} {r(w1, j5)} {r(w1, j20)} {r(w2, j20)}")
        print(f"{'':16} {'[wall ' + format(st.median(w1w), '.2f') + ']':>24} {'[wall ' + format(st.median(w2w), '.2f') + ']':>24}")
print()
print("end stretch (largest structural edge length / rest), first rep:")
for n in ("128", "256"):
    for c in ("calm", "hard_hand"):
        ws = [r[3] for r in rows if r[0] == n and r[1] == c and r[2] == "weft_stretch"]
        j5 = [r[4] for r in rows if r[0] == n and r[1] == c and r[2] == "jolt_i5"]
        j20 = [r[4] for r in rows if r[0] == n and r[1] == c and r[2] == "jolt_i20"]
        mark = lambda v: "-" if not v else (f"{v[0]} DIVERGED" if v[0] == "NaN" or float(v[0]) > 5 else v[0])
        if ws: print(f"  {n} {c:10} weft {ws[0]:>8}   Jolt 5 it {mark(j5):>22}   Jolt 20 it {mark(j20):>22}")
print("  (DIVERGED: an edge past 5x its rest length, weft's own divergence test, or non-finite)")
EOF
echo "# raw: $RAW; per-run logs in $OUT"
