#!/bin/sh
# scale.sh [BUILD] - loading a large scene against POV-Ray 3.7: 1,000,000 spheres (a 1000 x 1000 grid, two diffuse
# materials) in one file each, parsed and built and rendered at 1x1 on 1 thread (gtrace --threads 1, POV-Ray
# +WT1), so that the figures are the load's. Generated into BUILD/bench/scale (never committed; about 130 MB, rewritten
# only when missing or older than this script). By bench/README.md's procedure: an idle check (IDLE_WAIT, IDLE_LOAD),
# RUNS interleaved rounds (default 5), each ratio within a round, medians with min-max over the rounds. Prints:
#   - whole-process CPU (user + system) of gtrace / POV-Ray on the spheres (target <= 0.3);
#   - bytes per sphere of each: peak RSS of the spheres' run minus that of the same file without its spheres, over
#     1,000,000 (target <= 200 for gtrace);
#   - the load of a 100 MB file of plain entries (1,500,000 spheres, gtrace alone): CPU, wall and peak RSS.
# A benchmark: it prints figures and never fails on time.
BUILD=${1:-build}
RUNS=${RUNS:-5}
IDLE_WAIT=${IDLE_WAIT:-30}
IDLE_LOAD=${IDLE_LOAD:-0.5}
GT="$BUILD/bin/gtrace"
RUNSTAT="$BUILD/bench/runstat"
for f in "$GT" "$RUNSTAT"; do
    [ -x "$f" ] || { echo "bench-scale: $f is not built (make bench-scale builds it)"; exit 1; }
done
HAVE_POV=0
command -v povray > /dev/null && HAVE_POV=1
DIR="$BUILD/bench/scale"
mkdir -p "$DIR" || exit 1
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
stale() { [ ! -s "$DIR/$1" ] || [ "$0" -nt "$DIR/$1" ]; }

# gen N STEM [POV]: STEM.scene (gtrace), with POV also STEM.pov (POV-Ray), with N spheres, and STEM_empty.* with none
gen() {
    n=$1
    stem=$2
    stale "$stem.scene" || { [ -n "${3:-}" ] && stale "$stem.pov"; } || stale "${stem}_empty.scene" || return 0
    printf '%s\n' 'colormodel rgb' \
        'camera pinhole { from <0, 50, -150> at <0, 0, 0> fov 40 width 1 height 1 spp 1 depth 1 }' \
        'light point { position <0, 100, -100> intensity rgb 1000 1000 1000 }' \
        'material red lambert { reflectance rgb 0.7 0.2 0.1 }' \
        'material blue lambert { reflectance rgb 0.1 0.3 0.7 }' > "$DIR/${stem}_empty.scene"
    printf '%s\n' '#version 3.7;' 'global_settings { assumed_gamma 1.0 }' \
        'camera { location <0, 50, 150> look_at <0, 0, 0> }' 'light_source { <0, 100, 100> color rgb 1 }' \
        '#declare Red = texture { pigment { rgb <0.7, 0.2, 0.1> } }' \
        '#declare Blue = texture { pigment { rgb <0.1, 0.3, 0.7> } }' > "$DIR/${stem}_empty.pov"
    cp "$DIR/${stem}_empty.scene" "$DIR/$stem.scene"
    [ -z "${3:-}" ] || cp "$DIR/${stem}_empty.pov" "$DIR/$stem.pov"
    awk -v n="$n" -v gt="$DIR/$stem.scene" -v pov="${3:+$DIR/$stem.pov}" 'BEGIN {
        side = int(sqrt(n) + 0.5)
        for (k = 0; k < n; k++) {
            i = int(k / side); j = k % side
            x = (i - side / 2) * 0.1; z = (j - side / 2) * 0.1; y = (k % 7) * 0.01
            printf "object sphere { center <%.2f, %.2f, %.2f> radius 0.04 material %s }\n", x, y, z,
                k % 2 ? "red" : "blue" >> gt
            if (pov != "")
                printf "sphere { <%.2f, %.2f, %.2f>, 0.04 texture { %s } }\n", x, y, -z, k % 2 ? "Red" : "Blue" >> pov
        }
    }'
}
N=1000000
gen $N spheres pov
gen 1500000 big

