#!/bin/sh
# caustics.sh [BUILD] - the glass ball's caustic (examples/scenes/glass_ball_caustic.scene without its background:
# a ball of index 1.5 and radius 0.5 under a collimated beam, a white floor at the paraxial focus) rendered by
# `gtrace --integrator sppm` and by POV-Ray 3.7's photon mapping on a twin scene (the same camera, floor, ball and
# light: gtrace's irradiance 1 on a floor of reflectance 0.8 is POV-Ray's parallel light of colour 1/pi on a
# pigment of 0.8 with diffuse 1; the glass is POV-Ray's filtering pigment with Fresnel reflection and
# conserve_energy, the photons shot at it by refraction and reflection), W x H (default 97x73: the axis through a
# pixel's centre, where POV-Ray's single ray per pixel samples the focus), 1 thread each.
#
# 1. Convergence: gtrace with PASSES (default 2 4 .. 256) passes of PHOTONS (default 100000) photons, and
#    POV-Ray with POV_COUNTS photons (default 25000 .. 3200000), interleaved (gtrace, POV-Ray, at each effort in
#    turn) for RUNS rounds (default 3). Time is the process's CPU time (user + sys, GNU time; POV-Ray's photon
#    threads included), the median over the rounds, and net of start-up: minus the median CPU time of a run that
#    sends (almost) no photons (gtrace: 1 pass of 1 photon; POV-Ray: 1000 photons). POV-Ray gathers every photon within a radius 0.03 (COUNT / 100000)^(-1/6) (its
#    default, a gather of at most 100 photons, leaves speckles whose error does not fall with the count; a cap
#    below the photons the focus holds would flatten the caustic's peak). Each image's error is its RMSE (gprobe compare: linear
#    radiance over pixels and channels) against a long render by the same program (gtrace REF_PASSES passes,
#    default 2048, on 2 threads; POV-Ray POV_REF photons, default 12800000), so each is measured against what it
#    converges to; the RMSE between the two long renders (what the twins still differ by) is printed, and that of
#    gtrace's long render against LIGHT_PASSES (default 200) passes of `--integrator light` (unbiased on the floor:
#    what SPPM's radius still blurs at the focus). gtrace's long render shares the short runs' first passes (a
#    correlation of weight passes / REF_PASSES, at most 1/8). The exponent of each program is the least-squares
#    slope of log RMSE over log CPU time (SPPM with alpha 2/3 promises -1/3 at best in the limit: its bias and its
#    noise both fall as n^(-1/3)), over the whole
#    image and over two regions of the caustic (gprobe compare --mask; boxes placed from the long gtrace render's
#    brightest pixel, scaled by W / 97): the focus peak (the 3x3 pixels around it) and the smooth halo below it
#    (17x5 pixels from 3 to 7 pixels below the peak, radiance 0.04 to 0.35 against the peak's 15 and the lit
#    floor's 0.27). Each fit is printed with its first and last halves apart (the slope of the smaller and of
#    the larger efforts), to show whether the rate is still changing.
# 2. Time to a given RMSE: TARGET on each program's curve (log-log interpolation between the two efforts that
#    bracket it), and their ratio. TARGET=auto (the default) takes the smallest whole-image RMSE both programs
#    reach (the larger of their smallest, 2% above it), so that both curves bracket it.
# 3. Photons per second per core in every colour model: gtrace at 32x24 (the camera's part negligible) with 2
#    and 20 passes of 100000 photons on 1 thread; the rate is 1800000 photons over the difference of the CPU
#    times (start-up and camera passes cancel), the median over RUNS rounds. Most of this scene's photons meet
#    the floor once and leave: a short path; a closed room's photons bounce more and cost more each.
# A benchmark: it prints figures and never fails on time.
BUILD=${1:-build}
GT="$BUILD/bin/gtrace"
GP="$BUILD/bin/gprobe"
W=${W:-97} H=${H:-73} RUNS=${RUNS:-3}
PHOTONS=${PHOTONS:-100000}
PASSES=${PASSES:-"2 4 8 16 32 64 128 256"}
POV_COUNTS=${POV_COUNTS:-"25000 50000 100000 200000 400000 800000 1600000 3200000"}
REF_PASSES=${REF_PASSES:-2048} POV_REF=${POV_REF:-12800000} LIGHT_PASSES=${LIGHT_PASSES:-200}
TARGET=${TARGET:-auto}
[ -x "$GT" ] || { echo "bench-caustics: $GT is not built"; exit 1; }
[ -x "$GP" ] || { echo "bench-caustics: $GP is not built"; exit 1; }
[ -x /usr/bin/time ] || { echo "bench-caustics: needs GNU time (/usr/bin/time, Debian package time)"; exit 1; }
command -v oiiotool > /dev/null || { echo "bench-caustics: needs oiiotool (openimageio-tools)"; exit 1; }
POV=$(command -v povray)
[ -n "$POV" ] || echo "bench-caustics: povray is not installed (scripts/deps.sh): gtrace's side only"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

