#!/bin/sh
# python.sh [BUILD] - the Python package's tests (tests/python/, pytest) against BUILD/python, with Debian's python3
# (PYTHON; the package needs python3-cffi and python3-numpy, the tests python3-pytest: scripts/deps.sh).
# pytest's exit status is read strictly: 0 passes; 5 (no test collected) fails, as does every other status. A
# sanitizer build is skipped, saying so: its libraries need the AddressSanitizer run-time loaded before any other
# library, which an interpreter that opens them with dlopen cannot arrange.
BUILD=${1:-build}
PYTHON=${PYTHON:-/usr/bin/python3}
. "$(dirname "$0")/prelude.sh"
if nm -A "$BUILD/lib/libgeneric.a" 2> /dev/null | grep -q __asan_; then
    echo "python: SKIPPED in the sanitizer build $BUILD (the AddressSanitizer run-time cannot be loaded into $PYTHON)"
    exit 0
fi
need_program "$PYTHON"
[ -f "$BUILD/python/generic/__init__.py" ] || { echo "FAIL: $BUILD/python is not built (make python)"; exit 1; }
"$PYTHON" -c "import cffi, numpy, pytest" ||
    { echo "FAIL: $PYTHON lacks cffi, numpy or pytest (scripts/deps.sh)"; exit 1; }
GENERIC_BUILD_DIR=$(cd "$BUILD" && pwd)
GENERIC_SOURCE_DIR=$(pwd)
export GENERIC_BUILD_DIR GENERIC_SOURCE_DIR
PYTHONPATH="$GENERIC_BUILD_DIR/python${PYTHONPATH:+:$PYTHONPATH}" PYTHONDONTWRITEBYTECODE=1 \
    "$PYTHON" -m pytest -q -p no:cacheprovider --basetemp="$TMP/pytest" tests/python
status=$?
case $status in
0) ;;
5) fail "pytest collected no tests (status 5)" ;;
*) fail "pytest failed (status $status)" ;;
esac
exit $fails
