#!/bin/sh
# coated_conformance.sh BUILD - gmat check over the coated materials beyond their default instances (which
# conformance.sh checks): plastic at roughness 0.01, 0.05, 0.3, 0.8 and 1.0 (GGX, and Beckmann at 0.3) in every
# colour model; layer over a glossy phong, with a scattering medium, and over a re-radiating lambert (bispectral);
# a thin film over a rough plastic (the film's factors on a non-delta base) in rgb and bispectral. Every property
# must pass. About 40 s of CPU.
BUILD=$(cd "${1:-build}" 2> /dev/null && pwd) || { echo "FAIL: no build directory ${1:-build}"; exit 1; }
GMAT="$BUILD/bin/gmat"
. "$(dirname "$0")/prelude.sh"
need_program "$GMAT"
OPTS=$(check_opts "$GMAT") # gmat check's options (prelude.sh)
cat > "$TMP/coated.mat" << 'EOM'
material p001 plastic { reflectance rgb 0.7 0.4 0.2 roughness 0.01 }
material p005 plastic { reflectance rgb 0.7 0.4 0.2 roughness 0.05 }
material p03 plastic { reflectance rgb 0.7 0.4 0.2 roughness 0.3 }
material p03b plastic { reflectance rgb 0.7 0.4 0.2 roughness 0.3 distribution beckmann index 1.8 }
material p08 plastic { reflectance rgb 0.7 0.4 0.2 roughness 0.8 }
material p1 plastic { reflectance rgb 0.7 0.4 0.2 roughness 1 }
material glossy layer { top dielectric { index 1.6 } bottom phong { diffuse rgb 0.3 0.2 0.1 specular rgb 0.3 0.3 0.3 } }
material foggy layer { top dielectric { index 1.3 } bottom lambert { reflectance rgb 0.2 0.5 0.8 } thickness 1.5 }
material filmed thinfilm { thickness 320 index 1.4 base plastic { reflectance rgb 0.2 0.3 0.6 roughness 0.2 } }
EOM
cat > "$TMP/glow.mat" << 'EOM'
material glow layer { top dielectric { index 1.5 } bottom lambert { reflectance reradiation { } } }
EOM
checked=0
# must_pass FILE MATERIAL MODEL
must_pass() {
    checked=$((checked + 1))
    "$GMAT" check "$1" "$2" --colormodel "$3" $OPTS > "$TMP/log" 2>&1 || fail "$2 in $3 does not pass gmat check:
$(grep -v ' PASS ' "$TMP/log")"
}
turn=0
for model in rgb spectrum9 spectrum bispectral; do
    for m in p001 p005 p03 p03b p08 p1 glossy foggy; do
        turn=$((turn + 1))
        # under the sanitizers every third pair: each material and each model still, at a third of the cost
        sanitized "$GMAT" && [ $((turn % 3)) -ne 0 ] && continue
        must_pass "$TMP/coated.mat" $m $model
    done
done
must_pass "$TMP/coated.mat" filmed rgb
must_pass "$TMP/coated.mat" filmed bispectral
must_pass "$TMP/glow.mat" glow bispectral
[ $fails -eq 0 ] && echo "coated conformance: $checked checks pass (plastic, layer, thinfilm)"
exit $fails
