#!/bin/sh
# The main job on a built-in default: renders examples/scenes/demo.scene with gtrace into out/demo.png
# when the tracer is built; otherwise prints the colour report of every colour model.
set -e
BUILD=${1:-build}
mkdir -p out
if [ -x "$BUILD/bin/gtrace" ] && [ -f examples/scenes/demo.scene ]; then
    start=$(date +%s.%N)
    "$BUILD/bin/gtrace" examples/scenes/demo.scene -o out/demo.png
    end=$(date +%s.%N)
    awk -v a="$start" -v b="$end" -v d="$(pwd)" 'BEGIN { printf "demo: wrote %s/out/demo.png in %.1f s\n", d, b - a }'
else
    "$BUILD/bin/gcolor" | tee out/colour-report.txt
    echo "demo: colour report written to $(pwd)/out/colour-report.txt"
fi
