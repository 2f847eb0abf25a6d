#!/bin/sh
# bump_conformance.sh BUILD - gmat check over generated bump nodes, alone and with a transform above or below them:
# children lambert, phong without and with a mirror term and an interpolate of lambert and phong, under a bevel
# (a gradient height: the normal tilted 63 degrees along x everywhere, or 51 degrees between x and y), fbm in
# object space and Perlin noise in (u, v); each bump alone, under a transform with both a (u, v) part (rotate,
# uneven scale, translate) and an xyz part (rotate, scale with a mirroring axis, translate), and over that
# transform; the models rgb, spectrum and bispectral in turn. Every property must pass. A shading normal tilted far
# from the geometric one puts the edge of the cosine lobe slantwise across gmat's (cos theta, phi) bins, where it
# may clip a corner that none of a bin's midpoints sees: the chi2 test then expected nothing there and failed at
# the first draw (worst inf: 10 of these 48 did, the bevels alone too), where sampling.c now integrates that bin
# again on a finer grid. About 8 s.
BUILD=$(cd "${1:-build}" 2> /dev/null && pwd) || { echo "FAIL: no build directory ${1:-build}"; exit 1; }
GMAT="$BUILD/bin/gmat"
. "$(dirname "$0")/prelude.sh"
need_program "$GMAT"
cat > "$TMP/bumps.mat" << 'EOM'
material ll lambert { reflectance rgb 0.6 0.3 0.2 }
material ph phong { diffuse rgb 0.4 0.3 0.2 specular rgb 0.3 0.3 0.3 exponent 60 }
material pm phong { diffuse rgb 0.1 0.2 0.5 specular rgb 0.1 0.1 0.1 exponent 400 mirror rgb 0.04 0.04 0.04 }
node mix interpolate { a ll b ph t fbm { frequency 3 octaves 3 } }
generator bevel gradient { space object slope 2 0 0 }
generator slant gradient { space object slope 0.7 1 0 }
generator hills fbm { space object frequency 4 octaves 4 }
generator pits perlin { space uv frequency 6 }
EOM
MOVE="uv { rotate 30 scale 2 0.5 translate 0.1 0.2 } xyz { rotate 1 1 0 40 scale 1 -2 0.5 translate 0.3 0 1 }"
: > "$TMP/nodes"
for child in ll ph pm mix; do
    for h in "bevel 1" "slant 1" "hills 0.5" "pits 0.1"; do
        height=${h% *}
        strength=${h#* }
        bump="bump { child $child height $height strength $strength }"
        for form in plain over under; do
            name="${form}_${child}_$height"
            case $form in
            plain) echo "node $name $bump" ;;
            over) echo "node $name transform { child $bump $MOVE }" ;;
            under)
                moved="transform { child $child $MOVE }"
                echo "node $name bump { child $moved height $height strength $strength }"
                ;;
            esac >> "$TMP/bumps.mat"
            listed "$name"
        done
    done
done
check_nodes "$GMAT" "$TMP/bumps.mat" "$TMP/nodes"
[ "$checked" -eq 48 ] || fail "checked $checked bump nodes, expected 48 (4 children x 4 heights x 3 forms)"
[ $fails -eq 0 ] && echo "bump conformance: $checked bump nodes pass"
exit $fails
