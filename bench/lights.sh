#!/bin/sh
# lights.sh [BUILD] - what the number of discrete lights costs the path tracer (`make bench-lights`): a floor and a
# sphere under 2, 4, 8, 16, 32, 100 and 1000 point lights (COUNTS overrides the list) of the same total intensity,
# spread over a square 2 above the floor (intensities 1 to 4 times a base, so the table's choice by power is not
# uniform). Next-event estimation samples every light when the scene has few (lights/light_pick.h's
# LIGHT_PICK_EVERY_MAX) and one chosen by power when it has many. For each count: gtrace's render time (its summary
# line: loading is left out; median and min-max of RUNS rounds, default 3, that run every configuration once in turn),
# the RMSE (gprobe compare) of the image against a reference of the same scene at REF_SPP (default 256) samples
# (REF_GTRACE, default BUILD's gtrace, all threads: its own noise adds SPP / REF_SPP of its variance a sample to the
# squared RMSE), and time x RMSE^2, which does not depend on the samples: the time to reach a given RMSE is
# proportional to it. 80x60, SPP (default 4) spp, depth 4, path, 1 thread. GTRACE: another gtrace to measure;
# COMPARE: a second gtrace (e.g. a build with another LIGHT_PICK_EVERY_MAX: CFLAGS=-DLIGHT_PICK_EVERY_MAX=0 for one
# light a vertex everywhere) measured on the same scenes and references, with the ratio of its time to equal RMSE over
# the first's. A benchmark: it prints
# figures and never fails on time.
BUILD=${1:-build}
GT=${GTRACE:-$BUILD/bin/gtrace}
REF_GT=${REF_GTRACE:-$BUILD/bin/gtrace}
GP=$BUILD/bin/gprobe
[ -x "$GT" ] || { echo "bench-lights: $GT is not built"; exit 1; }
[ -x "$REF_GT" ] || { echo "bench-lights: $REF_GT is not built"; exit 1; }
[ -x "$GP" ] || { echo "bench-lights: $GP is not built"; exit 1; }
[ -z "${COMPARE:-}" ] || [ -x "$COMPARE" ] || { echo "bench-lights: $COMPARE is not built"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
RUNS=${RUNS:-3}
COUNTS=${COUNTS:-2 4 8 16 32 100 1000}
W=80 H=60 SPP=${SPP:-4} REF_SPP=${REF_SPP:-256}
for n in $COUNTS; do
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
    "$REF_GT" "$TMP/lights$n.scene" -o "$TMP/ref$n.exr" --width $W --height $H --spp "$REF_SPP" --depth 4 \
        --integrator path > /dev/null 2>&1 || { echo "bench-lights: the reference of $n lights failed"; exit 1; }
done
run() { # GTRACE N OUT: render seconds
    "$1" "$TMP/lights$2.scene" -o "$3" --width $W --height $H --spp "$SPP" --depth 4 --integrator path \
        --threads 1 2>&1 |
        awk '/^gtrace: .* rays/ { for (i = 1; i <= NF; i++) if ($i == "s,") t = $(i - 1) }
             END { if (t == "") exit 1; print t }'
}
rmse() { "$GP" compare "$1" "$2" | awk '$1 == "whole" { print $5 }'; }
r=0
while [ $r -lt "$RUNS" ]; do
    for n in $COUNTS; do
        t=$(run "$GT" $n "$TMP/a$n.exr") || t=failed
        echo "$n $t" >> "$TMP/times_a"
        if [ -n "${COMPARE:-}" ]; then
            t=$(run "$COMPARE" $n "$TMP/b$n.exr") || t=failed
            echo "$n $t" >> "$TMP/times_b"
        fi
    done
    r=$((r + 1))
done
median() { # FILE N: the median, min and max of N's times
    awk -v n=$2 '$1 == n && $2 != "failed" { print $2 }' "$1" | sort -g |
        awk '{ t[NR] = $1 } END { if (NR == 0) { print "failed"; exit }
            m = NR % 2 ? t[(NR + 1) / 2] : (t[NR / 2] + t[NR / 2 + 1]) / 2
            printf "%.4f %.4f %.4f\n", m, t[1], t[NR] }'
}
echo "point lights over a floor, ${W}x${H}, $SPP spp (reference $REF_SPP), depth 4, path, 1 thread, $RUNS rounds"
echo "A: $GT${COMPARE:+; B: $COMPARE}"
if [ -n "${COMPARE:-}" ]; then
    printf '%-7s %9s %20s %9s %11s  %9s %20s %9s %11s  %9s\n' lights "A s" "(min-max)" "A RMSE" "A t*RMSE^2" \
        "B s" "(min-max)" "B RMSE" "B t*RMSE^2" "B/A time"
else
    printf '%-7s %9s %20s %9s %11s\n' lights "s" "(min-max)" "RMSE" "t*RMSE^2"
fi
for n in $COUNTS; do
    set -- $(median "$TMP/times_a" $n)
    [ "$1" = failed ] && { printf '%-7s %9s\n' $n failed; continue; }
    ta=$1 ea=$(rmse "$TMP/a$n.exr" "$TMP/ref$n.exr")
    line=$(awk -v n=$n -v t=$1 -v lo=$2 -v hi=$3 -v e="$ea" \
        'BEGIN { printf "%-7s %9.4f %9.4f-%-9.4f %9.5f %11.4g", n, t, lo, hi, e, t * e * e }')
    if [ -n "${COMPARE:-}" ]; then
        set -- $(median "$TMP/times_b" $n)
        eb=$(rmse "$TMP/b$n.exr" "$TMP/ref$n.exr")
        line="$line$(awk -v t=$1 -v lo=$2 -v hi=$3 -v e="$eb" -v ta="$ta" -v ea="$ea" 'BEGIN {
            printf "  %9.4f %9.4f-%-9.4f %9.5f %11.4g  %9.3f", t, lo, hi, e, t * e * e, t * e * e / (ta * ea * ea) }')"
    fi
    echo "$line"
done
