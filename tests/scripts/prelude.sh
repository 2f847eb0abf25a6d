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
# serial_only: a script that asserts time bounds says so first; such a bound holds only on a machine no other test
# loads, so the script is listed in SERIAL of scripts/run_tests.sh (run alone, after the parallel batch), and in
# the batch (GENERIC_TEST_BATCH set) it fails at once. now: the time in seconds, with fractions.
serial_only() {
    [ -z "${GENERIC_TEST_BATCH:-}" ] || {
        echo "FAIL: time bounds in the parallel batch: list $(basename "$0") in SERIAL of scripts/run_tests.sh"
        exit 1
    }
}
now() { date +%s.%N; }
# sanitized PROGRAM: true when PROGRAM is built with the sanitizers (make SANITIZE=1), whose code runs several times
# slower. A script with many repetitions of one code path (the same check on more parameters) runs a subset there:
# the sanitizers look for memory errors and undefined behaviour in the paths, which the subset runs too.
sanitized() { ldd "$1" 2> /dev/null | grep -q -E "libasan|libubsan"; }
# check_opts GMAT: the options the conformance scripts give `gmat check`: under the sanitizers the albedo grid at its
# smallest, --samples 8 (the grid is most of a check's cost; a lobe the grid cannot resolve is judged by sample()).
check_opts() { if sanitized "$1"; then echo "--samples 8"; fi; }
# bounded_run WHAT WANT MAX_SECONDS COMMAND...: runs COMMAND (stdout in TMP/out, stderr in TMP/err), which must exit
# 0 (WANT 0) or 1..127 (WANT 1), without a sanitizer report or a failed assertion, within MAX_SECONDS (a time
# bound: call serial_only first).
bounded_run() {
    what=$1 want=$2 max=$3
    shift 3
    t0=$(now)
    "$@" > "$TMP/out" 2> "$TMP/err"
    st=$?
    took=$(echo "$(now) - $t0" | bc)
    echo "$what: status $st, $took s"
    if [ $st -ge 128 ]; then
        fail "$what: crashed (status $st): $(head -c 2000 "$TMP/err")"
    elif [ "$want" = 0 ] && [ $st -ne 0 ]; then
        fail "$what: failed (status $st): $(head -c 2000 "$TMP/err")"
    elif [ "$want" != 0 ] && [ $st -eq 0 ]; then
        fail "$what: succeeded"
    fi
    if grep -q -E "Sanitizer|runtime error:|Assertion" "$TMP/err"; then
        fail "$what: sanitizer report or failed assertion: $(head -c 2000 "$TMP/err")"
    fi
    if [ "$(echo "$took > $max" | bc)" = 1 ]; then
        fail "$what: took $took s (more than $max s)"
    fi
}
# listed NAME: appends "NAME MODEL" to TMP/nodes, MODEL rgb, spectrum and bispectral in turn (the count in turn).
turn=0
listed() {
    case $((turn % 3)) in 0) echo "$1 rgb" ;; 1) echo "$1 spectrum" ;; *) echo "$1 bispectral" ;; esac >> "$TMP/nodes"
    turn=$((turn + 1))
}
# check_nodes GMAT FILE LIST: `gmat check` of each "name model" line of LIST in FILE, every property must pass (a
# failure fails with gmat's report); checked is then the number of lines listed. Under the sanitizers (GMAT built
# with them) every fourth line runs, which still takes each colour model in turn.
check_nodes() {
    checked=0
    every=1
    sanitized "$1" && every=4
    while read -r name model; do
        checked=$((checked + 1))
        [ $(((checked - 1) % every)) -eq 0 ] || continue
        "$1" check "$2" "$name" --colormodel "$model" $(check_opts "$1") > "$TMP/log" 2>&1 || fail "$name in $model:
$(cat "$TMP/log")"
    done < "$3"
    [ "$every" -eq 1 ] || echo "under the sanitizers: every $every of $checked checked"
}
