#!/bin/sh
# emissive.sh [BUILD] - what glowing geometry costs the path tracer as light: camera samples per second with a lamp
# panel of 1, 100 and 10,000 emissive triangles over a floor and a sphere (`make bench-emissive`). The panel keeps
# its size (1 x 1; the single triangle is half of it), so the pictures are alike and only the number of triangles
# the light is chosen from changes: an alias table chooses one in constant time, so the rate should not fall with
# their number beyond what the larger mesh costs Embree. 160x120, 4 spp, depth 4, 1 thread, the fastest of RUNS
# rounds (default 3) that run every configuration once in turn; the render time is gtrace's summary line.
# A benchmark: it prints figures and never fails on time.
BUILD=${1:-build}
GT="$BUILD/bin/gtrace"
[ -x "$GT" ] || { echo "bench-emissive: $GT is not built"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
[ -n "${KEEP:-}" ] && trap 'echo "kept $TMP"' EXIT
RUNS=${RUNS:-3}
W=160 H=120 SPP=4
# panel N: an OBJ of N triangles (1, or a grid of a x b squares) at height 1.5 facing down
panel() {
    case $1 in
    1) printf 'v -0.5 1.5 -0.5\nv 0.5 1.5 -0.5\nv -0.5 1.5 0.5\nf 1 2 3\n' ;;
    100) cols=50 rows=1 ;;
    10000) cols=100 rows=50 ;;
    esac
    [ "$1" = 1 ] && return
    awk -v c="$cols" -v r="$rows" 'BEGIN {
        for (i = 0; i <= c; i++) for (j = 0; j <= r; j++) printf "v %.6f 1.5 %.6f\n", -0.5 + i / c, -0.5 + j / r
        for (i = 0; i < c; i++) for (j = 0; j < r; j++) {
            a = i * (r + 1) + j + 1; b = a + r + 1
            printf "f %d %d %d\nf %d %d %d\n", a, b, a + 1, b, b + 1, a + 1 } }'
}
for n in 1 100 10000; do
    panel $n > "$TMP/panel$n.obj"
    cat > "$TMP/lamp$n.scene" << SCENE
colormodel rgb
camera pinhole { from <0, 2, 4> at <0, 0.3, 0> fov 40 }
object plane { point <0, 0, 0> normal <0, 1, 0> material lambert { reflectance rgb 0.5 0.5 0.5 } }
object sphere { center <0.3, 0.4, 0.2> radius 0.4 material lambert { reflectance rgb 0.7 0.6 0.5 } }
object mesh { file "panel$n.obj" material emitter { radiance rgb 4 4 4 } }
SCENE
done
run() { # N: render seconds
    "$GT" "$TMP/lamp$1.scene" -o "$TMP/lamp$1.exr" --width $W --height $H --spp $SPP --depth 4 --integrator path \
        --threads 1 2>&1 | awk '/^gtrace: .* rays/ { for (i = 1; i <= NF; i++) if ($i == "s,") t = $(i - 1) }
                                END { if (t == "") exit 1; print t }'
}
r=0
while [ $r -lt "$RUNS" ]; do
    for n in 1 100 10000; do
        t=$(run $n) || t=failed
        echo "$n $t" >> "$TMP/times"
    done
    r=$((r + 1))
done
echo "lamp panel over a floor, ${W}x${H}, $SPP spp, depth 4, path, 1 thread, the fastest of $RUNS rounds"
printf '%-20s %8s %12s\n' "emissive triangles" "s" "samples/s"
for n in 1 100 10000; do
    awk -v n=$n -v s=$((W * H * SPP)) '$1 == n && $2 != "failed" && (t == "" || $2 < t) { t = $2 }
        END { if (t == "") printf "%-20s %8s\n", n, "failed"; else printf "%-20s %8.4f %12.0f\n", n, t, s / t }' "$TMP/times"
done
