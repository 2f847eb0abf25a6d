#!/bin/sh
# bench.sh [BUILD] - gtrace against POV-Ray 3.7 on the same picture (scene.scene / scene.pov: checker floor,
# glass, mirror, wood, marble, two point lights; 800x600, 1 sample per pixel, depth 8), by the procedure of
# bench/README.md:
#   1. idle check: waits up to IDLE_WAIT seconds (default 30) for the 1-minute load average to fall below
#      IDLE_LOAD (default 0.5); says so in the report when it did not (the figures are then of a busy machine);
#   2. RUNS rounds (default 5; RUNS=1 for a quick look), each running every configuration once, interleaved
#      (gtrace rgb, POV-Ray, the other colour models, 1 thread each, start-up), so that a change of load hits
#      both sides alike; rgb and the other colour models MODEL_REPS times a round (default 3: a 70 ms render's
#      jitter is a few per cent, as large as the margins the models' ratios are judged by);
#   3. each ratio is computed within a round and the median over the rounds is reported; the table shows the
#      best (least CPU) run of each configuration.
# Also: peak RSS of each side, and the mean absolute difference per channel between the two pictures (of 255).
# Two generated scenes (gen.sh, written into BUILD/bench/pov, never committed) run in the same rounds, 2 threads:
# a grid of 10,000 spheres and a 1M-triangle mesh (OBJ for gtrace, mesh2 for POV-Ray), each with CPU, wall,
# render and peak-RSS ratios; and the load check: 200,000 named spheres (naming 1,000 materials) parsed and
# built (1x1 render), target <= 2 s. Then the intersection-only limit (isect_limit.c): the Whitted render's own rays
# cast again without shading, its time per ray against the render's (target <= 1.5).
# A benchmark: it prints figures and never fails on time.
BUILD=${1:-build}
RUNS=${RUNS:-5}
MODEL_REPS=${MODEL_REPS:-3}
IDLE_WAIT=${IDLE_WAIT:-30}
IDLE_LOAD=${IDLE_LOAD:-0.5}
DIR=$(cd "$(dirname "$0")" && pwd)
GT="$BUILD/bin/gtrace"
if [ ! -x "$GT" ]; then
    echo "bench-pov: $GT is not built (make BUILD=$BUILD)"
    exit 1
fi
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
# runstat (bench/pov/runstat.c): wall, user and system seconds to the microsecond and the peak RSS of a command
RUNSTAT="$BUILD/bench/runstat"
if [ ! -x "$RUNSTAT" ]; then
    echo "bench-pov: $RUNSTAT is not built (make bench-pov builds it)"
    exit 1
fi
HAVE_POV=0
command -v povray > /dev/null && HAVE_POV=1
GEN="$BUILD/bench/pov"
"$DIR/gen.sh" "$GEN" || exit 1
GEN=$(cd "$GEN" && pwd)

# ---- 1. idle check ----
load1() { cut -d' ' -f1 /proc/loadavg; }
waited=0
while awk -v l="$(load1)" -v m="$IDLE_LOAD" 'BEGIN { exit !(l >= m) }' && [ "$waited" -lt "$IDLE_WAIT" ]; do
    sleep 5
    waited=$((waited + 5))
done
load_start=$(cut -d' ' -f1-3 /proc/loadavg)
if awk -v l="$(load1)" -v m="$IDLE_LOAD" 'BEGIN { exit !(l >= m) }'; then
    idle="NOT IDLE (load average $load_start after waiting ${waited} s; ratios within a round still compare like with like)"
else
    idle="idle (load average $load_start)"
fi

