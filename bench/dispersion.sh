#!/bin/sh
# dispersion.sh [BUILD] - what dispersion costs: the same scene (a glass sphere 1.2 wide over a checker floor,
# 640x480, 1 sample per pixel, depth 8, 1 thread) with a constant index 1.5168 and with BK7's Sellmeier index,
# in every colour model, at the default band count (16 groups) and with one group (--bands 1: dispersion off).
# Runs are interleaved (constant, dispersive, constant, ...) RUNS times (default 3) and the ratio of each pair's
# render CPU time is taken; the median of those ratios is printed, with the rays traced. A benchmark: it
# prints figures and never fails on time.
BUILD=${1:-build}
RUNS=${RUNS:-3}
GT="$BUILD/bin/gtrace"
[ -x "$GT" ] || { echo "bench-dispersion: $GT is not built"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
scene() { # INDEX -> a scene file
    f="$TMP/$(echo "$1" | cut -c1-9 | tr ' .' '__').scene"
    cat > "$f" <<SCENE
material floor interpolate { a lambert { reflectance rgb 0.8 0.8 0.8 } b lambert { reflectance rgb 0.1 0.1 0.1 }
                             t checker { dims 2 frequency 4 } }
object plane { point <0, 0, 0> normal <0, 1, 0> material floor }
object sphere { center <0, 0.6, 0> radius 0.6 material dielectric { index $1 } }
camera pinhole { from <0, 1.2, 3> at <0, 0.5, 0> fov 30 width 640 height 480 spp 1 depth 8 }
light point { position <-2, 4, 3> intensity rgb 20 20 20 }
light background { color rgb 0.3 0.35 0.4 }
SCENE
    echo "$f"
}
CONST=$(scene "1.5168")
DISP=$(scene "sellmeier 1.03961212 0.231792344 1.01046945 0.00600069867 0.0200179144 103.560653")
# render CPU seconds and rays of one run (from gtrace's summary line)
run() { # SCENE MODEL BANDS
    "$GT" "$1" -o "$TMP/out.exr" --colormodel "$2" --bands "$3" --threads 1 2>&1 |
        awk '/^gtrace: .* rays/ { for (i = 1; i <= NF; i++) { if ($i == "s,") t = $(i - 1); if ($i == "M" && $(i + 1) == "rays,") r = $(i - 1) } }
             END { if (t == "") exit 1; print t, r }'
}
median() { sort -n | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
printf '%-11s %-6s %10s %10s %9s %9s %8s\n' model bands "const s" "disp s" "const Mr" "disp Mr" "ratio"
for model in rgb spectrum9 spectrum bispectral; do
    for bands in 16 1; do
        : > "$TMP/ratios"
        i=0
        while [ $i -lt "$RUNS" ]; do
            c=$(run "$CONST" $model $bands) || { echo "bench-dispersion: gtrace failed"; exit 1; }
            d=$(run "$DISP" $model $bands) || { echo "bench-dispersion: gtrace failed"; exit 1; }
            echo "$c $d" | awk '{ print $3 / $1 }' >> "$TMP/ratios"
            i=$((i + 1))
        done
        ratio=$(median < "$TMP/ratios")
        echo "$c $d" | awk -v m=$model -v b=$bands -v q="$ratio" '{ printf "%-11s %-6s %10.3f %10.3f %9.2f %9.2f %7.2fx\n", m, b, $1, $3, $2, $4, q }'
    done
done
echo "(ratio: dispersive / constant-index render time, median of $RUNS interleaved pairs; 1 thread)"
