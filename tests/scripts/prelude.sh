# prelude.sh - sourced (not run) by the script tests after they set BUILD: a scratch directory TMP removed on exit,
# and fail MESSAGE, which prints the failure and counts it in fails (a script ends with `exit $fails`).
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fails=0
fail() {
    echo "FAIL: $*"
    fails=$((fails + 1))
}
# need_program PATH / need_command NAME PACKAGE: end the test (exit 1) unless the program is built, or the command
# is on PATH (PACKAGE: where scripts/deps.sh gets it).
need_program() { [ -x "$1" ] || { echo "FAIL: $1 is not built"; exit 1; }; }
need_command() { command -v "$1" > /dev/null || { echo "FAIL: $1 ($2, scripts/deps.sh) is missing"; exit 1; }; }
