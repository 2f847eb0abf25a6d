#!/bin/sh
# load_linear.sh BUILD - loading a scene is linear in its size: gtrace parses and builds N and 4N named spheres
# (each naming one of N/20 named materials, rendered at 1x1) and the CPU time of the larger, net of a 1-object
# scene's, must stay below 10 times the smaller's: linear work gives 4, a quadratic step 16. Each figure is the
# least CPU time (user + system) of three runs, so a burst of load on the shared machine does not decide it.
set -u
BUILD=${1:-build}
GT="$BUILD/bin/gtrace"
N=${LOAD_N:-50000}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
[ -x /usr/bin/time ] || { echo "SKIP: needs GNU time (/usr/bin/time)"; exit 0; }

scene() { # COUNT FILE
    awk -v n="$1" 'BEGIN {
        print "camera pinhole { from <0, 0, -10> at <0, 0, 0> width 1 height 1 spp 1 depth 1 }"
        print "light point { position <0, 10, -10> intensity rgb 10 10 10 }"
        nm = int(n / 20) + 1
        for (i = 0; i < nm; i++)
            printf "material m%d lambert { reflectance rgb 0.5 0.5 0.5 }\n", i
        for (i = 0; i < n; i++)
            printf "object o%d sphere { center <%d, %d, %d> radius 0.3 material m%d }\n", i, i % 100, int(i / 100) % 100, int(i / 10000), i % nm
    }' > "$2"
}
# best COUNT: the least CPU seconds of three loads of COUNT spheres
best() {
    scene "$1" "$TMP/s.scene"
    b=""
    for k in 1 2 3; do
        /usr/bin/time -f "%U %S" -o "$TMP/t" "$GT" "$TMP/s.scene" -o "$TMP/s.png" --threads 1 > "$TMP/out" 2>&1 || {
            echo "FAIL: gtrace on $1 spheres:"
            cat "$TMP/out"
            exit 1
        }
        c=$(awk '{ print $1 + $2 }' "$TMP/t")
        if [ -z "$b" ] || awk -v a="$c" -v b="$b" 'BEGIN { exit !(a < b) }'; then b=$c; fi
    done
    echo "$b"
}
base=$(best 1)
small=$(best "$N")
large=$(best $((4 * N)))
echo "CPU s: 1 sphere $base, $N spheres $small, $((4 * N)) spheres $large"
awk -v s="$small" -v l="$large" -v z="$base" 'BEGIN {
    s -= z; l -= z
    if (s < 0.02) s = 0.02   # the timer counts in 10 ms steps
    r = l / s
    printf "ratio %.2f (linear 4, quadratic 16; limit 10)\n", r
    exit !(r < 10)
}' || { echo "FAIL: loading grows faster than linearly"; exit 1; }
echo "PASS"
