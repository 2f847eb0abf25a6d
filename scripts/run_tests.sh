#!/bin/sh
# Runs every test program in BUILD/tests (default build) and the script tests in tests/scripts/,
# then prints one summary line "N passed, N failed".
# Test programs find the shared data and the source tree through GENERIC_SOURCE_DIR.
BUILD=${1:-build}
GENERIC_SOURCE_DIR=$(pwd)
GENERIC_BUILD_DIR=$(cd "$BUILD" && pwd)
export GENERIC_SOURCE_DIR GENERIC_BUILD_DIR
pass=0
fail=0
run() { # name, log, command...
    name=$1
    log=$2
    shift 2
    if "$@" > "$log" 2>&1; then
        pass=$((pass + 1))
        cases=$(grep -c '^\[       OK \]' "$log")
        if [ "$cases" -gt 0 ]; then echo "PASS $name ($cases cases)"; else echo "PASS $name"; fi
    else
        fail=$((fail + 1))
        echo "FAIL $name"
        cat "$log"
    fi
}
for t in "$BUILD"/tests/test_*; do
    case "$t" in *.log | *.d | *.o) continue ;; esac
    [ -x "$t" ] || continue
    run "$(basename "$t")" "$t.log" "$t"
done
for s in tests/scripts/*.sh; do
    [ -x "$s" ] || continue
    run "$(basename "$s")" "$BUILD/tests/$(basename "$s").log" "$s" "$BUILD"
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
