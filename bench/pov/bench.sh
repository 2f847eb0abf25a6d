#!/bin/sh
# bench.sh [BUILD] - gtrace against POV-Ray 3.7 on the same scene (scene.scene / scene.pov: checker floor,
# glass, mirror, wood, marble, two point lights; 800x600, 1 sample per pixel, depth 8, 2 threads).
# Prints in one run: the wall-time ratio gtrace/POV-Ray (whole process and render only), rays per second,
# the time ratios of the colour models to rgb, peak memory, and the speed-up from 1 to 2 threads.
# Each figure is the best of RUNS runs (default 3; set RUNS=1 for a quick look). A benchmark: it prints
# figures and never fails on time.
BUILD=${1:-build}
RUNS=${RUNS:-3}
DIR=$(cd "$(dirname "$0")" && pwd)
GT="$BUILD/bin/gtrace"
if [ ! -x "$GT" ]; then
    echo "bench-pov: $GT is not built (make BUILD=$BUILD)"
    exit 1
fi
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
TIME=/usr/bin/time
if [ ! -x "$TIME" ]; then
    echo "bench-pov: needs GNU time (/usr/bin/time, Debian package time)"
    exit 1
fi

# best NAME CMD...: runs CMD RUNS times; keeps the fastest run's wall time, CPU time, peak RSS and output
best() {
    name=$1
    shift
    i=0
    while [ $i -lt "$RUNS" ]; do
        "$TIME" -f "%e %U %S %M" -o "$TMP/$name.t" "$@" > "$TMP/$name.o" 2>&1 || {
            echo "bench-pov: $name failed:"
            cat "$TMP/$name.o"
            exit 1
        }
        if [ ! -f "$TMP/$name.best" ] || awk -v a="$(cut -d' ' -f1 "$TMP/$name.t")" \
            -v b="$(cut -d' ' -f1 "$TMP/$name.best")" 'BEGIN { exit !(a < b) }'; then
            cp "$TMP/$name.t" "$TMP/$name.best"
            cp "$TMP/$name.o" "$TMP/$name.out"
        fi
        i=$((i + 1))
    done
}
wall() { cut -d' ' -f1 "$TMP/$1.best"; }
cpu() { awk '{ print $2 + $3 }' "$TMP/$1.best"; }
rss() { awk '{ printf "%.0f", $4 / 1024 }' "$TMP/$1.best"; }
# render time and rays/s from gtrace's summary line
render_s() { sed -n 's/.*threads: \([0-9.]*\) s,.*/\1/p' "$TMP/$1.out"; }
rays_s() { sed -n 's/.* \([0-9.]*\) M rays\/s.*/\1/p' "$TMP/$1.out"; }
mrays() { sed -n 's/.* s, \([0-9.]*\) M rays,.*/\1/p' "$TMP/$1.out"; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%.2f", a / b; else print "n/a" }'; }

echo "== gtrace vs POV-Ray: $(nproc) processors, load average $(cut -d' ' -f1-3 /proc/loadavg), best of $RUNS"
for m in rgb spectrum9 spectrum bispectral; do
    best "gt_$m" "$GT" "$DIR/scene.scene" -o "$TMP/gt_$m.png" --threads 2 --colormodel $m
done
best gt_rgb_1 "$GT" "$DIR/scene.scene" -o "$TMP/gt_rgb_1.png" --threads 1 --colormodel rgb
best gt_start "$GT" --help

printf "%-18s %8s %8s %9s %9s %9s %8s\n" "" "wall s" "cpu s" "render s" "M rays" "M rays/s" "peak MB"
for m in rgb spectrum9 spectrum bispectral; do
    printf "%-18s %8s %8s %9s %9s %9s %8s\n" "gtrace $m" "$(wall gt_$m)" "$(cpu gt_$m)" "$(render_s gt_$m)" \
        "$(mrays gt_$m)" "$(rays_s gt_$m)" "$(rss gt_$m)"
done
printf "%-18s %8s %8s %9s %9s %9s %8s\n" "rgb, 1 thr" "$(wall gt_rgb_1)" "$(cpu gt_rgb_1)" "$(render_s gt_rgb_1)" \
    "$(mrays gt_rgb_1)" "$(rays_s gt_rgb_1)" "$(rss gt_rgb_1)"

if command -v povray > /dev/null; then
    best pov povray "+I$DIR/scene.pov" "+O$TMP/pov.png" +W800 +H600 -A +WT2 -D +FN -V -GA
    # POV-Ray prints its trace time as "(1.234 seconds)" on the Trace Time line
    povray "+I$DIR/scene.pov" "+O$TMP/pov.png" +W800 +H600 -A +WT2 -D +FN > "$TMP/pov.stats" 2>&1
    pov_trace=$(sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' "$TMP/pov.stats" | head -1)
    pov_rays=$(awk '/^Rays:/ { r = $2 } /^Shadow Ray Tests:/ { s = $4 } END { printf "%.2f", (r + s) / 1e6 }' "$TMP/pov.stats")
    printf "%-18s %8s %8s %9s %9s %9s %8s\n" "POV-Ray 3.7" "$(wall pov)" "$(cpu pov)" "$pov_trace" "$pov_rays" \
        "$(ratio "$pov_rays" "$pov_trace")" "$(rss pov)"
    echo "wall-time ratio gtrace rgb / POV-Ray: $(ratio "$(wall gt_rgb)" "$(wall pov)") (whole process), \
$(ratio "$(render_s gt_rgb)" "$pov_trace") (render only; target <= 1.0)"
else
    echo "POV-Ray: not installed (Debian package povray); no comparison"
fi
echo "colour models / rgb (render time): spectrum9 $(ratio "$(render_s gt_spectrum9)" "$(render_s gt_rgb)") \
(target <= 2), spectrum $(ratio "$(render_s gt_spectrum)" "$(render_s gt_rgb)") (target <= 6), \
bispectral $(ratio "$(render_s gt_bispectral)" "$(render_s gt_rgb)")"
echo "speed-up from 1 to 2 threads (render time): $(ratio "$(render_s gt_rgb_1)" "$(render_s gt_rgb)") (target >= 1.8)"
# CPU time is steadier than wall time on a shared machine: the same ratios from the processes' CPU seconds,
# gtrace's start-up (loading OpenImageIO's shared libraries, measured with --help) taken out
start=$(cpu gt_start)
net() { awk -v a="$(cpu "$1")" -v s="$start" 'BEGIN { printf "%.3f", a - s }'; }
echo "CPU seconds: start-up $start; net of it rgb $(net gt_rgb), spectrum9 $(net gt_spectrum9), spectrum \
$(net gt_spectrum), bispectral $(net gt_bispectral); ratios to rgb $(ratio "$(net gt_spectrum9)" "$(net gt_rgb)"), \
$(ratio "$(net gt_spectrum)" "$(net gt_rgb)"), $(ratio "$(net gt_bispectral)" "$(net gt_rgb)")"
if command -v povray > /dev/null; then
    echo "CPU seconds, whole process: gtrace rgb $(cpu gt_rgb), POV-Ray $(cpu pov): ratio $(ratio "$(cpu gt_rgb)" "$(cpu pov)")"
fi
