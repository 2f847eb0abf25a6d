#!/bin/sh
# materials.sh [BUILD] - `make bench-materials`: path-traced camera samples per second of the material preview (the
# scene of scripts/docs_images.sh's materials.png: a sphere of the material over a checker floor, under a sky and a
# sphere light) per material against lambert's, in every colour model. 96x96, depth 12, the path tracer, 1 thread.
# Time is the process's CPU time (user + sys, GNU time), which other users of a shared machine disturb far less than
# wall time: a render at 33 spp less one at 1 spp, so loading the scene and building its tables cancel out, over the
# 32 x 96 x 96 camera samples between them. Each figure is the fastest of RUNS rounds (default 3), every round running
# every configuration once in turn. A benchmark: it prints figures and never fails on time.
BUILD=${1:-build}
GT="$BUILD/bin/gtrace"
[ -x "$GT" ] || { echo "bench-materials: $GT is not built"; exit 1; }
[ -x /usr/bin/time ] || { echo "bench-materials: needs GNU time (/usr/bin/time, Debian package time)"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
RUNS=${RUNS:-3}
W=96 H=96 SPP=33
# name and material entry, lambert first (the baseline)
cat > "$TMP/materials" << 'EOM'
lambert lambert { reflectance rgb 0.6 0.05 0.04 }
gold conductor { metal Au }
copper-0.3 conductor { metal Cu roughness 0.3 }
silver-brushed conductor { metal Ag roughness_u 0.05 roughness_v 0.3 }
BK7-0.1 dielectric { glass BK7 roughness 0.1 }
plastic-0.2 plastic { reflectance rgb 0.6 0.05 0.04 roughness 0.2 }
varnish-layer layer { top dielectric { index 1.5 } bottom lambert { reflectance rgb 0.1 0.3 0.6 } }
film-320nm thinfilm { thickness 320 index 1.4 base conductor { metal Al } }
thin-glass thindielectric { index 1.5 }
EOM
scene() { # NAME ENTRY...: the preview scene of the material into $TMP/NAME.scene
    name=$1
    shift
    cat > "$TMP/$name.scene" << EOS
material m $*
material ground interpolate { a lambert { reflectance rgb 0.7 0.7 0.68 } b lambert { reflectance rgb 0.15 0.15 0.16 }
    t checker { dims 2 frequency 2 } }
object plane { point <0, -1, 0> normal <0, 1, 0> material ground }
object sphere { center <0, 0, 0> radius 1 material m }
camera pinhole { from <0, 1.2, 4.2> at <0, -0.1, 0> fov 34 width $W height $H spp $SPP depth 12 }
light background { color rgb 0.55 0.6 0.7 }
light sphere { center <-4, 6, 4> radius 1.5 radiance rgb 6 6 6 }
EOS
}
while read -r name entry; do scene "$name" "$entry"; done < "$TMP/materials"
names=$(awk '{ print $1 }' "$TMP/materials")
cpu() { # NAME MODEL SPP: the render's CPU seconds
    /usr/bin/time -f '%U %S' -o "$TMP/time" "$GT" "$TMP/$1.scene" -o "$TMP/out.exr" --colormodel "$2" \
        --integrator path --threads 1 --spp "$3" -q > /dev/null 2>&1 || return 1
    awk '{ print $1 + $2 }' "$TMP/time"
}
render() { # NAME MODEL: CPU seconds of SPP - 1 samples per pixel
    a=$(cpu "$1" "$2" "$SPP") && b=$(cpu "$1" "$2" 1) && echo "$a $b" | awk '{ print $1 - $2 }'
}
r=0
while [ $r -lt "$RUNS" ]; do
    for model in rgb spectrum9 spectrum bispectral; do
        for name in $names; do
            t=$(render "$name" "$model") || t=failed
            echo "$model $name $t" >> "$TMP/times"
        done
    done
    r=$((r + 1))
done
echo "material preview ${W}x${H}, depth 12, path tracer, 1 thread: camera samples per CPU second" \
    "($SPP spp less 1 spp), the fastest of $RUNS rounds"
printf '%-11s %-15s %9s %12s %9s\n' model material "s" "samples/s" "/lambert"
for model in rgb spectrum9 spectrum bispectral; do
    awk -v m="$model" -v n=$((W * H * (SPP - 1))) '
        $1 == m && $3 != "failed" && $3 > 0 && (!($2 in t) || $3 < t[$2]) { t[$2] = $3 }
        $1 == m && !($2 in seen) { seen[$2] = 1; order[++k] = $2 }
        END { for (i = 1; i <= k; i++) { x = order[i]
                  if (!(x in t)) { printf "%-11s %-15s %9s\n", m, x, "failed"; continue }
                  printf "%-11s %-15s %9.4f %12.0f %8.2fx\n", m, x, t[x], n / t[x],
                         ("lambert" in t && t[x] > 0) ? t["lambert"] / t[x] : 0 } }' "$TMP/times"
done
