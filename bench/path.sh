#!/bin/sh
# path.sh [BUILD] - what path tracing costs against the Whitted tracer, and how noisy each is at equal time.
#
# 1. Speed: examples/scenes/demo.scene at 160x120, 4 samples per pixel, depth 8, 1 thread, in every colour
#    model, with `--integrator whitted` and `--integrator path`: render time, camera samples per second and
#    rays per second (from gtrace's summary line), of the fastest of RUNS rounds (default 3) that run every
#    configuration once in turn (a render takes 0.07-0.3 s, whose jitter on a shared machine is several per cent).
# 2. Noise at equal time: demo.scene at 96x72, depth 8, 1 thread. Time is the process's CPU time (user + sys,
#    GNU time; loading included), which other users of a shared machine disturb far less than wall time; the
#    shorter of two runs. Whitted renders 16 spp in CPU time T; the path tracer's fixed cost is its time at 1
#    spp and its time per sample the difference to 16 spp, and it renders the spp that fit in T (its own time
#    is printed beside). Each image's noise is
#    its RMSE (gprobe compare: linear radiance, over pixels and the three channels) against a long render of
#    the same integrator (Whitted 256 spp, path 1024 spp, 2 threads), so each is measured against what it
#    converges to; the last column is the RMSE between the two long renders, what Whitted leaves out (the
#    indirect light). The long renders' own noise is in the figures (a factor sqrt(1 + n / n_long) at most,
#    1.03 for Whitted, under 1.05 for path) and they share their first n samples' random streams with the
#    short ones (a correlation of weight n / n_long).
# A benchmark: it prints figures and never fails on time.
BUILD=${1:-build}
GT="$BUILD/bin/gtrace"
GP="$BUILD/bin/gprobe"
SCENE=$(dirname "$0")/../examples/scenes/demo.scene
W=160 H=120 SPP=4
[ -x "$GT" ] || { echo "bench-path: $GT is not built"; exit 1; }
[ -x "$GP" ] || { echo "bench-path: $GP is not built"; exit 1; }
[ -x /usr/bin/time ] || { echo "bench-path: needs GNU time (/usr/bin/time, Debian package time)"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
RUNS=${RUNS:-3}
# render seconds and M rays of one run
run() { # MODEL INTEGRATOR
    "$GT" "$SCENE" -o "$TMP/out.exr" --width $W --height $H --spp $SPP --depth 8 --colormodel "$1" \
        --integrator "$2" --threads 1 2>&1 |
        awk '/^gtrace: .* rays/ { for (i = 1; i <= NF; i++) { if ($i == "s,") t = $(i - 1); if ($i == "M" && $(i + 1) == "rays,") r = $(i - 1) } }
             END { if (t == "") exit 1; print t, r }'
}
echo "demo.scene ${W}x${H}, $SPP spp, depth 8, 1 thread, the fastest of $RUNS rounds"
printf '%-11s %-8s %8s %12s %10s\n' model integr. "s" "samples/s" "Mrays/s"
r=0
while [ $r -lt "$RUNS" ]; do
    for model in rgb spectrum9 spectrum bispectral; do
        for integ in whitted path; do
            out=$(run "$model" "$integ") || out="failed"
            echo "$model $integ $out" >> "$TMP/speed"
        done
    done
    r=$((r + 1))
done
for model in rgb spectrum9 spectrum bispectral; do
    for integ in whitted path; do
        awk -v m="$model" -v g="$integ" -v n=$((W * H * SPP)) '
            $1 == m && $2 == g && $3 != "failed" && (t == "" || $3 < t) { t = $3; r = $4 }
            END { if (t == "") printf "%-11s %-8s %8s\n", m, g, "failed"
                  else printf "%-11s %-8s %8.4f %12.0f %10.3f\n", m, g, t, (t > 0 ? n / t : 0),
                              (t > 0 ? r / t : 0) }' "$TMP/speed"
    done
done

# ---- noise at equal time ----
NW=96 NH=72 SPP_W=16 REF_W=256 REF_P=1024
# render MODEL INTEGRATOR SPP THREADS OUT: prints the process's CPU seconds
render() {
    /usr/bin/time -f '%U %S' -o "$TMP/cpu" "$GT" "$SCENE" -o "$5" --width $NW --height $NH --spp "$3" --depth 8 \
        --colormodel "$1" --integrator "$2" --threads "$4" -q > /dev/null 2>&1 && awk '{ printf "%.2f\n", $1 + $2 }' "$TMP/cpu"
}
# best MODEL INTEGRATOR SPP OUT: the shorter CPU time of two runs on 1 thread
best() {
    a=$(render "$1" "$2" "$3" 1 "$4") && b=$(render "$1" "$2" "$3" 1 "$4") && awk -v a="$a" -v b="$b" 'BEGIN { print (a < b ? a : b) }'
}
rmse() { "$GP" compare "$1" "$2" | awk '$1 == "whole" { print $5 }'; }
echo
echo "noise at equal CPU time: demo.scene ${NW}x${NH}, depth 8, 1 thread; RMSE against Whitted at $REF_W spp and path at $REF_P spp"
printf '%-11s %16s %9s %16s %9s %14s\n' model "Whitted spp (s)" RMSE "path spp (s)" RMSE "Whitted-path"
for model in rgb spectrum9 spectrum bispectral; do
    tw=$(best "$model" whitted $SPP_W "$TMP/w.exr") && t1=$(best "$model" path 1 "$TMP/p.exr") &&
        t16=$(best "$model" path 16 "$TMP/p.exr") &&
        np=$(awk -v a="$tw" -v b="$t1" -v c="$t16" 'BEGIN { n = c > b ? int(1 + 15 * (a - b) / (c - b) + 0.5) : 16; print n < 1 ? 1 : n }') &&
        tp=$(best "$model" path "$np" "$TMP/p.exr") &&
        render "$model" whitted $REF_W 2 "$TMP/wref.exr" > /dev/null && render "$model" path $REF_P 2 "$TMP/pref.exr" > /dev/null ||
        { printf '%-11s %s\n' "$model" failed; continue; }
    printf '%-11s %16s %9.5f %16s %9.5f %14.5f\n' "$model" "$SPP_W ($tw)" "$(rmse "$TMP/w.exr" "$TMP/wref.exr")" \
        "$np ($tp)" "$(rmse "$TMP/p.exr" "$TMP/pref.exr")" "$(rmse "$TMP/wref.exr" "$TMP/pref.exr")"
done
