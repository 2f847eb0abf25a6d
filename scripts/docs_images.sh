#!/bin/sh
# Regenerates the pictures README.md and docs/ show (docs/images/): texture swatches of every example in
# examples/textures/ (the last node or material each file defines) as one contact sheet, the demo
# render, and the laser reflection patterns of the fluorescent materials.
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
echo "docs images written to $out/ (swatches, row by row: $names)"
