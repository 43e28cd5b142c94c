#!/usr/bin/env bash
# Regenerates the data and plot of docs/performance.md: weft-bench throughput (sheets of 32²
# to 256² with all spring families, weft against the plain baseline, the machine's limits,
# drawing, self-collision), in a Release build, with the machine and its load recorded in
# the log. About two minutes on a 2-core machine. WEFT_THREADS=1 runs it on one thread.
usage="scripts/performance-report.sh"
source "$(dirname "$0")/help_or_version.sh"
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release -j 2 --target weft-bench
out=docs/performance
mkdir -p "$out"
{
    echo "machine:"
    lscpu | grep -E '^(Model name|CPU\(s\)|Thread|Core|L1d|L2|L3)'
    echo "memory: $(free -g | awk '/^Mem:/ {print $2}') GiB; $(. /etc/os-release && echo "$PRETTY_NAME"); $(g++ --version | head -1)"
    echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
    echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
    echo
    build/release/bench/weft_bench/weft-bench throughput --out "$out"
    echo
    echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
} 2>&1 | tee "$out/throughput.log"
