#!/bin/sh
# grid_ratios.sh ROUNDS [GTRACE] - the spectrum model's cost against rgb's as its number of samples grows: Whitted on
# bench/pov/scene.scene (800x600, 1 thread) with `colormodel spectrum { step S }` for S = 50, 20, 10, 5 (the default)
# and 2 nm, that is 9, 21, 41, 81 and 201 samples from 380 to 780 nm. A round renders rgb and then each grid; each
# grid's ratio is its render time (gtrace's summary line) over the rgb render's of the same round. Prints the medians
# (min-max) over the rounds and, when valgrind is installed and CG=1, each render's instructions and first-level data
# cache misses as cachegrind simulates them at 320x240 (deterministic: they do not depend on the machine's load).
# A benchmark: it prints figures and never fails on time.
ROUNDS=${1:?usage: grid_ratios.sh ROUNDS [GTRACE]}
SRC=$(cd "$(dirname "$0")/.." && pwd)
GT=${2:-$SRC/build/bin/gtrace}
[ -x "$GT" ] || { echo "grid_ratios: $GT is not built"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cp "$SRC/bench/pov/scene.scene" "$TMP/rgb.scene"
for s in 50 20 10 5 2; do
    sed "s/^colormodel rgb\$/colormodel spectrum { step $s }/" "$SRC/bench/pov/scene.scene" > "$TMP/s$s.scene"
    grep -q "^colormodel spectrum" "$TMP/s$s.scene" || { echo "grid_ratios: the scene's colormodel line changed"; exit 1; }
done
render_time() { # SCENE: gtrace's render seconds
    "$GT" "$TMP/$1.scene" -o "$TMP/o.png" --threads 1 2>&1 |
        awk '/^gtrace: .* rays/ { for (i = 1; i <= NF; i++) if ($i == "s,") print $(i - 1) }'
}
echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
r=0
while [ "$r" -lt "$ROUNDS" ]; do
    base=$(render_time rgb)
    for s in 50 20 10 5 2; do
        echo "s$s $base $(render_time s$s)"
    done
    r=$((r + 1))
done > "$TMP/pairs"
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "spectrum / rgb render time, medians (min-max) of $ROUNDS rounds, 800x600, 1 thread:"
for s in 50 20 10 5 2; do
    n=$(( (780 - 380) / s + 1 ))
    awk -v k="s$s" '$1 == k && $2 > 0 { print $3 / $2 }' "$TMP/pairs" | sort -g | awk -v s="$s" -v n="$n" '
        { v[NR] = $1 } END { if (!NR) exit
            med = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
            printf "  step %2d nm, %3d samples: %.3f (%.3f-%.3f)\n", s, n, med, v[1], v[NR] }'
done
if [ "${CG:-0}" = 1 ] && command -v valgrind > /dev/null; then
    echo "cachegrind, 320x240, 1 thread: instructions, first-level data cache misses"
    for v in rgb s50 s20 s10 s5 s2; do
        valgrind --tool=cachegrind --cache-sim=yes --cachegrind-out-file=/dev/null "$GT" "$TMP/$v.scene" \
            -o "$TMP/o.png" --width 320 --height 240 --threads 1 2>&1 |
            awk -v v="$v" '/I +refs/ { i = $4 } /D1 +misses/ { d = $4 } END { printf "  %-4s %s  %s\n", v, i, d }'
    done
fi
