#!/bin/sh
# model_ratios.sh ROUNDS GTRACE... - each colour model's cost against rgb's, for one or more gtrace binaries side by
# side (a change's before and after): Whitted on bench/pov/scene.scene (800x600, 2 threads) and the path tracer on
# examples/scenes/demo.scene (160x120, 4 spp, depth 8, 1 thread). A round runs, for each binary, integrator and
# model M of spectrum9, spectrum and bispectral, an rgb render and then an M render, and takes the two ratios M / rgb:
# the process's CPU time (user + system, from RUNSTAT, default build/bench/runstat: `make build/bench/runstat`) and
# gtrace's render time (wall). Prints the medians (min-max) over the rounds; the pairs go to $RATIOS_LOG if set.
# A benchmark: it prints figures and never fails on time.
ROUNDS=${1:?usage: model_ratios.sh ROUNDS GTRACE...}
shift
[ $# -ge 1 ] || { echo "usage: model_ratios.sh ROUNDS GTRACE..."; exit 1; }
SRC=$(cd "$(dirname "$0")/.." && pwd)
RUNSTAT=${RUNSTAT:-$SRC/build/bench/runstat}
[ -x "$RUNSTAT" ] || { echo "model_ratios: $RUNSTAT is not built (make build/bench/runstat)"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
# one render: prints "render_seconds cpu_seconds"
one() { # GTRACE MODEL INTEGRATOR
    if [ "$3" = whitted ]; then
        "$RUNSTAT" "$TMP/st" "$1" "$SRC/bench/pov/scene.scene" -o "$TMP/o.png" --threads 2 --colormodel "$2" \
            > "$TMP/log" 2>&1
    else
        "$RUNSTAT" "$TMP/st" "$1" "$SRC/examples/scenes/demo.scene" -o "$TMP/o.exr" --width 160 --height 120 \
            --spp 4 --depth 8 --colormodel "$2" --integrator path --threads 1 > "$TMP/log" 2>&1
    fi
    t=$(awk '/^gtrace: .* rays/ { for (i = 1; i <= NF; i++) if ($i == "s,") print $(i - 1) }' "$TMP/log")
    echo "${t:-0} $(awk '{ print $2 + $3 }' "$TMP/st")"
}
echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
r=0
while [ "$r" -lt "$ROUNDS" ]; do
    b=0
    for gt in "$@"; do
        for integ in whitted path; do
            for m in spectrum9 spectrum bispectral; do
                base=$(one "$gt" rgb $integ)
                x=$(one "$gt" $m $integ)
                echo "$b $integ $m $base $x" |
                    awk '{ printf "%s %s %s %.4f %.4f\n", $1, $2, $3, ($4 > 0 ? $6 / $4 : 0), $7 / $5 }'
            done
        done
        b=$((b + 1))
    done
    r=$((r + 1))
done > "$TMP/pairs"
[ -n "${RATIOS_LOG:-}" ] && cp "$TMP/pairs" "$RATIOS_LOG"
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "model / rgb, medians (min-max) of $ROUNDS rounds; binary 0 is $1"
b=0
for gt in "$@"; do
    for integ in whitted path; do
        for col in 5 4; do
            line=""
            for m in spectrum9 spectrum bispectral; do
                stat=$(awk -v b=$b -v g=$integ -v m=$m -v c=$col '$1 == b && $2 == g && $3 == m { print $c }' \
                    "$TMP/pairs" | sort -g | awk '{ v[NR] = $1 } END {
                        med = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
                        printf "%.3f (%.2f-%.2f)", med, v[1], v[NR] }')
                line="$line  $m $stat"
            done
            printf 'binary %d %-7s %-6s%s\n' $b $integ "$([ $col = 5 ] && echo cpu || echo render)" "$line"
        done
    done
    b=$((b + 1))
done
