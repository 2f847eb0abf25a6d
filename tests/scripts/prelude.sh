# prelude.sh - sourced (not run) by the script tests after they set BUILD: a scratch directory TMP removed on exit,
# and fail MESSAGE, which prints the failure and counts it in fails (a script ends with `exit $fails`).
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fails=0
fail() {
    echo "FAIL: $*"
    fails=$((fails + 1))
}
