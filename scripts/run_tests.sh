#!/bin/sh
# Runs every test program in BUILD/tests (default build) and prints one summary line.
# Test programs find the shared data and the source tree through GENERIC_SOURCE_DIR.
BUILD=${1:-build}
GENERIC_SOURCE_DIR=$(pwd)
GENERIC_BUILD_DIR=$(cd "$BUILD" && pwd)
export GENERIC_SOURCE_DIR GENERIC_BUILD_DIR
pass=0
fail=0
failed=""
for t in "$BUILD"/tests/test_*; do
    [ -x "$t" ] || continue
    name=$(basename "$t")
    if "$t" > "$BUILD/tests/$name.log" 2>&1; then
        pass=$((pass + 1))
        echo "PASS $name ($(grep -c '^\[       OK \]' "$BUILD/tests/$name.log") cases)"
    else
        fail=$((fail + 1))
        failed="$failed $name"
        echo "FAIL $name"
        cat "$BUILD/tests/$name.log"
    fi
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
