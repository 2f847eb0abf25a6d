#!/bin/sh
# path.sh [BUILD] - what path tracing costs against the Whitted tracer: examples/scenes/demo.scene at 160x120,
# 4 samples per pixel, depth 8, 1 thread, in every colour model, with `--integrator whitted` and
# `--integrator path`. Prints the render time, camera samples per second and rays per second (from gtrace's
# summary line). A benchmark: it prints figures and never fails on time.
BUILD=${1:-build}
GT="$BUILD/bin/gtrace"
SCENE=$(dirname "$0")/../examples/scenes/demo.scene
W=160 H=120 SPP=4
[ -x "$GT" ] || { echo "bench-path: $GT is not built"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
# render seconds and M rays of one run
run() { # MODEL INTEGRATOR
    "$GT" "$SCENE" -o "$TMP/out.exr" --width $W --height $H --spp $SPP --depth 8 --colormodel "$1" \
        --integrator "$2" --threads 1 2>&1 |
        awk '/^gtrace: .* rays/ { for (i = 1; i <= NF; i++) { if ($i == "s,") t = $(i - 1); if ($i == "M" && $(i + 1) == "rays,") r = $(i - 1) } }
             END { if (t == "") exit 1; print t, r }'
}
echo "demo.scene ${W}x${H}, $SPP spp, depth 8, 1 thread"
printf '%-11s %-8s %8s %12s %10s\n' model integr. "s" "samples/s" "Mrays/s"
for model in rgb spectrum9 spectrum bispectral; do
    for integ in whitted path; do
        out=$(run "$model" "$integ") || { printf '%-11s %-8s %8s\n' "$model" "$integ" "failed"; continue; }
        set -- $out
        echo "$model $integ $1 $2" | awk -v n=$((W * H * SPP)) '{ printf "%-11s %-8s %8.2f %12.0f %10.3f\n", $1, $2, $3, ($3 > 0 ? n / $3 : 0), ($3 > 0 ? $4 / $3 : 0) }'
    done
done