# idle check
load1() { cut -d' ' -f1 /proc/loadavg; }
waited=0
while awk -v l="$(load1)" -v m="$IDLE_LOAD" 'BEGIN { exit !(l >= m) }' && [ "$waited" -lt "$IDLE_WAIT" ]; do
    sleep 5
    waited=$((waited + 5))
done
load_start=$(cut -d' ' -f1-3 /proc/loadavg)
if awk -v l="$(load1)" -v m="$IDLE_LOAD" 'BEGIN { exit !(l >= m) }'; then
    idle="NOT IDLE (load average $load_start; ratios within a round still compare like with like)"
else
    idle="idle (load average $load_start)"
fi

# once NAME CMD...: one run; appends "wall cpu rss_kib" to TMP/NAME.runs
once() {
    name=$1
    shift
    "$RUNSTAT" "$TMP/$name.t" "$@" > "$TMP/$name.o" 2>&1 || {
        echo "bench-scale: $name failed:"
        tail -5 "$TMP/$name.o"
        exit 1
    }
    awk '{ printf "%.3f %.3f %s\n", $1, $2 + $3, $4 }' "$TMP/$name.t" >> "$TMP/$name.runs"
}
last() { tail -n 1 "$TMP/$1.runs" | cut -d' ' -f"$2"; }
note() { echo "$2" >> "$TMP/$1.r"; }
# stats KEY: "median (min-max)" of the per-round figures
stats() { sort -g "$TMP/$1.r" | awk '{ v[NR] = $1 } END { m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
    printf "%.3g (%.3g-%.3g)", m, v[1], v[NR] }'; }

POV="+W1 +H1 -D -A +WT1 -GA"
r=0
while [ $r -lt "$RUNS" ]; do
    once gt "$GT" "$DIR/spheres.scene" -o "$TMP/gt.png" --threads 1
    once gt0 "$GT" "$DIR/spheres_empty.scene" -o "$TMP/gt0.png" --threads 1
    once big "$GT" "$DIR/big.scene" -o "$TMP/big.png" --threads 1
    note gt_cpu "$(last gt 2)"
    note gt_bytes "$(awk -v a="$(last gt 3)" -v b="$(last gt0 3)" -v n=$N 'BEGIN { print (a - b) * 1024 / n }')"
    note big_cpu "$(last big 2)"
    note big_wall "$(last big 1)"
    note big_mb "$(awk -v a="$(last big 3)" 'BEGIN { print a / 1024 }')"
    if [ $HAVE_POV -eq 1 ]; then
        # shellcheck disable=SC2086
        once pov povray "+I$DIR/spheres.pov" "+O$TMP/pov.png" $POV
        # shellcheck disable=SC2086
        once pov0 povray "+I$DIR/spheres_empty.pov" "+O$TMP/pov0.png" $POV
        note pov_cpu "$(last pov 2)"
        note ratio "$(awk -v a="$(last gt 2)" -v b="$(last pov 2)" 'BEGIN { printf "%.4f", a / b }')"
        note pov_bytes "$(awk -v a="$(last pov 3)" -v b="$(last pov0 3)" -v n=$N 'BEGIN { print (a - b) * 1024 / n }')"
    fi
    r=$((r + 1))
done

echo "== loading 1,000,000 spheres at 1x1, 1 thread: $(nproc) processors, $idle; $RUNS interleaved rounds"
echo "medians (min-max) over the rounds:"
echo "  gtrace: $(stats gt_cpu) s CPU, $(stats gt_bytes) bytes per sphere (peak RSS less the scene without spheres;" \
    "target <= 200)"
if [ $HAVE_POV -eq 1 ]; then
    echo "  POV-Ray 3.7: $(stats pov_cpu) s CPU, $(stats pov_bytes) bytes per sphere"
    echo "  whole-process CPU gtrace / POV-Ray: $(stats ratio) (target <= 0.3)"
else
    echo "  POV-Ray: not installed (Debian package povray); no comparison"
fi
echo "a 100 MB file of plain entries ($(($(wc -c < "$DIR/big.scene") / 1000000)) MB, 1,500,000 spheres), gtrace:" \
    "$(stats big_cpu) s CPU, $(stats big_wall) s wall, $(stats big_mb) MB peak RSS"
