#!/bin/sh
# media_equiangular.sh [BUILD] - equiangular sampling towards point and spot lights in media against free flight
# alone (gtrace --equiangular on|off), in the path tracer: noise at equal time on the fog scenes, per colour model.
#
# Scenes: examples/scenes/media_fog.scene (a spot light in fog, its lamp in a clear bubble) and the same without the
# bubble (the lamp in the fog: scattering right next to it). Noise: the mean per-pixel variance, the square of the
# RMSE (gprobe compare: linear radiance, over pixels and the three channels) of a short render against a long one
# (REF spp, equiangular on, 2 threads; both estimators converge to it). Time: the process's CPU time on 1 thread
# (GNU time, user + sys) at SPP samples less the same at 1 sample (the loading), the shorter of two runs. Variance at
# equal time is variance x time; the ratio printed is free flight's over equiangular's (above 1: equiangular
# sampling reaches the same noise in that much less time).
# A benchmark: it prints figures and never fails on them.
BUILD=${1:-build}
GT="$BUILD/bin/gtrace"
GP="$BUILD/bin/gprobe"
SRC=$(cd "$(dirname "$0")/.." && pwd)
[ -x "$GT" ] || { echo "bench-media-equiangular: $GT is not built"; exit 1; }
[ -x "$GP" ] || { echo "bench-media-equiangular: $GP is not built"; exit 1; }
[ -x /usr/bin/time ] || { echo "bench-media-equiangular: needs GNU time (/usr/bin/time, Debian package time)"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
W=${W:-64} H=${H:-48} SPP=${SPP:-32} REF=${REF:-512}
cp "$SRC/examples/scenes/media_fog.scene" "$TMP/fog.scene"
grep -v 'material clear' "$SRC/examples/scenes/media_fog.scene" > "$TMP/lamp.scene"
# cpu SCENE MODEL SPP EQUIANGULAR OUT: the process's CPU seconds on 1 thread
cpu() {
    /usr/bin/time -f '%U %S' -o "$TMP/cpu" "$GT" "$TMP/$1.scene" -o "$5" --colormodel "$2" --spp "$3" \
        --equiangular "$4" --width "$W" --height "$H" --integrator path --threads 1 -q > /dev/null 2>&1 &&
        awk '{ printf "%.3f\n", $1 + $2 }' "$TMP/cpu"
}
best() { # the shorter of two runs
    a=$(cpu "$@") && b=$(cpu "$@") && awk -v a="$a" -v b="$b" 'BEGIN { print (a < b ? a : b) }'
}
rmse() { "$GP" compare "$1" "$2" | awk '$1 == "whole" { print $5 }'; }
echo "fog with a spot light, path integrator, ${W}x${H}, $SPP spp against $REF spp, CPU time on 1 thread;"
echo "variance = RMSE^2; fog: media_fog.scene (lamp in a clear bubble), lamp: the same with the lamp in the fog"
printf '%-11s %-5s %-4s %9s %11s %13s\n' model scene equi "s" "variance" "variance x s"
for model in rgb spectrum9 spectrum bispectral; do
    for s in fog lamp; do
        "$GT" "$TMP/$s.scene" -o "$TMP/ref.exr" --colormodel "$model" --spp "$REF" --width "$W" --height "$H" \
            --integrator path --threads 2 -q > /dev/null 2>&1 || { echo "$model $s: the reference failed"; continue; }
        for e in on off; do
            if t1=$(best "$s" "$model" 1 "$e" "$TMP/one.exr") &&
                tn=$(best "$s" "$model" "$SPP" "$e" "$TMP/short.exr") &&
                err=$(rmse "$TMP/short.exr" "$TMP/ref.exr"); then
                awk -v m="$model" -v s="$s" -v e="$e" -v t1="$t1" -v tn="$tn" -v r="$err" 'BEGIN {
                    t = tn - t1; if (t < 0.001) t = 0.001
                    printf "%-11s %-5s %-4s %9.3f %11.4e %13.4e\n", m, s, e, t, r * r, r * r * t }' | tee -a "$TMP/rows"
            else
                echo "$model $s $e: failed"
            fi
        done
    done
done
echo
echo "variance at equal time, free flight over equiangular"
printf '%-11s %8s %8s\n' model fog lamp
for model in rgb spectrum9 spectrum bispectral; do
    awk -v m="$model" '$1 == m { v[$2 " " $3] = $6 }
        END { printf "%-11s", m
              n = split("fog lamp", s, " ")
              for (i = 1; i <= n; i++) {
                  on = v[s[i] " on"]; off = v[s[i] " off"]
                  if (on > 0 && off > 0) printf " %8.3f", off / on; else printf " %8s", "failed"
              }
              printf "\n" }' "$TMP/rows"
done