# ---- 2. interleaved rounds ----
# once NAME CMD...: one run; appends "wall cpu rss_kib" to TMP/NAME.runs, keeps the output of the least-CPU run
once() {
    name=$1
    shift
    "$RUNSTAT" "$TMP/$name.t" "$@" > "$TMP/$name.o" 2>&1 || {
        echo "bench-pov: $name failed:"
        cat "$TMP/$name.o"
        exit 1
    }
    line=$(awk '{ printf "%.3f %.3f %s", $1, $2 + $3, $4 }' "$TMP/$name.t")
    echo "$line" >> "$TMP/$name.runs"
    cpu=$(echo "$line" | cut -d' ' -f2)
    if [ ! -f "$TMP/$name.best" ] || awk -v a="$cpu" -v b="$(cut -d' ' -f2 "$TMP/$name.best")" 'BEGIN { exit !(a < b) }'; then
        echo "$line" > "$TMP/$name.best"
        cp "$TMP/$name.o" "$TMP/$name.out"
    fi
    cp "$TMP/$name.o" "$TMP/$name.last"
}
# last NAME FIELD: a field (1 wall, 2 CPU, 3 peak RSS) of NAME's last run
last() { tail -n 1 "$TMP/$1.runs" | cut -d' ' -f"$2"; }
# gtrace's render time (its summary line) and POV-Ray's trace time and trace CPU (its statistics), last run
gt_render() { sed -n 's/.*threads\{0,1\}: \([0-9.]*\) s,.*/\1/p' "$TMP/$1.$2"; }
pov_trace() { sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' "$TMP/$1.$2" | head -1; }
pov_trace_cpu() { awk '/Trace Time:/ { t = 1; next } t && /CPU-seconds/ { for (i = 1; i <= NF; i++) if ($i == "with") { print $(i + 1); exit } }' "$TMP/$1.$2"; }
field() { cut -d' ' -f"$2" "$TMP/$1.best"; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%.3f", a / b; else print "n/a" }'; }
# note KEY VALUE: a per-round figure (one line per round in TMP/KEY.r)
note() { echo "$2" >> "$TMP/$1.r"; }
median() { [ -f "$TMP/$1.r" ] && sort -g "$TMP/$1.r" | awk '{ v[NR] = $1 } END { if (NR % 2) printf "%.2f", v[(NR + 1) / 2]; else printf "%.2f", (v[NR / 2] + v[NR / 2 + 1]) / 2 }' || echo "n/a"; }
# spread KEY: the median with the least and the greatest of the rounds, "median (min-max)"
spread() { [ -f "$TMP/$1.r" ] && echo "$(median "$1") ($(sort -g "$TMP/$1.r" | awk 'NR == 1 { a = $1 } { b = $1 } END { printf "%.2f-%.2f", a, b }'))" || echo "n/a"; }

# absdiff A B: the mean absolute difference per channel of TMP/A.png and TMP/B.png, in 8-bit units
absdiff() {
    oiiotool "$TMP/$1.png" "$TMP/$2.png" --absdiff --printstats 2>&1 |
        sed -n 's/.*Stats Avg: *\([0-9. ]*\)(float).*/\1/p' | awk '{ printf "%.1f %.1f %.1f", $1 * 255, $2 * 255, $3 * 255 }'
}

POV_ARGS="+W800 +H600 -A -D +FN File_Gamma=sRGB"
r=0
while [ $r -lt "$RUNS" ]; do
    # the colour models against rgb MODEL_REPS times a round, each model's ratio against the rgb run just before
    rep=0
    while [ $rep -lt "$MODEL_REPS" ]; do
        once gt_rgb "$GT" "$DIR/scene.scene" -o "$TMP/gt_rgb.png" --threads 2 --colormodel rgb
        if [ $rep -eq 0 ] && [ $HAVE_POV -eq 1 ]; then
            # shellcheck disable=SC2086
            once pov povray "+I$DIR/scene.pov" "+O$TMP/pov.png" $POV_ARGS +WT2
        fi
        for m in spectrum9 spectrum bispectral; do
            once "gt_$m" "$GT" "$DIR/scene.scene" -o "$TMP/gt_$m.png" --threads 2 --colormodel $m
            note "render_$m" "$(ratio "$(gt_render "gt_$m" last)" "$(gt_render gt_rgb last)")"
            note "cpu_$m" "$(ratio "$(last "gt_$m" 2)" "$(last gt_rgb 2)")"
        done
        rep=$((rep + 1))
    done
    once gt_rgb_1 "$GT" "$DIR/scene.scene" -o "$TMP/gt_rgb_1.png" --threads 1 --colormodel rgb
    if [ $HAVE_POV -eq 1 ]; then
        # shellcheck disable=SC2086
        once pov_1 povray "+I$DIR/scene.pov" "+O$TMP/pov_1.png" $POV_ARGS +WT1
    fi
    for g in spheres mesh; do
        once "gt_$g" "$GT" "$GEN/$g.scene" -o "$TMP/gt_$g.png" --threads 2
        if [ $HAVE_POV -eq 1 ]; then
            # shellcheck disable=SC2086
            once "pov_$g" povray "+I$GEN/$g.pov" "+L$GEN" "+O$TMP/pov_$g.png" $POV_ARGS +WT2
        fi
    done
    once gt_load "$GT" "$GEN/load.scene" -o "$TMP/gt_load.png" --threads 2
    # thread scaling on a render long enough (1600x1200, about 1 s) that start-up and output do not count
    once gt_big_1 "$GT" "$DIR/scene.scene" -o "$TMP/gt_big_1.png" --threads 1 --width 1600 --height 1200
    once gt_big_2 "$GT" "$DIR/scene.scene" -o "$TMP/gt_big_2.png" --threads 2 --width 1600 --height 1200
    once gt_start "$GT" --help
    # this round's ratios
    st=$(last gt_start 2)
    note threads "$(ratio "$(gt_render gt_rgb_1 last)" "$(gt_render gt_rgb last)")"
    note threads_big "$(ratio "$(gt_render gt_big_1 last)" "$(gt_render gt_big_2 last)")"
    if [ $HAVE_POV -eq 1 ]; then
        note cpu_pov "$(ratio "$(last gt_rgb 2)" "$(last pov 2)")"
        note cpu_pov_1 "$(ratio "$(last gt_rgb_1 2)" "$(last pov_1 2)")"
        note wall_pov "$(ratio "$(last gt_rgb 1)" "$(last pov 1)")"
        note render_pov "$(ratio "$(gt_render gt_rgb last)" "$(pov_trace pov last)")"
        note render_pov_1 "$(ratio "$(gt_render gt_rgb_1 last)" "$(pov_trace pov_1 last)")"
        note net_cpu_pov_1 "$(ratio "$(awk -v a="$(last gt_rgb_1 2)" -v s="$st" 'BEGIN { print a - s }')" "$(pov_trace_cpu pov_1 last)")"
        note rss_pov "$(ratio "$(last gt_rgb 3)" "$(last pov 3)")"
        for g in spheres mesh; do
            note "cpu_pov_$g" "$(ratio "$(last "gt_$g" 2)" "$(last "pov_$g" 2)")"
            note "wall_pov_$g" "$(ratio "$(last "gt_$g" 1)" "$(last "pov_$g" 1)")"
            note "render_pov_$g" "$(ratio "$(gt_render "gt_$g" last)" "$(pov_trace "pov_$g" last)")"
            note "rss_pov_$g" "$(ratio "$(last "gt_$g" 3)" "$(last "pov_$g" 3)")"
        done
    fi
    r=$((r + 1))
done

# ---- the intersection-only limit (isect_limit.c): the render's own rays cast again with no shading, 1 thread,
# RUNS interleaved rounds of its own, through the direct list gtrace takes for this scene and through Embree ----
LIMIT="$BUILD/bench/isect_limit"
if [ -x "$LIMIT" ]; then
    "$LIMIT" "$DIR/scene.scene" --rounds "$RUNS" > "$TMP/limit.out" 2>&1 &&
        "$LIMIT" "$DIR/scene.scene" --rounds "$RUNS" --embree > "$TMP/limit_embree.out" 2>&1 ||
        echo "bench-pov: isect_limit failed: $(cat "$TMP/limit.out" "$TMP/limit_embree.out" 2> /dev/null)"
fi

# ---- 3. report ----
echo "== gtrace vs POV-Ray: $(nproc) processors, $idle; $RUNS interleaved rounds (bench/README.md)"
printf "%-20s %8s %8s %9s %8s\n" "least-CPU run" "wall s" "cpu s" "render s" "peak MB"
for n in gt_rgb gt_spectrum9 gt_spectrum gt_bispectral gt_rgb_1 gt_big_1 gt_big_2 gt_spheres gt_mesh gt_load gt_start; do
    printf "%-20s %8s %8s %9s %8.1f\n" "$n" "$(field $n 1)" "$(field $n 2)" "$(gt_render $n out)" "$(awk -v k="$(field $n 3)" 'BEGIN { print k / 1024 }')"
done
if [ $HAVE_POV -eq 1 ]; then
    for n in pov pov_1 pov_spheres pov_mesh; do
        printf "%-20s %8s %8s %9s %8.1f\n" "$n" "$(field $n 1)" "$(field $n 2)" "$(pov_trace $n out)" "$(awk -v k="$(field $n 3)" 'BEGIN { print k / 1024 }')"
    done
    echo "medians of the per-round ratios gtrace rgb / POV-Ray:"
    echo "  whole-process CPU: 2 threads $(spread cpu_pov), 1 thread $(spread cpu_pov_1) (target <= 0.35)"
    echo "  render only: wall 2 threads $(median render_pov), 1 thread $(median render_pov_1); CPU 1 thread net of start-up $(spread net_cpu_pov_1) (target <= 0.6)"
    echo "  whole-process wall (2 threads): $(median wall_pov); peak RSS: $(spread rss_pov) (target <= 0.6)"
    if command -v oiiotool > /dev/null; then
        d=$(absdiff gt_rgb pov)
        means=$(for f in gt_rgb pov; do oiiotool "$TMP/$f.png" --printstats 2>&1 |
            sed -n 's/.*Stats Avg: *\([0-9. ]*\)(of 255).*/\1/p' | awk '{ printf "%.0f", ($1 + $2 + $3) / 3 }'; echo; done | paste -sd' ' -)
        echo "  the two pictures: mean absolute difference per channel (R G B) $d of 255 (target < 6); mean value gtrace, POV-Ray: $means of 255"
    fi
    for g in spheres mesh; do
        case $g in spheres) what="10,000 spheres" ;; *) what="1M-triangle mesh" ;; esac
        echo "$what, medians of gtrace / POV-Ray (2 threads): whole-process CPU $(median "cpu_pov_$g"), wall $(median "wall_pov_$g"), render $(median "render_pov_$g"), peak RSS $(median "rss_pov_$g")"
        if command -v oiiotool > /dev/null; then
            echo "  the two pictures: mean absolute difference per channel (R G B) $(absdiff "gt_$g" "pov_$g") of 255"
        fi
    done
