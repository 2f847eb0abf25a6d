#!/bin/sh
# Regenerates the pictures README.md and docs/ show (docs/images/): texture swatches of every example in
# examples/textures/ (the last node or material each file defines) as one contact sheet, the demo
# render, the laser reflection patterns of the fluorescent materials, and sheets of the physically based materials,
# the measured metals.
# Usage: scripts/docs_images.sh [BUILD]   (needs oiiotool from openimageio-tools)
set -eu
BUILD=${1:-build}
out=docs/images
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
tiles=""
names=""
for f in examples/textures/*.txt; do
    name=$(grep -E '^(node|material) [A-Za-z_][A-Za-z0-9_.-]* ' "$f" | tail -n 1 | awk '{print $2}')
    base=$(basename "$f" .txt)
    "$BUILD/bin/gmat" swatch "$f" "$name" -o "$tmp/$base.png" --size 160
    tiles="$tiles $tmp/$base.png"
    names="${names:+$names, }$base"
done
# shellcheck disable=SC2086
n=$(echo $tiles | wc -w)
oiiotool $tiles --mosaic:pad=4 "5x$(((n + 4) / 5))" -o "$out/swatches.png"
"$BUILD/bin/gmat" swatch examples/textures/fig2.txt fig2 -o "$out/fig2_sphere.png" --size 256 --sphere
"$BUILD/bin/gtrace" examples/scenes/demo.scene -o "$out/demo.png" -q
for m in dayglo-varnish dayglo-phong; do
    "$BUILD/bin/gmat" laser examples/materials/fluorescent.mat "$m" --wavelength 532 --elevation 5,20,60 \
        --pattern "$out/laser_$m.png" > "$out/laser_$m.txt"
done
# Fig. 1 of Wilkie et al.: bispectral (left) against spectrum (right)
"$BUILD/bin/gtrace" examples/scenes/fluorescent_fig1.scene -o "$tmp/fig1_bi.png" -q --width 480 --height 300
"$BUILD/bin/gtrace" examples/scenes/fluorescent_fig1.scene -o "$tmp/fig1_sp.png" -q --width 480 --height 300 \
    --colormodel spectrum
oiiotool "$tmp/fig1_bi.png" "$tmp/fig1_sp.png" --mosaic:pad=4 2x1 -o "$out/fluorescent_fig1.png"
# Fig. 10 set-up of Wilkie et al. rendered by gtrace (bispectral): the lit spot seen from the target, 5, 20, 60 degrees
for e in 05 20 60; do
    "$BUILD/bin/gtrace" examples/scenes/fluorescent_fig10_$e.scene -o "$tmp/fig10_$e.png" -q --width 240 --height 240
done
oiiotool "$tmp/fig10_05.png" "$tmp/fig10_20.png" "$tmp/fig10_60.png" --mosaic:pad=4 3x1 -o "$out/fluorescent_fig10.png"
# The physically based materials, each a sphere over a checker floor rendered by the path tracer in spectrum
# (materials.png), and every measured metal at roughness 0.15 as a swatch (metals.png, docs/reference/metals.md),
# named in the tile.
font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf # fonts-dejavu-core
label() { # NAME: $tmp/raw.png labelled into $tmp/tile_NAME.png
    oiiotool "$tmp/raw.png" --text:x=4:y=13:size=11:color=1,1,1:font=$font "$1" -o "$tmp/tile_$1.png"
}
rendered() { # NAME MATERIAL-ENTRY: a labelled 112-pixel render of a sphere of the material
    cat > "$tmp/tile.scene" << EOS
colormodel spectrum { step 5 }
material m $2
material ground interpolate { a lambert { reflectance rgb 0.7 0.7 0.68 } b lambert { reflectance rgb 0.15 0.15 0.16 }
    t checker { dims 2 frequency 2 } }
object plane { point <0, -1, 0> normal <0, 1, 0> material ground }
object sphere { center <0, 0, 0> radius 1 material m }
camera pinhole { from <0, 1.2, 4.2> at <0, -0.1, 0> fov 34 width 112 height 112 spp 256 depth 12 }
light background { color rgb 0.55 0.6 0.7 }
light sphere { center <-4, 6, 4> radius 1.5 radiance rgb 6 6 6 }
EOS
    "$BUILD/bin/gtrace" "$tmp/tile.scene" --integrator path -o "$tmp/raw.png" -q
    label "$1"
}
swatch() { # NAME MATERIAL-ENTRY: a labelled 112-pixel swatch sphere of the material (gmat swatch)
    printf 'colormodel spectrum { step 5 }\nmaterial m %s\n' "$2" > "$tmp/tile.mat"
    "$BUILD/bin/gmat" swatch "$tmp/tile.mat" m -o "$tmp/raw.png" --size 112 --sphere --samples 3
    label "$1"
}
sheet() { # OUT COLUMNS NAME...: the tiles named, COLUMNS to a row
    o=$1 c=$2
    shift 2
    set -- $(for n in "$@"; do echo "$tmp/tile_$n.png"; done)
    oiiotool "$@" --mosaic:pad=2 "${c}x$((($# + c - 1) / c))" -o "$out/$o"
}
rendered gold "conductor { metal Au }"
rendered copper-0.3 "conductor { metal Cu roughness 0.3 }"
rendered silver-brushed "conductor { metal Ag roughness_u 0.05 roughness_v 0.3 }"
rendered BK7-0.1 "dielectric { glass BK7 roughness 0.1 }"
rendered plastic-0.2 "plastic { reflectance rgb 0.6 0.05 0.04 roughness 0.2 }"
rendered varnish-layer "layer { top dielectric { index 1.5 } bottom lambert { reflectance rgb 0.1 0.3 0.6 } }"
rendered film-320nm "thinfilm { thickness 320 index 1.4 base conductor { metal Al } }"
rendered thin-glass "thindielectric { index 1.5 }"
sheet materials.png 8 gold copper-0.3 silver-brushed BK7-0.1 plastic-0.2 varnish-layer film-320nm thin-glass
metals=$("$BUILD/bin/gmat" metals | awk '{ print $1 }')
for m in $metals; do swatch "$m" "conductor { metal $m roughness 0.15 }"; done
# shellcheck disable=SC2086
sheet metals.png 10 $metals
echo "docs images written to $out/ (swatches, row by row: $names)"
