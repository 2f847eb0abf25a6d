#!/bin/sh
# render_identity.sh BUILD OUTDIR [REFDIR] - renders every scene of examples/scenes, the bench scene
# (bench/pov/scene.scene) and the path tracer's demo into OUTDIR, in every built-in colour model, with the
# Whitted tracer and the path tracer, as float OpenEXR, with each render's exit status and messages. With REFDIR,
# every image must hold exactly REFDIR's pixel values (idiff -fail 0 -warn 0: every float equal; the files' own
# bytes differ by their DateTime), every status and message file must be byte-identical, and a missing or extra
# file is a failure.
#
# For refactorings that must not change what anything computes: render once from the old build, once from the new,
# and compare (`scripts/render_identity.sh build /tmp/new /tmp/old`). One thread each, two renders at a time.
set -u
BUILD=${1:?usage: render_identity.sh BUILD OUTDIR [REFDIR]}
OUT=${2:?usage: render_identity.sh BUILD OUTDIR [REFDIR]}
REF=${3:-}
SRC=$(cd "$(dirname "$0")/.." && pwd)
GT=$(cd "$BUILD" && pwd)/bin/gtrace
[ -x "$GT" ] || { echo "render_identity: $GT is not built"; exit 1; }
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
cd "$SRC" || exit 1
jobs="$OUT/.jobs"
: > "$jobs"
for scene in examples/scenes/*.scene bench/pov/scene.scene; do
    name=$(echo "$scene" | tr '/' '_' | sed 's/\.scene$//')
    for model in rgb spectrum9 spectrum bispectral; do
        echo "$scene $model whitted 48 36 2 $name.$model.whitted" >> "$jobs"
        echo "$scene $model path 32 24 4 $name.$model.path" >> "$jobs"
    done
done
# shellcheck disable=SC2016
GT="$GT" OUT="$OUT" xargs -P 2 -L 1 sh -c '"$GT" "$1" --colormodel "$2" --integrator "$3" --width "$4" \
    --height "$5" --spp "$6" --depth 4 --threads 1 -q -o "$OUT/$7.exr" 2> "$OUT/$7.err" > /dev/null
    echo $? > "$OUT/$7.status"' job < "$jobs"
rm -f "$jobs"
n=$(ls "$OUT"/*.status | wc -l)
echo "render_identity: $n renders in $OUT"
[ -n "$REF" ] || exit 0
status=0
for f in "$REF"/*.exr "$REF"/*.status "$REF"/*.err; do
    b=$(basename "$f")
    if [ ! -f "$OUT/$b" ]; then echo "render_identity: $b missing"; status=1
    elif [ "${b%.exr}" != "$b" ]; then
        idiff -q -fail 0 -warn 0 "$f" "$OUT/$b" > /dev/null 2>&1 || { echo "render_identity: $b differs"; status=1; }
    elif ! cmp -s "$f" "$OUT/$b"; then echo "render_identity: $b differs"; status=1; fi
done
for f in "$OUT"/*.exr; do
    [ -f "$REF/$(basename "$f")" ] || { echo "render_identity: $(basename "$f") is new"; status=1; }
done
[ $status -eq 0 ] && echo "render_identity: all $(ls "$REF"/*.exr | wc -l) images identical to $REF"
exit $status