cat > "$TMP/ball.scene" <<'SCENE'
colormodel rgb
camera pinhole { from <0, 2.6, 2.6> at <0, 0.2, 0> fov 35 width 320 height 240 spp 1 depth 8 }
object sphere { center <0, 0.75, 0> radius 0.5 material dielectric { index 1.5 } }
object box { min <-1.5, -0.05, -1.5> max <1.5, 0, 1.5> material lambert { reflectance rgb 0.8 0.8 0.8 } }
light directional { direction <0, -1, 0> irradiance rgb 1 1 1 }
SCENE
cat > "$TMP/ball.pov" <<'SCENE'
#version 3.7;
#ifndef (COUNT) #declare COUNT = 100000; #end
#ifndef (RADIUS) #declare RADIUS = 0.03; #end
global_settings { assumed_gamma 1.0 max_trace_level 8
                  photons { count COUNT autostop 0 gather 1, 5000000 radius RADIUS } }
camera { perspective location <0, 2.6, 2.6> look_at <0, 0.2, 0> right x * image_width / image_height
         angle 2 * degrees(atan(tan(radians(17.5)) * image_width / image_height)) }
light_source { <0, 10, 0> color rgb 1 / pi parallel point_at <0, 0, 0> photons { refraction on reflection on } }
sphere { <0, 0.75, 0>, 0.5
         pigment { rgbf 1 } finish { ambient 0 diffuse 0 specular 0 reflection { 0, 1 fresnel on } conserve_energy }
         interior { ior 1.5 } photons { target refraction on reflection on collect off } }
box { <-1.5, -0.05, -1.5>, <1.5, 0, 1.5> pigment { rgb 0.8 } finish { ambient 0 diffuse 1 specular 0 } }
SCENE

cpu() { awk '{ printf "%.3f\n", $1 + $2 }' "$TMP/cpu"; }
# gt PASSES PHOTONS THREADS OUT [MODEL W H]: prints the CPU seconds of one gtrace run
gt() {
    /usr/bin/time -f '%U %S' -o "$TMP/cpu" "$GT" "$TMP/ball.scene" -o "$4" --integrator sppm --passes "$1" \
        --photons "$2" --threads "$3" --colormodel "${5:-rgb}" --width "${6:-$W}" --height "${7:-$H}" -q \
        > /dev/null 2>&1 && cpu
}
# pov COUNT THREADS OUT: prints the CPU seconds of one POV-Ray run; it gathers every photon within a radius of
# 0.03 (COUNT / 100000)^(-1/6), a radius that shrinks as the photons grow so that its estimate converges
pov() {
    g=$(awk -v c="$1" 'BEGIN { printf "%.5f", 0.03 * (c / 100000) ^ (-1 / 6) }')
    ( cd "$TMP" && /usr/bin/time -f '%U %S' -o "$TMP/cpu" "$POV" +Iball.pov +O"$3" +FE +W"$W" +H"$H" -A -D -V -GA \
        +WT"$2" Declare=COUNT="$1" Declare=RADIUS="$g" > /dev/null 2>&1 ) && cpu
}
# rmse IMAGE REFERENCE: the RMSE over the whole image, the focus peak and the smooth halo (three numbers)
rmse() {
    rw=$("$GP" compare "$1" "$2" | awk '$1 == "whole" { print $5 }')
    rp=$("$GP" compare "$1" "$2" --mask "$TMP/peak_mask.exr" | awk '$1 == "shadow" { print $5 }')
    rh=$("$GP" compare "$1" "$2" --mask "$TMP/halo_mask.exr" | awk '$1 == "shadow" { print $5 }')
    echo "$rw $rp $rh"
}
median() { sort -n | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }

echo "glass ball caustic ${W}x${H}, 1 thread; long renders: gtrace $REF_PASSES x $PHOTONS photons, POV-Ray $POV_REF photons"
gt "$REF_PASSES" "$PHOTONS" 2 "$TMP/gt_ref.exr" > /dev/null || { echo "bench-caustics: gtrace failed"; exit 1; }
if [ -n "$POV" ]; then
    pov "$POV_REF" 2 pov_ref.exr > /dev/null || { echo "bench-caustics: povray failed"; POV=; }
