#!/bin/sh
# texparam_conformance.sh BUILD - gmat check (reciprocity, energy, finite values, flags, sampling) passes for every
# material of examples/materials/textured.mat, whose parameters are textured (an image, a mix, generators with a
# range), at a point of the texture, in every built-in colour model; and a textured material whose texture leaves
# the energy rule is refused before it is checked.
set -u
BUILD=${1:-build}
GMAT="$BUILD/bin/gmat"
. "$(dirname "$0")/prelude.sh"
need_program "$GMAT"
OPTS=$(check_opts "$GMAT") # gmat check's options (prelude.sh)
FILE=examples/materials/textured.mat
"$GMAT" list "$FILE" > "$TMP/list" 2> "$TMP/err" || fail "gmat list $FILE: $(cat "$TMP/err")"
names=$(awk 'NF >= 3 && $1 == "material" { print $2 }' "$TMP/list")
[ "$(echo "$names" | wc -w)" -ge 6 ] || fail "$FILE lists fewer than 6 materials: $names"
checked=0
every=1
sanitized "$GMAT" && every=4 # under the sanitizers every fourth pair: each model, the same code paths
for model in rgb spectrum9 spectrum bispectral; do
    for m in $names; do
        checked=$((checked + 1))
        [ $(((checked - 1) % every)) -eq 0 ] || continue
        "$GMAT" check "$FILE" "$m" --colormodel $model $OPTS > "$TMP/log" 2>&1 ||
            fail "gmat check $m in $model: $(grep -v PASS "$TMP/log" | tail -5)"
        grep -q "^$m: PASS" "$TMP/log" || fail "gmat check $m in $model printed no verdict"
    done
done
printf 'material x lambert { reflectance image { file "%s/examples/scenes/label.png" } }\n' "$(pwd)" > "$TMP/ok.mat"
printf 'material x phong { diffuse image { file "%s/examples/scenes/label.png" } specular rgb 0.3 0.3 0.3 }\n' \
    "$(pwd)" > "$TMP/over.mat"
"$GMAT" check "$TMP/ok.mat" x > /dev/null 2>&1 || fail "a lambert with the label as its reflectance fails gmat check"
if "$GMAT" list "$TMP/over.mat" > /dev/null 2> "$TMP/err"; then
    fail "phong with the label (largest channel 0.95) as kd and ks 0.3 was accepted"
else
    grep -q "over.mat:1:.*phong: kd + ks + mirror is" "$TMP/err" || fail "kd + ks above 1: $(cat "$TMP/err")"
fi
if [ $fails -eq 0 ]; then
    echo "texparam_conformance: $checked checks of textured materials pass (4 models); an image kd above the energy rule refused"
fi
[ $fails -eq 0 ]
