#!/bin/sh
# cycles.sh [BUILD] - gtrace's path tracer against Blender Cycles: time to equal RMSE on three scenes and their twins.
#
# The scenes (SCENES, default "cornell glossy probe"), each in rgb with a Cycles twin written in Blender's Python:
#   cornell  examples/scenes/cornell.scene, Lambert surfaces: bench/cycles_cornell.py
#   glossy   bench/scenes/cycles_glossy.scene, the box with a rough gold and a glass sphere: cycles_cornell.py glossy
#   probe    bench/scenes/cycles_probe.scene, objects under examples/scenes/sky.hdr: bench/cycles_probe.py
# (each twin's header says how its materials, lights and camera match; 8 bounces, no clamping, denoising or adaptive
# sampling, a one-pixel box filter: gtrace averages a pixel's samples with equal weight; Cycles' default, a
# 1.5-pixel Blackman-Harris filter, would blur the noise over neighbouring pixels). Both render SIZE x SIZE (default
# 128) on 1 and on 2 threads, at N samples per pixel (default 64) and at N/4; the marginal cost of a sample is the
# difference of the two runs' times over 3N/4 (which leaves out start-up, loading, the BVH and writing), the noise is
# the RMSE at N against a long reference of the same renderer (REF_SPP, default 4096, 2 threads): gtrace's Sobol
# renders against its independent-sampler reference and the other way round, Cycles' renders (seed = the round)
# against its own of another seed, so no render shares a random sequence with its reference. Time to equal RMSE is
# cost per sample times N * RMSE^2 (bench/cycles_stats.py summary); the table gives its ratios, gtrace (--sampler
# sobol, the default, and independent) over Cycles and Sobol over independent, for the whole image (the pixels that
# see a lamp or the sun, and their neighbours, left out: Cycles' area light is not seen by the camera) and for the
# scene's patches (cycles_stats.py), with wall time (gtrace's render time, Cycles' render call) and CPU time
# (gtrace's process, Cycles' render call), medians and min-max over RUNS rounds (default 5), each running every
# configuration (CONFIGS, default "sobol independent cycles") of every scene in turn. The references' patch means are
# printed side by side (the twins agree within their noise and their materials' differences). REF_DIR: keep the
# references there (DIR/SCENE/ref_*.exr) and use those found there (the Sobol one is made only for CONFIGS with
# independent). Blender is optional (Debian's `blender`): without
# it the benchmark says so and stops. It never fails on time.
BUILD=${1:-build}
GT=${GTRACE:-$BUILD/bin/gtrace} # GTRACE: another gtrace (a copy beside it, kept while BUILD is rebuilt)
DIR=$(dirname "$0")
command -v blender > /dev/null 2>&1 || { echo "bench-cycles: blender not installed, skipped"; exit 0; }
[ -x "$GT" ] || { echo "bench-cycles: $GT is not built"; exit 1; }
command -v oiiotool > /dev/null 2>&1 || { echo "bench-cycles: needs oiiotool (openimageio-tools)"; exit 1; }
command -v python3 > /dev/null 2>&1 || { echo "bench-cycles: needs python3"; exit 1; }
[ -x /usr/bin/time ] || { echo "bench-cycles: needs GNU time (/usr/bin/time, Debian package time)"; exit 1; }
SIZE=${SIZE:-128} N=${SPP:-64} REF=${REF_SPP:-4096} RUNS=${RUNS:-5}
SCENES=${SCENES:-cornell glossy probe} CONFIGS=${CONFIGS:-sobol independent cycles}
Q=$((N / 4))
[ "$Q" -ge 1 ] || { echo "bench-cycles: SPP must be at least 4"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
STATS="python3 $DIR/cycles_stats.py"

# scene NAME: sets SCENE (gtrace's file), CY (the twin's script) and VARIANT (its argument)
scene() {
    case $1 in
    cornell) SCENE="$DIR/../examples/scenes/cornell.scene" CY="$DIR/cycles_cornell.py" VARIANT=cornell ;;
    glossy) SCENE="$DIR/scenes/cycles_glossy.scene" CY="$DIR/cycles_cornell.py" VARIANT=glossy ;;
    probe) SCENE="$DIR/scenes/cycles_probe.scene" CY="$DIR/cycles_probe.py" VARIANT= ;;
    *) echo "bench-cycles: unknown scene $1"; exit 1 ;;
    esac
}
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
    # shellcheck disable=SC2086 # VARIANT: no word or one
    blender -b --factory-startup -P "$CY" -- "$4" "$SIZE" "$1" "$2" "$3" $VARIANT > "$TMP/cy.log" 2>&1 || return 1
    awk '$1 == "cycles-render-seconds" { print $2, $3; ok = 1 } END { exit !ok }' "$TMP/cy.log"
}