fi
# the regions, from the brightest pixel of gtrace's long render
peak=$(oiiotool --dumpdata "$TMP/gt_ref.exr" |
    awk '/Pixel/ { gsub(/[(),:]/, " "); if ($4 > m) { m = $4; x = $2; y = $3 } } END { print x, y }')
set -- $peak
boxes=$(awk -v x="$1" -v y="$2" -v s="$W" 'BEGIN { s /= 97; r = int(s + 0.5); r = r < 1 ? 1 : r
    printf "%d,%d,%d,%d %d,%d,%d,%d", x - r, y - r, x + r, y + r,
           x - int(8 * s + 0.5), y + int(3 * s + 0.5), x + int(8 * s + 0.5), y + int(7 * s + 0.5) }')
set -- $boxes
oiiotool --create "${W}x${H}" 3 --box:color=1,1,1:fill=1 "$1" -o "$TMP/peak_mask.exr"
oiiotool --create "${W}x${H}" 3 --box:color=1,1,1:fill=1 "$2" -o "$TMP/halo_mask.exr"
echo "focus peak at pixel $peak: peak box $1, halo box $2 (x0,y0,x1,y1 inclusive)"
# SPPM's long render is biased (its radius still blurs the focus): against particle tracing to the camera, which is
# unbiased for the floor's caustic (the ball's own pixels differ: `light` does not draw what is seen through glass)
"$GT" "$TMP/ball.scene" -o "$TMP/light_ref.exr" --integrator light --passes "$LIGHT_PASSES" --photons "$PHOTONS" \
    --threads 2 --width "$W" --height "$H" -q > /dev/null 2>&1 &&
    echo "gtrace's long render against $LIGHT_PASSES x $PHOTONS photons of --integrator light (unbiased): RMSE" \
        "(whole, peak, halo) $(rmse "$TMP/gt_ref.exr" "$TMP/light_ref.exr")"
[ -n "$POV" ] && echo "the two long renders differ by RMSE (whole, peak, halo)" \
    "$(rmse "$TMP/gt_ref.exr" "$TMP/pov_ref.exr") (the twins' mismatch)"

: > "$TMP/runs"
r=0
while [ $r -lt "$RUNS" ]; do
    set -- $POV_COUNTS
    t=$(gt 1 1 1 "$TMP/gt.exr") && echo "gtrace-base 0 $t 0 0 0" >> "$TMP/runs"
    [ -n "$POV" ] && t=$(pov 1000 1 pov.exr) && echo "povray-base 0 $t 0 0 0" >> "$TMP/runs"
    for p in $PASSES; do
        t=$(gt "$p" "$PHOTONS" 1 "$TMP/gt.exr") && echo "gtrace $p $t $(rmse "$TMP/gt.exr" "$TMP/gt_ref.exr")" >> "$TMP/runs"
        if [ -n "$POV" ] && [ $# -gt 0 ]; then
            t=$(pov "$1" 1 pov.exr) && echo "povray $1 $t $(rmse "$TMP/pov.exr" "$TMP/pov_ref.exr")" >> "$TMP/runs"
            shift
        fi
    done
    r=$((r + 1))
done
# the median CPU time and RMSEs of each effort: PROGRAM EFFORT CPU RMSE-WHOLE RMSE-PEAK RMSE-HALO, in increasing
# effort
summary() {
    for e in $(awk -v p="$1" '$1 == p { print $2 }' "$TMP/runs" | sort -n -u); do
        line="$1 $e"
        for col in 3 4 5 6; do
            line="$line $(awk -v p="$1" -v e="$e" -v c=$col '$1 == p && $2 == e { print $c }' "$TMP/runs" | median)"
        done
        echo "$line"
    done
}
# net of start-up: minus the median CPU time of a run with (almost) no photons
{ summary gtrace-base; summary gtrace; [ -n "$POV" ] && summary povray-base && summary povray; } |
    awk '$1 ~ /-base$/ { base[substr($1, 1, length($1) - 5)] = $3; next }
         { print $1, $2, $3, $3 - base[$1], $4, $5, $6 }' > "$TMP/sum"
printf '%-8s %16s %8s %8s %10s %10s %10s\n' program effort "CPU s" "net s" "RMSE" "peak" "halo"
awk '{ printf "%-8s %16s %8.3f %8.3f %10.5f %10.5f %10.5f\n", $1, ($1 == "gtrace" ? $2 " passes" : $2 " photons"),
       $3, $4, $5, $6, $7 }' "$TMP/sum"
