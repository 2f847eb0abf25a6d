#!/bin/sh
# reuse_limits.sh BUILD - `like`, `define` and ramps on large generated inputs, through gmat list: 100,000 entries
# each derived from one base (loads, each listed as derived, a bounded time), a chain of 10,000 `like`s (refused
# at depth 33 with the exact message, at once), a base of 20,000 parameters copied 1,000 times (refused by the
# re-read budget, at once), 100,000 constants each defined from the one before, `like` of an entry nested 60
# deep, and a ramp of 100,000 keys (refused at its 1025th key). Every run ends with a status below 128, no
# sanitizer report, and within a generous time (what it catches is quadratic work).
BUILD=$(cd "${1:-build}" 2> /dev/null && pwd) || { echo "FAIL: no build directory ${1:-build}"; exit 1; }
GMAT="$BUILD/bin/gmat"
. "$(dirname "$0")/prelude.sh"
serial_only

# run WHAT WANT_STATUS MAX_SECONDS FILE [EXPECTED STDERR TEXT]: gmat list FILE through bounded_run (prelude.sh)
run() {
    bounded_run "$1" "$2" "$3" "$GMAT" list "$4"
    if [ -n "$5" ] && ! grep -qF "$5" "$TMP/err"; then
        fail "$1: expected '$5', got: $(head -c 2000 "$TMP/err")"
    fi
}

awk 'BEGIN { print "material base phong { diffuse rgb 0.3 0.3 0.3 specular rgb 0.1 0.1 0.1 exponent 20 }"
    for (i = 0; i < 100000; i++) printf "material m%d like base { diffuse rgb %g 0.2 0.2 }\n", i, (i % 50) / 100 }' \
    > "$TMP/siblings.mat"
run "100,000 entries like one base" 0 30 "$TMP/siblings.mat"
n=$(grep -c " like base " "$TMP/out")
[ "$n" = 100000 ] || fail "100,000 entries like one base: $n listed as derived"

awk 'BEGIN { print "material m0 lambert { reflectance rgb 0.5 0.5 0.5 }"
    for (i = 1; i < 10000; i++) printf "material m%d like m%d { reflectance rgb 0.4 0.4 0.4 }\n", i, i - 1 }' \
    > "$TMP/chain.mat"
run "a chain of 10,000 likes" 1 10 "$TMP/chain.mat" \
    "chain.mat:34:19: 'like m32': a chain of entries derived with 'like' may be at most 32 deep"

awk 'BEGIN { printf "color big spectrum {"; for (i = 0; i < 20000; i++) printf " %d 0.5", 380 + i; print " }"
    for (i = 0; i < 1000; i++) printf "color c%d like big\n", i }' > "$TMP/budget.mat"
run "a big base copied 1,000 times" 1 10 "$TMP/budget.mat" "entries derived with 'like' re-read more than"

awk 'BEGIN { print "define k0 0.5"; for (i = 1; i < 100000; i++) printf "define k%d k%d\n", i, i - 1
    print "material m lambert { reflectance rgb k99999 k5 k0 }" }' > "$TMP/constants.mat"
run "100,000 constants" 0 30 "$TMP/constants.mat"

awk 'BEGIN { s = "lambert"; for (i = 0; i < 60; i++) s = "scale { child " s " factor constant }"
    print "material deep " s; print "material deep2 like deep { factor constant { value 0.5 } }" }' \
    > "$TMP/deep.mat"
run "like of an entry nested 60 deep" 0 10 "$TMP/deep.mat"

awk 'BEGIN { printf "node n spline { t constant ramp {"; for (i = 0; i < 100000; i++) printf " %.6f lambert", i / 100000
    print " } }" }' > "$TMP/ramp.mat"
run "a ramp of 100,000 keys" 1 10 "$TMP/ramp.mat" "spline: a ramp has at most 1024 keys"

[ $fails -eq 0 ] && echo "reuse_limits: all passed"
exit $((fails > 0))
