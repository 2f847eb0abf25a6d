#!/bin/sh
# check_gaps.sh BUILD - gmat check on legitimate materials it once failed, and on wrong ones it must still fail.
# snell: a strongly dispersive Cauchy glass (A 1, B 0.1: n from 1.20 to 1.63 over the visible) refracts with the
# scalar relative index of the colour it is handed, the brightness of n(from) / n(to); the check took 1 / the
# brightness of n from outside, which differs for a dispersive index (Jensen), and measured a tangential error of
# 8e-4 in a correct material. albedo: a fluorescent varnish under a bump of strength 100 in bispectral; the check
# asked whether light moves between samples at three fixed pairs of directions, all behind the steep facet at one
# place, where reflection is black, so it measured that place with white light sample by sample and counted the
# re-radiated light of every other sample as reflected in one (1.65). albedo again: a select of a fluorescent varnish
# and a white mirror, the varnish at the first place; the check measured the mirror's places after it with the
# one-sample light the varnish's place left set, against white light (1.56 in bispectral). Then misbent_glass
# (refracts about the geometric normal) must still fail snell under a bump, and gain_lambert (1.5 times the light)
# albedo where it is selected after the varnish (tests/plugins/nonconforming.c). chi2: a GGX reflector drawing half
# vectors from D(h) cos(theta_h) at alpha 0.2 (tests/plugins/halfvector.c), correct, whose pdf's integrable 1/(o.h)
# peak at theta_out 80 defeated the midpoint rule over the bins (chi2 4.42 against 3.78); the bins are integrated
# adaptively, and misdrawn_lambert must still fail chi2. About 4 s.
BUILD=$(cd "${1:-build}" 2> /dev/null && pwd) || { echo "FAIL: no build directory ${1:-build}"; exit 1; }
GMAT="$BUILD/bin/gmat"
PLUGINS="$BUILD/plugins"
. "$(dirname "$0")/prelude.sh"
need_program "$GMAT"
cat > "$TMP/gaps.mat" << 'EOM'
material flint dielectric { index cauchy 1 0.1 }
material dense dielectric { index cauchy 1.5 0.1 -0.000132 }
node steep_varnish bump {
    child fluorescent-varnish { matrix reradiation { absorb_peak 470 } ior 1.3 slope 13 }
    height perlin { space object frequency 5.6 seed 37 }
    strength 100
}
node varnish_or_mirror select {
    index cpg { shape square 0.5 0.5 0.4 }
    children { fluorescent-varnish { matrix reradiation { absorb_peak 470 } ior 1.06 slope 17 } mirror { } }
}
EOM
# must_pass NAME MODEL PROPERTY
must_pass() {
    "$GMAT" check "$TMP/gaps.mat" "$1" --colormodel "$2" > "$TMP/log" 2>&1
    awk -v p="$3" '$1 == p && $2 == "worst" && / PASS / { ok = 1 } END { exit !ok }' "$TMP/log" ||
        fail "$1 in $2: $3 does not pass:
$(cat "$TMP/log")"
}
for model in rgb spectrum spectrum9 bispectral; do
    must_pass flint $model snell
    must_pass dense $model snell
done
must_pass steep_varnish bispectral albedo
must_pass varnish_or_mirror bispectral albedo
# still failing where the material is wrong
cat > "$TMP/wrong.mat" << 'EOM'
node bent bump { child misbent_glass height gradient { space object slope 2 0 0 } strength 0.3 }
EOM
cat > "$TMP/gain.mat" << 'EOM'
node varnish_or_gain select {
    index cpg { shape square 0.5 0.5 0.4 }
    children { fluorescent-varnish { matrix reradiation { absorb_peak 470 } ior 1.06 slope 17 } gain_lambert }
}
EOM
"$GMAT" check "$TMP/wrong.mat" bent --plugin "$PLUGINS/misbent.so" > "$TMP/log" 2>&1
awk '$1 == "snell" && / FAIL / { ok = 1 } END { exit !ok }' "$TMP/log" ||
    fail "misbent_glass under a bump no longer fails snell:
$(cat "$TMP/log")"
"$GMAT" check "$TMP/gain.mat" varnish_or_gain --colormodel bispectral --plugin "$PLUGINS/gain.so" > "$TMP/log" 2>&1
awk '$1 == "albedo" && / FAIL / { ok = 1 } END { exit !ok }' "$TMP/log" ||
    fail "gain_lambert selected after a fluorescent varnish no longer fails albedo:
$(cat "$TMP/log")"
echo "material h halfvector_ggx" > "$TMP/halfvector.mat"
for model in rgb spectrum spectrum9 bispectral; do
    "$GMAT" check "$TMP/halfvector.mat" h --colormodel $model --plugin "$PLUGINS/halfvector.so" > "$TMP/log" 2>&1
    awk '$1 == "chi2" && / PASS / { ok = 1 } END { exit !ok }' "$TMP/log" ||
        fail "halfvector_ggx in $model: chi2 does not pass:
$(cat "$TMP/log")"
done
echo "material m misdrawn_lambert" > "$TMP/misdrawn.mat"
"$GMAT" check "$TMP/misdrawn.mat" m --plugin "$PLUGINS/misdrawn.so" > "$TMP/log" 2>&1
awk '$1 == "chi2" && / FAIL / { ok = 1 } END { exit !ok }' "$TMP/log" ||
    fail "misdrawn_lambert no longer fails chi2:
$(cat "$TMP/log")"
[ $fails -eq 0 ] && echo "check gaps: half-vector sampling passes chi2, dispersive glasses pass snell," \
    "fluorescent trees pass albedo"
exit $fails
