#!/bin/sh
# untrusted.sh BUILD - the tools on inputs that must not succeed wrongly or act without consent:
#   - gcolor: an unknown model is a usage error, a conversion that fails or overflows is reported for its sample
#     (never printed with another sample's values) and makes the exit status 1; magnitudes 1e0..1e300 either
#     convert to finite values or fail so;
SRC=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=$(cd "${1:-build}" 2> /dev/null && pwd) || { echo "FAIL: no build directory ${1:-build}"; exit 1; }
GCOLOR="$BUILD/bin/gcolor"
GMAT="$BUILD/bin/gmat"
GTRACE="$BUILD/bin/gtrace"
PLUGINS="$BUILD/plugins"
for t in "$GCOLOR" "$GMAT" "$GTRACE"; do
    [ -x "$t" ] || { echo "FAIL: $t is not built"; exit 1; }
done
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fails=0
checked=0
fail() {
    echo "FAIL: $*"
    fails=$((fails + 1))
}
# expect STATUS WHAT COMMAND...: runs COMMAND (stdout in $TMP/out, stderr in $TMP/err), checks its exit status
expect() {
    want=$1
    what=$2
    shift 2
    "$@" > "$TMP/out" 2> "$TMP/err"
    st=$?
    checked=$((checked + 1))
    [ "$st" -eq "$want" ] || fail "$what: exit status $st, expected $want: $(head -c 2000 "$TMP/err")"
    if grep -q -E "Sanitizer|runtime error:" "$TMP/err"; then
        fail "$what: sanitizer report: $(head -c 2000 "$TMP/err")"
    fi
}
has() { # WHAT FILE TEXT: FILE contains TEXT
    grep -q -F -- "$3" "$2" || fail "$1: expected '$3' in: $(head -c 2000 "$2")"
}

# ---- gcolor ----
expect 2 "gcolor --models with an unknown model" "$GCOLOR" --models rgb,nosuch
has "gcolor --models rgb,nosuch" "$TMP/err" "gcolor: --models: unknown colour model 'nosuch' (registered: "
[ -s "$TMP/out" ] && fail "gcolor --models rgb,nosuch printed a report: $(cat "$TMP/out")"
expect 2 "gcolor --rgb nan" "$GCOLOR" --rgb nan,0,0
expect 1 "gcolor --rgb 1e300" "$GCOLOR" --models rgb,spectrum --rgb 1e300,0,0 --rgb 0.5,0.5,0.5
has "gcolor --rgb 1e300" "$TMP/out" "rgb 1e300,0,0      conversion to sRGB and XYZ failed"
has "gcolor --rgb 1e300" "$TMP/out" "rgb 0.5,0.5,0.5    brightness 0.5000  -> sRGB 0.5000 0.5000 0.5000"
has "gcolor --rgb 1e300" "$TMP/err" "gcolor: spectrum: 'rgb 1e300,0,0': the conversion to sRGB and XYZ failed"
e=0
while [ $e -le 300 ]; do # every magnitude: finite values and status 0, or the sample failed and status 1
    "$GCOLOR" --rgb "1e$e,1e$e,0" > "$TMP/out" 2> "$TMP/err"
    st=$?
    checked=$((checked + 1))
    grep -i -q -E "inf|nan" "$TMP/out" && fail "gcolor --rgb 1e$e printed a value that is not finite: $(cat "$TMP/out")"
    if [ $st -eq 0 ]; then
        grep -q "failed" "$TMP/out" && fail "gcolor --rgb 1e$e: a failed sample with status 0"
    elif [ $st -eq 1 ]; then
        grep -q "conversion .* failed" "$TMP/out" || fail "gcolor --rgb 1e$e: status 1 without a failed sample"
    else
        fail "gcolor --rgb 1e$e: exit status $st: $(cat "$TMP/err")"
    fi
    e=$((e + 20))
done

echo "$checked runs checked, $fails failures"
[ $fails -eq 0 ]