load=$(cut -d' ' -f1 /proc/loadavg)
state=$(awk -v l="$load" 'BEGIN { print (l < 1.0 ? "idle" : "NOT IDLE") }')
echo "scenes: $SCENES; ${SIZE}x${SIZE}, depth 8, rgb; $N and $Q spp, references $REF spp; $RUNS rounds;" \
    "$state (load $load)"
echo "$(blender --version 2>/dev/null | head -1), gtrace $GT"
for s in $SCENES; do
    scene "$s"
    R="$TMP/$s"
    [ -n "$REF_DIR" ] && R="$REF_DIR/$s"
    mkdir -p "$R"
    case " $CONFIGS " in *" independent "*) need_sobol=1 ;; *) need_sobol= ;; esac
    { [ -s "$R/ref_sobol.exr" ] || [ -z "$need_sobol" ] || gt sobol "$REF" 2 "$R/ref_sobol.exr" > /dev/null; } &&
        { [ -s "$R/ref_independent.exr" ] || gt independent "$REF" 2 "$R/ref_independent.exr" > /dev/null; } &&
        { [ -s "$R/ref_cycles.exr" ] || cy "$REF" 2 1000 "$R/ref_cycles.exr" > /dev/null; } ||
        { echo "bench-cycles: a reference render of $s failed"; exit 1; }
    ln -s "$R" "$TMP/ref_$s" 2> /dev/null || true
    echo "$s: patch means (luminance) of the references:"
    [ -s "$R/ref_sobol.exr" ] && echo "  gtrace sobol        $($STATS means "$R/ref_sobol.exr" "$s")"
    echo "  gtrace independent  $($STATS means "$R/ref_independent.exr" "$s")"
    echo "  Cycles              $($STATS means "$R/ref_cycles.exr" "$s")"
    echo "  RMSE gtrace against Cycles (the twins' difference with the references' noise): $($STATS rmse \
"$R/ref_independent.exr" "$R/ref_cycles.exr" "$s")"
done

r=1
while [ $r -le "$RUNS" ]; do
    for s in $SCENES; do
        scene "$s"
        for t in 1 2; do
            for cfg in $CONFIGS; do
                case $cfg in
                sobol) ref=ref_independent ;;
                independent) ref=ref_sobol ;;
                cycles) ref=ref_cycles ;;
                *) echo "bench-cycles: unknown configuration $cfg"; exit 1 ;;
                esac
                if [ "$cfg" = cycles ]; then
                    a=$(cy "$Q" "$t" "$r" "$TMP/q.exr") && b=$(cy "$N" "$t" "$r" "$TMP/n.exr")
                else
                    a=$(gt "$cfg" "$Q" "$t" "$TMP/q.exr") && b=$(gt "$cfg" "$N" "$t" "$TMP/n.exr")
                fi || { echo "bench-cycles: $s $cfg on $t threads failed"; continue; }
                e=$($STATS rmse "$TMP/n.exr" "$TMP/ref_$s/$ref.exr" "$s" | awk '{ print $2, $4 }')
                echo "$s $r $t $cfg $N $b $a $e" >> "$TMP/records"
            done
        done
    done
    r=$((r + 1))
done
[ -n "$REF_DIR" ] && cp "$TMP/records" "$REF_DIR/records.$$"
$STATS summary "$TMP/records"
