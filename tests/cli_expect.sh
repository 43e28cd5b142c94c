# Sourced by the command-line tests (tests/app/cli_test.sh, tests/bench/weft_bench_cli_test.sh).
# Before sourcing: $program (the binary under test), $work (a scratch folder), and
# failures=0 passes=0.

# expect STATUS STDERR_REGEX -- ARGS...: runs $program, checks its status and stderr
# (STDERR_REGEX "quiet": stderr must be empty). Its stdout is left in $work/out.
expect() {
  local status=$1 pattern=$2
  shift 3
  timeout 120 "$program" "$@" >"$work/out" 2>"$work/err"
  local actual=$?
  local stderr_ok=true
  if [ "$pattern" = quiet ]; then
    [ -s "$work/err" ] && stderr_ok=false
  else
    grep -Eq -- "$pattern" "$work/err" || stderr_ok=false
  fi
  if [ "$actual" -ne "$status" ] || [ "$stderr_ok" = false ]; then
    echo "FAIL: $(basename "$program") $*"
    echo "  expected status $status and stderr matching: $pattern"
    echo "  got status $actual, stderr:"; sed 's/^/    /' "$work/err" | head -5
    failures=$((failures + 1))
  else
    passes=$((passes + 1))
  fi
}

# check DESCRIPTION COMMAND...: a plain assertion.
check() {
  local description=$1
  shift
  if "$@"; then passes=$((passes + 1)); else echo "FAIL: $description"; failures=$((failures + 1)); fi
}
