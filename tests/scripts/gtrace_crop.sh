#!/bin/sh
# gtrace_crop.sh BUILD - `gtrace --crop X0,Y0,X1,Y1`: the output has the region's size, an EXR records it as its
# data window inside the full image's display window, and its pixels are bit-identical to the same pixels of the
# full render (whatever the thread count and however the region cuts the 16x16 tiles), for the Whitted and the path
# integrators; bad regions exit 2.
BUILD=${1:-build}
GT="$BUILD/bin/gtrace"
. "$(dirname "$0")/prelude.sh"
need_program "$GT"
need_command oiiotool openimageio-tools
SCENE=examples/scenes/demo.scene
"$GT" "$SCENE" -q -o "$TMP/full.exr" --width 120 --spp 2 --threads 2 || fail "the full render failed"
# full size of the image (the camera's aspect gives the height)
size=$(oiiotool --info "$TMP/full.exr" | sed -n 's/.*: *\([0-9]*\) x *\([0-9]*\),.*/\1 \2/p')
W=${size% *} H=${size#* }
[ "$W" = 120 ] || fail "the full render is not 120 pixels wide: $size"

check_crop() { # X0 Y0 X1 Y1 THREADS
    x0=$1 y0=$2 x1=$3 y1=$4
    w=$((x1 - x0)) h=$((y1 - y0))
    out="$TMP/crop_$1_$2_$3_$4.exr"
    "$GT" "$SCENE" -q -o "$out" --width=120 --spp=2 --threads "$5" --crop "$x0,$y0,$x1,$y1" ||
        { fail "--crop $x0,$y0,$x1,$y1 failed"; return; }
    info=$(oiiotool --info -v "$out")
    echo "$info" | grep -q ": *$w x *$h," || fail "--crop $x0,$y0,$x1,$y1: not $w x $h: $(echo "$info" | head -2)"
    if [ "$w" != "$W" ] || [ "$h" != "$H" ]; then # the whole image is written without a separate window
        echo "$info" | grep -q "pixel data origin: x=$x0, y=$y0" || fail "--crop $x0,$y0,$x1,$y1: no data window at $x0,$y0"
        echo "$info" | grep -q "full/display size: $W x $H" || fail "--crop $x0,$y0,$x1,$y1: display window is not $W x $H"
    fi
    # the same region of both, moved to the origin, compared exactly (--fail 0: any difference fails)
    d=$(oiiotool "$TMP/full.exr" --cut "${w}x${h}+${x0}+${y0}" "$out" --cut "${w}x${h}+${x0}+${y0}" --fail 0 --diff 2>&1)
    echo "$d" | grep -q '^PASS' || fail "--crop $x0,$y0,$x1,$y1: pixels differ from the full render: $d"
    # and a region that is not the crop differs (the comparison can fail)
    d=$(oiiotool "$TMP/full.exr" --cut "${w}x${h}+$((x0 + 1))+${y0}" "$out" --cut "${w}x${h}+${x0}+${y0}" --fail 0 --diff 2>&1)
    echo "$d" | grep -q '^PASS' && fail "--crop $x0,$y0,$x1,$y1: a shifted region compares equal (the check is blind)"
}
check_crop 10 20 50 41 1
check_crop 0 0 120 "$H" 2
check_crop 37 5 119 63 2
check_crop 100 30 101 31 2

# the path integrator seeds each pixel from its index in the full image (its Sobol points and its generator), so its
# crops agree with the full render too, with either sampler and thread count
for sampler in sobol independent; do
    "$GT" "$SCENE" -q -o "$TMP/path_full.exr" --width 120 --spp 2 --integrator path --sampler $sampler --threads 2 ||
        fail "the full path render ($sampler) failed"
    "$GT" "$SCENE" -q -o "$TMP/path_crop.exr" --width 120 --spp 2 --integrator path --sampler $sampler --threads 1 \
        --crop 37,5,119,63 || fail "the path crop ($sampler) failed"
    d=$(oiiotool "$TMP/path_full.exr" --cut 82x58+37+5 "$TMP/path_crop.exr" --cut 82x58+37+5 --fail 0 --diff 2>&1)
    echo "$d" | grep -q '^PASS' ||
        fail "--integrator path --sampler $sampler --crop 37,5,119,63: pixels differ from the full render: $d"
done

# two crops rendered apart merge into the full image (disjoint data windows: added, black outside each)
"$GT" "$SCENE" -q -o "$TMP/left.exr" --width 120 --spp 2 --crop "0,0,61,$H" &&
    "$GT" "$SCENE" -q -o "$TMP/right.exr" --width 120 --spp 2 --crop "61,0,120,$H" ||
    fail "rendering two halves failed"
d=$(oiiotool "$TMP/left.exr" "$TMP/right.exr" --add "$TMP/full.exr" --fail 0 --diff 2>&1)
echo "$d" | grep -q '^PASS' || fail "two crops merged with oiiotool --add differ from the full render: $d"

# PNG: the region's size (no data window)
"$GT" "$SCENE" -q -o "$TMP/crop.png" --width 120 --spp 1 --crop 8,8,40,24 || fail "a PNG crop failed"
oiiotool --info "$TMP/crop.png" | grep -q ": *32 x *16," || fail "the PNG crop is not 32 x 16"

for bad in 5,5,5,9 10,10,2,20 0,0,121,10 1,2,3 a,b,c,d 0,0,10,10,3 -1,0,4,4; do
    "$GT" "$SCENE" -q -o "$TMP/bad.png" --width 120 --crop "$bad" > "$TMP/err" 2>&1
    st=$?
    [ $st -eq 2 ] || fail "--crop $bad: exit status $st, expected 2"
    grep -q -- "--crop" "$TMP/err" || fail "--crop $bad: the message does not name --crop: $(cat "$TMP/err")"
    [ -e "$TMP/bad.png" ] && fail "--crop $bad: an image was written"
done
[ $fails -eq 0 ] && echo "gtrace_crop: 4 Whitted crops and a path crop per sampler bit-identical to the full render, data windows recorded, two halves merge, 7 bad regions refused"
exit $fails