else
    echo "POV-Ray: not installed (Debian package povray); no comparison"
fi
echo "colour models / rgb, medians: render time spectrum9 $(median render_spectrum9), spectrum $(median render_spectrum), \
bispectral $(median render_bispectral); process CPU spectrum9 $(median cpu_spectrum9), spectrum $(median cpu_spectrum), \
bispectral $(median cpu_bispectral) (targets 1.02, 1.05, 1.05)"
# limit_line OUT: "ns per ray render, limit; ratio median (min-max)" from isect_limit's report
limit_line() {
    sed -n 's/.*Whitted render \([0-9.]*\), intersection only \([0-9.]*\); .*median of the rounds \([0-9.]*\) (min-max \([0-9.-]*\)).*/\1 ns against \2 ns a ray: \3x (\4)/p' "$TMP/$1.out"
}
if [ -s "$TMP/limit.out" ] && [ -s "$TMP/limit_embree.out" ]; then
    # gtrace's own 1-thread run above (its least-CPU run): process CPU less start-up, and render wall time, per ray
    gt_ns=$(awk -v c="$(field gt_rgb_1 2)" -v s="$(field gt_start 2)" -v t="$(gt_render gt_rgb_1 out)" \
        -v r="$(sed -n 's/.* \([0-9.]*\) M rays,.*/\1/p' "$TMP/gt_rgb_1.out")" \
        'BEGIN { if (r > 0) printf "%.0f ns of process CPU less start-up (parsing and PNG included), %.0f ns of render wall time", 1e3 * (c - s) / r, 1e3 * t / r; else print "n/a" }')
    echo "time per ray against the intersection-only limit (bench/pov/isect_limit, the render's own $(sed -n 's/.*thread: \([0-9]*\) rays.*/\1/p' "$TMP/limit.out") rays cast again without shading, 1 thread, CPU, median of $RUNS rounds; target <= 1.5):"
    echo "  direct list (gtrace's way for this scene): $(limit_line limit); through Embree: $(limit_line limit_embree)"
    echo "  gtrace rgb 1 thread above, a ray: $gt_ns"
    if [ $HAVE_POV -eq 1 ]; then
        # POV-Ray's own rays (camera, reflected, refracted: "Rays") and shadow rays ("Shadow Ray Tests") of its
        # least-CPU 1-thread run, against its trace CPU: where the peer stands against the same limit
        pov_rays=$(awk '/^Rays:/ { r = $2 } /^Shadow Ray Tests:/ { s = $4 } END { print r + s }' "$TMP/pov_1.out")
        echo "  POV-Ray 1 thread, a ray: $(awk -v c="$(pov_trace_cpu pov_1 out)" -v r="$pov_rays" \
            -v l="$(sed -n 's/.*intersection only \([0-9.]*\);.*/\1/p' "$TMP/limit.out")" \
            'BEGIN { if (r > 0 && l > 0) printf "%.0f ns of trace CPU (%d rays and shadow rays), %.1fx the direct-list limit", 1e9 * c / r, r, 1e9 * c / r / l; else print "n/a" }')"
    fi
fi
echo "speed-up from 1 to 2 threads (render time, median): $(median threads) at 800x600, $(median threads_big) at 1600x1200 (target >= 1.9 on an idle machine)"
echo "load check (200,000 named spheres, 1,000 materials; parse and build, 1x1 render; least-CPU run): $(field gt_load 2) s CPU, $(field gt_load 1) s wall, $(awk -v k="$(field gt_load 3)" 'BEGIN { printf "%.0f", k / 1024 }') MB (target <= 2 s)"
echo "start-up (gtrace --help, least CPU): $(field gt_start 2) s CPU, $(awk -v k="$(field gt_start 3)" 'BEGIN { printf "%.1f", k / 1024 }') MB (make bench runs bench_startup for the details)"
