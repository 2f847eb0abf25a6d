#!/bin/sh
# rgbspace_gamut.sh BUILD - a wide-gamut colour literal outside the reflectances (no smooth reflectance within
# [0, 1] has it) is warned about at the literal's file:line:col with the distance the uplift leaves, and loads: as
# a reflectance the spectral models take the nearest, rgb refuses its negative components. A colour the
# reflectances reach, or one with a component above 1 (a light), is not warned about.
BUILD=${1:-build}
GMAT="$BUILD/bin/gmat"
. "$(dirname "$0")/prelude.sh"
need_program "$GMAT"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

printf 'colormodel spectrum\ncolor inside rgbspace display-p3 0 0.8 0\nmaterial m lambert {\n    reflectance rgbspace rec2020 0 0.8 0 }\ncolor lamp rgbspace rec2020 0 4 0\n' \
    > "$TMP/wide.mat"
"$GMAT" list "$TMP/wide.mat" > "$TMP/out" 2> "$TMP/err" || fail "spectrum: the wide colour was refused: $(cat "$TMP/err")"
grep -q "^$TMP/wide.mat:4:17: warning: rgbspace rec2020 0 0.8 0 lies outside the reflectances (no smooth reflectance within \[0, 1\] has it: CIELAB distance 33.2 left)" "$TMP/err" ||
    fail "no warning at 4:17 with its distance: $(cat "$TMP/err")"
[ "$(grep -c warning "$TMP/err")" = 1 ] || fail "colours inside the gamut, or lights, were warned about: $(cat "$TMP/err")"
sed 's/colormodel spectrum/colormodel rgb/' "$TMP/wide.mat" > "$TMP/rgb.mat"
"$GMAT" list "$TMP/rgb.mat" > "$TMP/out" 2> "$TMP/err" && fail "rgb accepted a reflectance with negative components"
grep -q "rgb.mat:4:5: lambert: reflectance has the value -0.47" "$TMP/err" || fail "rgb: not the range rule: $(cat "$TMP/err")"
exit $fails
