#!/bin/sh
# media_noise.sh [BUILD] - the noise of a chromatic medium at equal time against single-wavelength baselines, per
# colour model, in gtrace's path tracer.
#
# The scene: a scattering sphere (radius 0.5, albedo 0.8, Henyey-Greenstein g 0.3) under a white sky and a white
# directional light, as in tests/test_gtrace_media_chroma.c. Chromatic: sigma_t = rgb 2 6 9 (in the spectral models
# the model's uplift of that triple). The baselines are grey: sigma_t the same in every band, 2, 6 or 9 (one band's
# value everywhere), whose free-flight sampling has no other band to weigh against.
# Noise: the mean per-pixel variance, the square of the RMSE (gprobe compare: linear radiance, over pixels and the
# three channels) of a short render against a long one of the same scene and model (REF spp, 2 threads; its own
# noise adds a factor 1 + SPP / REF to the variance, the same for every figure). Time: the process's CPU time on 1
# thread (GNU time, user + sys) at SPP samples less the same at 1 sample (the loading), the shorter of two runs.
# Variance at equal time is variance x time (the variance falls as 1 / samples, the time grows with them), and the
# ratios printed are the chromatic sphere's over each grey one's: above 1, the chromatic medium costs that many
# times the time of the grey one for the same noise.
# A benchmark: it prints figures and never fails on them.
BUILD=${1:-build}
GT="$BUILD/bin/gtrace"
GP="$BUILD/bin/gprobe"
[ -x "$GT" ] || { echo "bench-media-noise: $GT is not built"; exit 1; }
[ -x "$GP" ] || { echo "bench-media-noise: $GP is not built"; exit 1; }
[ -x /usr/bin/time ] || { echo "bench-media-noise: needs GNU time (/usr/bin/time, Debian package time)"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
W=${W:-48} SPP=${SPP:-256} REF=${REF:-2048}
scene() { # NAME R G B: the sphere with sigma_t = (R, G, B), albedo 0.8 (sigma_s = 4 sigma_a, scale 0.2)
    s4=$(awk -v r="$2" -v g="$3" -v b="$4" 'BEGIN { print 4 * r, 4 * g, 4 * b }')
    cat > "$TMP/$1.scene" << END
medium haze homogeneous { sigma_a rgb $2 $3 $4 sigma_s rgb $s4 scale 0.2 phase hg { g 0.3 } }
object sphere { radius 0.5 material dielectric { index 1 } interior haze }
light background { color rgb 1 1 1 }
light directional { direction <0.3, -1, -0.2> irradiance rgb 2 2 2 }
camera pinhole { from <0, 0, 4> at <0, 0, 0> fov 15 width $W height $W spp 1 depth 64 }
END
}
scene chroma 2 6 9
scene grey2 2 2 2
scene grey6 6 6 6
scene grey9 9 9 9
# cpu SCENE MODEL SPP OUT: the process's CPU seconds on 1 thread
cpu() {
    /usr/bin/time -f '%U %S' -o "$TMP/cpu" "$GT" "$TMP/$1.scene" -o "$4" --colormodel "$2" --spp "$3" \
        --integrator path --threads 1 -q > /dev/null 2>&1 && awk '{ printf "%.3f\n", $1 + $2 }' "$TMP/cpu"
}
best() { # SCENE MODEL SPP OUT: the shorter of two runs
    a=$(cpu "$@") && b=$(cpu "$@") && awk -v a="$a" -v b="$b" 'BEGIN { print (a < b ? a : b) }'
}
rmse() { "$GP" compare "$1" "$2" | awk '$1 == "whole" { print $5 }'; }
echo "chromatic sphere sigma_t (2, 6, 9) against grey ones, path integrator, ${W}x${W}, $SPP spp against $REF spp,"
echo "CPU time on 1 thread; variance = RMSE^2; at equal time: variance x time, chromatic over grey"
printf '%-11s %-7s %9s %11s %13s\n' model scene "s" "variance" "variance x s"
for model in rgb spectrum9 spectrum bispectral; do
    for s in chroma grey2 grey6 grey9; do
        "$GT" "$TMP/$s.scene" -o "$TMP/ref.exr" --colormodel "$model" --spp "$REF" --integrator path --threads 2 -q \
            > /dev/null 2>&1 || { echo "$model $s: the reference failed"; continue; }
        t1=$(best "$s" "$model" 1 "$TMP/one.exr") && tn=$(best "$s" "$model" "$SPP" "$TMP/short.exr") &&
            e=$(rmse "$TMP/short.exr" "$TMP/ref.exr") || { echo "$model $s: failed"; continue; }
        awk -v m="$model" -v s="$s" -v t1="$t1" -v tn="$tn" -v e="$e" 'BEGIN {
            t = tn - t1; if (t < 0.001) t = 0.001
            printf "%-11s %-7s %9.3f %11.4e %13.4e\n", m, s, t, e * e, e * e * t }' | tee -a "$TMP/rows"
    done
done
echo
echo "variance at equal time, chromatic over grey"
printf '%-11s %10s %10s %10s\n' model "grey 2" "grey 6" "grey 9"
for model in rgb spectrum9 spectrum bispectral; do
    awk -v m="$model" '$1 == m { v[$2] = $5 }
        END { if (!("chroma" in v)) { printf "%-11s failed\n", m; exit }
              printf "%-11s", m
              n = split("grey2 grey6 grey9", g, " ")
              for (i = 1; i <= n; i++) printf " %10.3f", (g[i] in v && v[g[i]] > 0) ? v["chroma"] / v[g[i]] : 0
              printf "\n" }' "$TMP/rows"
done
