#!/bin/sh
# lights.sh [BUILD] - what the number of discrete lights costs the path tracer (`make bench-lights`): a floor and a
# sphere under 1, 100 and 1000 point lights of the same total intensity, spread over a square 2 above the floor
# (intensities 1 to 4 times a base, so the table's choice by power is not uniform). Next-event estimation takes one
# light a vertex from an alias table by power (lights/light_pick.h), so the time per sample should not grow with the
# number of lights. 160x120, 4 spp, depth 4, path, 1 thread; gtrace's render time (its summary line: loading is left
# out) and camera samples per second, median and min-max of RUNS rounds (default 3) that run every configuration once
# in turn. GTRACE: another gtrace to measure (e.g. an older build, for a before-and-after). A benchmark: it prints
# figures and never fails on time.
BUILD=${1:-build}
GT=${GTRACE:-$BUILD/bin/gtrace}
[ -x "$GT" ] || { echo "bench-lights: $GT is not built"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
RUNS=${RUNS:-3}
W=160 H=120 SPP=4
for n in 1 100 1000; do
    {
        echo "colormodel rgb"
        echo "camera pinhole { from <0, 2, 4> at <0, 0.3, 0> fov 40 }"
        echo "object plane { point <0, 0, 0> normal <0, 1, 0> material lambert { reflectance rgb 0.5 0.5 0.5 } }"
        echo "object sphere { center <0.3, 0.4, 0.2> radius 0.4 material lambert { reflectance rgb 0.7 0.6 0.5 } }"
        awk -v n=$n 'BEGIN {
            side = int(sqrt(n)); if (side * side < n) side++
            for (k = 0; k < n; k++) sum += 1 + k % 4
            for (k = 0; k < n; k++) {
                x = -1 + 2 * ((k % side) + 0.5) / side; z = -1 + 2 * (int(k / side) + 0.5) / side
                i = 12 * (1 + k % 4) / sum
                printf "light point { position <%.4f, 2, %.4f> intensity rgb %.6g %.6g %.6g }\n", x, z, i, i, i } }'
    } > "$TMP/lights$n.scene"
done
run() { # N: render seconds
    "$GT" "$TMP/lights$1.scene" -o "$TMP/lights$1.exr" --width $W --height $H --spp $SPP --depth 4 \
        --integrator path --threads 1 2>&1 |
        awk '/^gtrace: .* rays/ { for (i = 1; i <= NF; i++) if ($i == "s,") t = $(i - 1) }
             END { if (t == "") exit 1; print t }'
}
r=0
while [ $r -lt "$RUNS" ]; do
    for n in 1 100 1000; do
        t=$(run $n) || t=failed
        echo "$n $t" >> "$TMP/times"
    done
    r=$((r + 1))
done
echo "point lights over a floor, ${W}x${H}, $SPP spp, depth 4, path, 1 thread, $RUNS rounds ($GT)"
printf '%-14s %8s %18s %12s\n' "point lights" "s" "(min-max)" "samples/s"
for n in 1 100 1000; do
    awk -v n=$n '$1 == n && $2 != "failed" { print $2 }' "$TMP/times" | sort -g |
        awk -v n=$n -v s=$((W * H * SPP)) '{ t[NR] = $1 } END {
            if (NR == 0) { printf "%-14s %8s\n", n, "failed"; exit }
            m = NR % 2 ? t[(NR + 1) / 2] : (t[NR / 2] + t[NR / 2 + 1]) / 2
            printf "%-14s %8.4f %8.4f-%-8.4f %12.0f\n", n, m, t[1], t[NR], s / m }'
done
