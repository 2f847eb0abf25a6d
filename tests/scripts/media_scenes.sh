#!/bin/sh
# media_scenes.sh BUILD - the example scenes of participating media (examples/scenes/media_*.scene: fog with a spot
# light, a chromatic absorbing liquid in a glass) render with the path integrator, which renders media, in rgb,
# spectrum9, spectrum and bispectral at 24x18, 4 samples per pixel: exit status 0, an image written, no sample NaN
# or infinite (gtrace's summary line) and nothing on stderr (no warning). (scenes_all_models.sh renders them with
# the default integrator, which takes media as vacuum.)
SRC=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=$(cd "${1:-build}" 2> /dev/null && pwd) || { echo "FAIL: no build directory ${1:-build}"; exit 1; }
GTRACE="$BUILD/bin/gtrace"
. "$(dirname "$0")/prelude.sh"
need_program "$GTRACE"
cd "$SRC" || exit 1
n=0
for scene in examples/scenes/media_*.scene; do
    for model in rgb spectrum9 spectrum bispectral; do
        n=$((n + 1))
        out="$TMP/$n.png"
        if ! "$GTRACE" "$scene" --colormodel "$model" --integrator path --width 24 --height 18 --spp 4 --threads 1 \
            -o "$out" > "$TMP/out" 2> "$TMP/err"; then
            fail "$scene in $model: exit status $?: $(head -c 600 "$TMP/err")"
            continue
        fi
        [ -s "$out" ] || fail "$scene in $model: no image written"
        summary="gtrace: $out 24x18, 4 spp, depth [0-9]*, $model, 1 threads: .* 0 non-finite$"
        [ -s "$TMP/err" ] && fail "$scene in $model: output on stderr: $(head -c 600 "$TMP/err")"
        grep -q "^$summary" "$TMP/out" || fail "$scene in $model: no summary line with 0 non-finite: $(cat "$TMP/out")"
    done
done
[ "$n" -ge 8 ] || fail "only $((n / 4)) media scenes found in examples/scenes"
[ "$fails" -eq 0 ] && echo "media_scenes: $n renders passed"
exit "$fails"
