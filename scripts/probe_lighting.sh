#!/bin/sh
# Renders examples/scenes/probe.scene lit by a light probe with every technique and with the Monte Carlo
# reference, and prints the RMSE of each against the reference, over the whole image and inside the cast
# shadows, as a markdown table (docs/probe-lighting.md shows one).
#   scripts/probe_lighting.sh [BUILD] [PROBE] [COUNTS] [SAMPLES] [IMAGES]
#     BUILD    build directory with bin/gtrace and bin/gprobe (default build)
#     PROBE    the probe (default ../shared/data/probes/grace.hdr, else /work/shared/data/probes/grace.hdr)
#     COUNTS   light counts, space separated (default "16 64")
#     SAMPLES  reference samples per pixel (default 16384; one camera ray per pixel through its centre, so
#              every render shoots the same camera rays and the differences are the lighting's alone)
#     IMAGES   directory for PNGs of the first count and the reference (default: none)
set -e
BUILD=${1:-build}
PROBE=${2:-}
COUNTS=${3:-16 64}
SAMPLES=${4:-16384}
IMAGES=${5:-}
if [ -z "$PROBE" ]; then
    PROBE=../shared/data/probes/grace.hdr
    [ -f "$PROBE" ] || PROBE=/work/shared/data/probes/grace.hdr
fi
[ -f "$PROBE" ] || { echo "probe_lighting: no probe $PROBE" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
G="$BUILD/bin/gtrace examples/scenes/probe.scene --spp 1 --width 320 --height 240 --probe $PROBE"

# png EXR PNG OPTIONS...: the display image of a render (oiiotool's sRGB encoding is gtrace's), else render it
png() {
    exr=$1 out=$2
    shift 2
    if command -v oiiotool > /dev/null; then
        oiiotool "$exr" --colorconvert linear sRGB -d uint8 -o "$out"
    else
        $G "$@" -q -o "$out"
    fi
}

# render NAME OPTIONS...: renders $tmp/NAME.exr, sets $prep and $secs from gtrace's summary lines
render() {
    name=$1
    shift
    $G "$@" -o "$tmp/$name.exr" > "$tmp/$name.log"
    prep=$(sed -n 's/.*prepared in \([0-9.]*\) s.*/\1/p' "$tmp/$name.log")
    secs=$(sed -n 's/.*threads: \([0-9.]*\) s,.*/\1/p' "$tmp/$name.log")
    ierr=$(sed -n 's/.*mean irradiance error \([0-9.]*\)%.*/\1/p' "$tmp/$name.log")
}

render reference --probe-technique reference --probe-samples "$SAMPLES"
ref_secs=$secs
render open --probe-technique reference --probe-samples "$SAMPLES" --probe-shadows off
render quarter --probe-technique reference --probe-samples $((SAMPLES / 4))
C="$BUILD/bin/gprobe compare"
$C "$tmp/reference.exr" "$tmp/reference.exr" --unshadowed "$tmp/open.exr" --write-mask "$tmp/mask.png" > "$tmp/mask.txt"
shadow_px=$(sed -n 's/^shadow pixels \([0-9]*\).*/\1/p' "$tmp/mask.txt")
# the reference's own noise: a quarter of the samples has twice its noise, so RMSE(quarter, reference)^2 = 5 s^2
noise=$($C "$tmp/quarter.exr" "$tmp/reference.exr" --unshadowed "$tmp/open.exr" |
    awk '{print $1, $5 / sqrt(5)}' | tr '\n' ' ')
echo "probe $PROBE: reference $SAMPLES samples per pixel in $ref_secs s; $shadow_px of 76800 pixels in the"
echo "shadow mask; estimated noise (RMSE) of the reference: $noise"
echo
echo "| technique | lights | irradiance error (mean %) | prepare (s) | render (s) | RMSE whole | rel. whole | RMSE shadows | rel. shadows |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
row() { # label count irr prep secs file
    out=$($C "$6" "$tmp/reference.exr" --unshadowed "$tmp/open.exr")
    w=$(echo "$out" | sed -n 's/^whole  pixels [0-9]* rmse \([^ ]*\) relative \([^ ]*\)/\1 \2/p')
    s=$(echo "$out" | sed -n 's/^shadow pixels [0-9]* rmse \([^ ]*\) relative \([^ ]*\)/\1 \2/p')
    set -- "$1" "$2" "$3" "$4" "$5" $w $s
    printf '| %s | %s | %s | %s | %s | %.4f | %.1f%% | %.4f | %.1f%% |\n' "$1" "$2" "$3" "$4" "$5" "$6" \
        "$(echo "$7" | awk '{print $1 * 100}')" "$8" "$(echo "$9" | awk '{print $1 * 100}')"
}
first=
for n in $COUNTS; do
    for t in mediancut adaptive kmeans irradiance; do
        render "${t}_$n" --probe-technique "$t" --probe-count "$n"
        row "$t" "$n" "$ierr" "$prep" "$secs" "$tmp/${t}_$n.exr"
        [ -n "$IMAGES" ] && [ -z "$first" ] && png "$tmp/${t}_$n.exr" "$IMAGES/probe_$t.png" --probe-technique "$t" \
            --probe-count "$n"
    done
    first=done
done
row "reference, $((SAMPLES / 4)) samples" "-" "-" "-" "-" "$tmp/quarter.exr"
if [ -n "$IMAGES" ]; then
    png "$tmp/reference.exr" "$IMAGES/probe_reference.png" --probe-technique reference --probe-samples "$SAMPLES"
    cp "$tmp/mask.png" "$IMAGES/probe_shadow_mask.png"
fi
