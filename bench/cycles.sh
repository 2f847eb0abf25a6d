#!/bin/sh
# cycles.sh [BUILD] - gtrace's path tracer against Blender Cycles on the Cornell box: time to equal RMSE.
#
# The scene is examples/scenes/cornell.scene in rgb; its Cycles twin is bench/cycles_cornell.py (Blender's Python:
# the same boxes, camera and light, Lambert surfaces, 8 bounces, no clamping, denoising or adaptive sampling, a
# one-pixel box filter). Both render SIZE x SIZE (default 128) on 1 and on 2 threads, at N samples per pixel
# (default 64) and at N/4; the marginal cost of a sample is the difference of the two runs' times over 3N/4 (which
# leaves out start-up, loading, the BVH and writing), the noise is the RMSE at N against a long reference of the
# same renderer (REF_SPP, default 4096, 2 threads): gtrace's Sobol renders against its independent-sampler reference
# and the other way round, Cycles' renders (seed = the round) against its own of another seed, so no render shares
# a random sequence with its reference. Time to equal RMSE is cost per sample times N * RMSE^2 (bench/cycles_stats.py
# summary); the table gives its ratios, gtrace (--sampler sobol, the default, and independent) over Cycles and
# Sobol over independent, for the whole image (the lamp's pixels left out: Cycles' area light is not seen by the
# camera) and for four wall and floor patches, with wall time (gtrace's render time, Cycles' render call) and CPU
# time (gtrace's process, Cycles' render call), medians and min-max over RUNS rounds (default 5), each running every
# configuration in turn. The references' patch means are printed side by side (the twins agree within their noise).
# Blender is optional (Debian's `blender`): without it the benchmark says so and stops. It never fails on time.
BUILD=${1:-build}
GT=${GTRACE:-$BUILD/bin/gtrace} # GTRACE: another gtrace (a copy beside it, kept while BUILD is rebuilt)
DIR=$(dirname "$0")
SCENE="$DIR/../examples/scenes/cornell.scene"
command -v blender > /dev/null 2>&1 || { echo "bench-cycles: blender not installed, skipped"; exit 0; }
[ -x "$GT" ] || { echo "bench-cycles: $GT is not built"; exit 1; }
command -v oiiotool > /dev/null 2>&1 || { echo "bench-cycles: needs oiiotool (openimageio-tools)"; exit 1; }
command -v python3 > /dev/null 2>&1 || { echo "bench-cycles: needs python3"; exit 1; }
[ -x /usr/bin/time ] || { echo "bench-cycles: needs GNU time (/usr/bin/time, Debian package time)"; exit 1; }
SIZE=${SIZE:-128} N=${SPP:-64} REF=${REF_SPP:-4096} RUNS=${RUNS:-5}
Q=$((N / 4))
[ "$Q" -ge 1 ] || { echo "bench-cycles: SPP must be at least 4"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
STATS="python3 $DIR/cycles_stats.py"

# gt SAMPLER SPP THREADS OUT: "WALL CPU" (gtrace's render time, the process's CPU seconds)
gt() {
    /usr/bin/time -f '%U %S' -o "$TMP/cpu" "$GT" "$SCENE" --colormodel rgb -o "$4" --width "$SIZE" --height "$SIZE" \
        --spp "$2" --depth 8 --integrator path --sampler "$1" --threads "$3" > "$TMP/gt.log" 2>&1 || return 1
    t=$(awk '/^gtrace: .* rays/ { for (i = 1; i <= NF; i++) if ($i == "s,") t = $(i - 1) } END { print t }' \
        "$TMP/gt.log")
    awk -v t="$t" '{ printf "%s %.4f\n", t, $1 + $2 }' "$TMP/cpu"
}
# cy SPP THREADS SEED OUT: "WALL CPU" of Cycles' render call
cy() {
    blender -b --factory-startup -P "$DIR/cycles_cornell.py" -- "$4" "$SIZE" "$1" "$2" "$3" > "$TMP/cy.log" 2>&1 ||
        return 1
    awk '$1 == "cycles-render-seconds" { print $2, $3; ok = 1 } END { exit !ok }' "$TMP/cy.log"
}

load=$(cut -d' ' -f1 /proc/loadavg)
state=$(awk -v l="$load" 'BEGIN { print (l < 1.0 ? "idle" : "NOT IDLE") }')
echo "Cornell box ${SIZE}x${SIZE}, depth 8, rgb; $N and $Q spp, references $REF spp; $RUNS rounds; $state (load $load)"
echo "$(blender --version 2>/dev/null | head -1), gtrace $GT"
if ! { gt sobol "$REF" 2 "$TMP/ref_sobol.exr" > /dev/null && gt independent "$REF" 2 "$TMP/ref_independent.exr" \
    > /dev/null && cy "$REF" 2 1000 "$TMP/ref_cycles.exr" > /dev/null; }; then
    echo "bench-cycles: a reference render failed"
    exit 1
fi
echo "patch means (luminance) of the references:"
echo "  gtrace sobol        $($STATS means "$TMP/ref_sobol.exr")"
echo "  gtrace independent  $($STATS means "$TMP/ref_independent.exr")"
echo "  Cycles              $($STATS means "$TMP/ref_cycles.exr")"
echo "  RMSE gtrace against Cycles (the twins' difference with the references' noise): $($STATS rmse \
"$TMP/ref_independent.exr" "$TMP/ref_cycles.exr")"

r=1
while [ $r -le "$RUNS" ]; do
    for t in 1 2; do
        for cfg in sobol independent cycles; do
            case $cfg in
            sobol) ref=ref_independent ;;
            independent) ref=ref_sobol ;;
            cycles) ref=ref_cycles ;;
            esac
            if [ $cfg = cycles ]; then
                a=$(cy "$Q" "$t" "$r" "$TMP/q.exr") && b=$(cy "$N" "$t" "$r" "$TMP/n.exr")
            else
                a=$(gt "$cfg" "$Q" "$t" "$TMP/q.exr") && b=$(gt "$cfg" "$N" "$t" "$TMP/n.exr")
            fi || { echo "bench-cycles: $cfg on $t threads failed"; continue; }
            e=$($STATS rmse "$TMP/n.exr" "$TMP/$ref.exr" | awk '{ print $2, $4 }')
            echo "$r $t $cfg $N $b $a $e" >> "$TMP/records"
        done
    done
    r=$((r + 1))
done
$STATS summary "$TMP/records"