# slope PROGRAM COLUMN FIRST LAST: the least-squares slope of log RMSE (column) over log net time, efforts FIRST..LAST
slope() {
    awk -v p="$1" -v c="$2" -v a="$3" -v b="$4" '
        $1 == p && $4 > 0 && $c > 0 { k++; if (k >= a && k <= b) { n++; x[n] = log($4); y[n] = log($c) } }
        END {
            for (i = 1; i <= n; i++) { sx += x[i]; sy += y[i] }
            for (i = 1; i <= n; i++) { sxx += (x[i] - sx / n) ^ 2; sxy += (x[i] - sx / n) * (y[i] - sy / n) }
            if (n < 2) printf "-"; else printf "%.3f", (sxx > 0 ? sxy / sxx : 0)
        }' "$TMP/sum"
}
echo "exponents: RMSE ~ (net CPU time)^e, over all efforts [smaller half / larger half]"
printf '%-8s %22s %22s %22s\n' program whole "focus peak" "smooth halo"
for prog in gtrace povray; do
    n=$(awk -v p="$prog" '$1 == p && $4 > 0' "$TMP/sum" | wc -l)
    [ "$n" -ge 2 ] || continue
    h=$(((n + 1) / 2))
    line=$(printf '%-8s' "$prog")
    for col in 5 6 7; do
        fit="$(slope $prog $col 1 "$n") [$(slope $prog $col 1 "$h") / $(slope $prog $col $((n - h + 1)) "$n")]"
        line="$line $(printf '%22s' "$fit")"
    done
    echo "$line" | tee -a "$TMP/slopes"
done
[ -n "$POV" ] && awk '{ g[$1] = $2; p[$1] = $6; s[$1] = $10 } END { if ("gtrace" in g && "povray" in g)
    printf "exponent ratio gtrace / POV-Ray: whole %.2f, focus peak %.2f, smooth halo %.2f\n",
           g["gtrace"] / g["povray"], p["gtrace"] / p["povray"], s["gtrace"] / s["povray"] }' "$TMP/slopes"
if [ "$TARGET" = auto ]; then
    TARGET=$(awk '$4 > 0 && $5 > 0 { if (!($1 in m) || $5 < m[$1]) m[$1] = $5 }
        END { t = 0; for (p in m) if (m[p] > t) t = m[p]; printf "%.6g", (t > 0 ? 1.02 * t : 0.05) }' "$TMP/sum")
fi
for prog in gtrace povray; do
    grep -q "^$prog " "$TMP/sum" || continue
    awk -v p="$prog" -v target="$TARGET" '
        $1 == p && $4 > 0 && $5 > 0 { n++; x[n] = log($4); y[n] = log($5) }
        END {
            for (i = 1; i <= n; i++) { sx += x[i]; sy += y[i] }
            for (i = 1; i <= n; i++) { sxx += (x[i] - sx / n) ^ 2; sxy += (x[i] - sx / n) * (y[i] - sy / n) }
            slope = sxx > 0 ? sxy / sxx : 0
            t = ""
            for (i = 1; i < n; i++)
                if (t == "" && y[i] >= log(target) && y[i + 1] <= log(target) && y[i] > y[i + 1])
                    t = exp(x[i] + (log(target) - y[i]) * (x[i + 1] - x[i]) / (y[i + 1] - y[i]))
            printf "%s: whole image RMSE ~ (net CPU time)^%.3f; net time to RMSE %s: %s\n", p, slope, target,
                   (t == "" ? "not bracketed" : sprintf("%.3f s", t))
            print p, (t == "" ? "-" : t) > "'"$TMP/ttr"'"
        }' "$TMP/sum"
    cat "$TMP/ttr" >> "$TMP/times"
done
[ -n "$POV" ] && awk '{ t[$1] = $2 } END { if (t["gtrace"] != "-" && t["povray"] != "-" && t["povray"] > 0)
    printf "time to RMSE: gtrace / POV-Ray = %.2f\n", t["gtrace"] / t["povray"] }' "$TMP/times"

echo
echo "photons per second per core (32x24, passes 20 - 2 of 100000, 1 thread, median of $RUNS rounds)"
: > "$TMP/rates"
r=0
while [ $r -lt "$RUNS" ]; do
    for model in rgb spectrum9 spectrum bispectral; do
        a=$(gt 2 100000 1 "$TMP/p.exr" "$model" 32 24) && b=$(gt 20 100000 1 "$TMP/p.exr" "$model" 32 24) &&
            awk -v m="$model" -v a="$a" -v b="$b" 'BEGIN { if (b > a) print m, 1800000 / (b - a) }' >> "$TMP/rates"
    done
    r=$((r + 1))
done
for model in rgb spectrum9 spectrum bispectral; do
    v=$(awk -v m="$model" '$1 == m { print $2 }' "$TMP/rates" | median)
    printf '%-11s %12.0f photons/s\n' "$model" "${v:-0}"
done
