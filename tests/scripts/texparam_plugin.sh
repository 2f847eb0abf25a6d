#!/bin/sh
# texparam_plugin.sh BUILD - a plug-in material gets textured parameters without code changes (kit/texparam.h):
# the example module oren_nayar (examples/plugins/oren_nayar.c, built on GMaterialOneColor, reading its colour with
# greader_color) takes `reflectance image { ... }` and `mix { ... }`, passes `gmat check` with them, and renders with
# an image reflectance exactly (idiff: every float equal) what the image node over it with a white reflectance
# renders, in both integrators; a mix beyond 1 is refused at the parameter.
set -u
BUILD=${1:-build}
GT="$BUILD/bin/gtrace"
GMAT="$BUILD/bin/gmat"
PLUGIN="$BUILD/plugins/oren_nayar.so"
. "$(dirname "$0")/prelude.sh"
need_program "$GT"
need_program "$GMAT"
[ -f "$PLUGIN" ] || { echo "FAIL: $PLUGIN is not built"; exit 1; }
need_command idiff openimageio-tools
LABEL=$(pwd)/examples/scenes/label.png

cat > "$TMP/m.mat" << EOF2
material img oren_nayar { reflectance image { file "$LABEL" } sigma 25 }
material mixed oren_nayar { sigma 10 reflectance mix { by perlin { frequency 3 } a rgb 0.1 0.2 0.3 b rgb 0.9 0.8 0.7 } }
EOF2
for m in img mixed; do
    "$GMAT" check "$TMP/m.mat" $m --plugin "$PLUGIN" > "$TMP/check.$m" 2>&1 ||
        fail "gmat check of the textured plug-in material $m: $(tail -3 "$TMP/check.$m")"
done

scene() {
    cat << EOF2
camera pinhole { from <0, 1.6, 5> at <0, 0.6, 0> fov 35 width 40 height 30 spp 2 depth 3 }
light background { color rgb 0.08 0.1 0.14 }
light point { position <-3, 5, 4> intensity rgb 40 40 40 }
object plane { point <0, 0, 0> normal <0, 1, 0> material lambert { reflectance rgb 0.5 0.5 0.5 } }
object box { min <-1.6, 0, -0.5> max <1.6, 1.6, -0.45> material $1 }
object sphere { center <0.6, 0.6, 0.5> radius 0.5 material $1 }
EOF2
}
scene "oren_nayar { reflectance image { file \"$LABEL\" wrap clamp } sigma 25 }" > "$TMP/a.scene"
scene "image { child oren_nayar { reflectance rgb 1 1 1 sigma 25 } file \"$LABEL\" wrap clamp }" > "$TMP/b.scene"
for integrator in whitted path; do
    for s in a b; do
        "$GT" "$TMP/$s.scene" -o "$TMP/$s.$integrator.exr" --integrator $integrator --plugin "$PLUGIN" -q \
            2> "$TMP/err" || fail "render $s ($integrator): $(cat "$TMP/err")"
    done
    idiff -q -fail 0 -warn 0 "$TMP/a.$integrator.exr" "$TMP/b.$integrator.exr" > /dev/null 2>&1 ||
        fail "$integrator: the textured plug-in material differs from the image node over it"
done

printf 'material x oren_nayar { reflectance mix { by checker { dims 2 } a rgb 0 0 0 b rgb 1.5 1.5 1.5 } }\n' \
    > "$TMP/bad.mat"
if "$GMAT" list "$TMP/bad.mat" --plugin "$PLUGIN" > /dev/null 2> "$TMP/err"; then
    fail "a textured reflectance above 1 was accepted"
else
    grep -q "bad.mat:1:25: oren_nayar: reflectance has the value 1.5" "$TMP/err" ||
        fail "a textured reflectance above 1: $(cat "$TMP/err")"
fi

if [ $fails -eq 0 ]; then
    echo "texparam_plugin: oren_nayar takes image and mix reflectances without code changes, passes gmat check," \
        "renders as the image node over it (both integrators); above 1 refused at the parameter"
fi
[ $fails -eq 0 ]
