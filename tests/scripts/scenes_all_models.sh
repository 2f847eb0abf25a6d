#!/bin/sh
# scenes_all_models.sh BUILD - every scene of examples/scenes (picked up by its name, *.scene, so a new scene is
# tested the moment it exists) renders in every registered colour model (gcolor list) at 16x12, 1 sample per
# pixel, depth 2: exit status 0, an image written, nothing on stderr but gtrace's summary line and warnings.
# A warning names an entry (FILE:LINE:COL: warning: ...) and appears once; in rgb every light given as a `line`
# (out of the rgb gamut) gets exactly one, in the spectral models none does (they hold lines exactly).
SRC=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=$(cd "${1:-build}" 2> /dev/null && pwd) || { echo "FAIL: no build directory ${1:-build}"; exit 1; }
GTRACE="$BUILD/bin/gtrace"
GCOLOR="$BUILD/bin/gcolor"
for t in "$GTRACE" "$GCOLOR"; do
    [ -x "$t" ] || { echo "FAIL: $t is not built"; exit 1; }
done
. "$(dirname "$0")/prelude.sh"
"$GCOLOR" list > "$TMP/models" || fail "gcolor list failed"
for m in rgb spectrum9 spectrum bispectral; do
    grep -qx "$m" "$TMP/models" || fail "colour model $m is not registered"
done
cd "$SRC" || exit 1
ls examples/scenes/*.scene > "$TMP/scenes"
[ "$(wc -l < "$TMP/scenes")" -ge 20 ] || fail "only $(wc -l < "$TMP/scenes") scenes found in examples/scenes"
# one job per scene and model, two at a time: "SCENE MODEL" -> $TMP/out/N.{png,err,st}
n=0
while read -r scene; do
    while read -r model; do
        n=$((n + 1))
        echo "$n $scene $model"
    done < "$TMP/models"
done < "$TMP/scenes" > "$TMP/jobs"
mkdir "$TMP/out"
# shellcheck disable=SC2016
GTRACE="$GTRACE" OUT="$TMP/out" xargs -P 2 -L 1 sh -c '"$GTRACE" "$2" --colormodel "$3" --width 16 --height 12 \
    --spp 1 --depth 2 --threads 1 -o "$OUT/$1.png" > /dev/null 2> "$OUT/$1.err"; echo $? > "$OUT/$1.st"' job \
    < "$TMP/jobs" || fail "xargs failed"
rendered=0
while read -r i scene model; do
    err="$TMP/out/$i.err"
    st=$(cat "$TMP/out/$i.st" 2> /dev/null)
    if [ "$st" != 0 ]; then
        fail "$scene in $model: exit status ${st:-none}: $(head -c 600 "$err")"
        continue
    fi
    [ -s "$TMP/out/$i.png" ] || fail "$scene in $model: no image written"
    other=$(grep -v "^gtrace: $TMP/out/$i.png 16x12, 1 spp, depth 2, $model" "$err" | grep -v ': warning: ')
    [ -z "$other" ] || fail "$scene in $model: unexpected output on stderr: $other"
    grep ': warning: ' "$err" > "$TMP/warn"
    dup=$(sort "$TMP/warn" | uniq -d)
    [ -z "$dup" ] || fail "$scene in $model: a warning repeated: $dup"
    # each warning names a light entry of the scene (or of a file it includes) at the light's colour
    while IFS= read -r w; do
        where=${w%%: warning:*}
        file=${where%:*:*}
        pos=${where#"$file":}
        line=${pos%:*}
        col=${pos#*:}
        text=$(sed -n "${line}p" "$file" 2> /dev/null | cut -c"$col"-)
        case "$(sed -n "${line}p" "$file" 2> /dev/null)" in
        *light*) ;;
        *) fail "$scene in $model: the warning '$w' does not point into a light entry" ;;
        esac
        [ -n "$text" ] || fail "$scene in $model: the warning '$w' names no position of $file"
    done < "$TMP/warn"
    lines=$(grep -c '^ *light .* line [0-9]' "$scene")
    got=$(grep -c 'warning: the light' "$TMP/warn")
    if [ "$model" = rgb ]; then
        [ "$got" -eq "$lines" ] || fail "$scene in rgb: $got gamut warnings for $lines line lights"
    elif [ "$got" -ne 0 ]; then
        fail "$scene in $model: gamut warnings in a spectral model: $(cat "$TMP/warn")"
    fi
    rendered=$((rendered + 1))
done < "$TMP/jobs"
if [ $fails -gt 0 ]; then
    echo "$fails failure(s) in $n renders"
    exit 1
fi
echo "scenes_all_models: $rendered renders ($(wc -l < "$TMP/scenes") scenes x $(wc -l < "$TMP/models") models) passed"
