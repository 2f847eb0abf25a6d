#!/bin/sh
# structure_limits.sh BUILD - the tools on large structured inputs written here at run time: 200,000 spheres
# (gtrace, a bounded time), a scene textured by a CSG union of 300,000 spheres and a CPG union of 300,000
# circles (rendered, no crash), 200,000 nodes (gmat list, every one listed, a bounded time), a chain of 100,000
# references and a tower of 40 self-blending nodes (refused with the exact message at once). Every run must end
# with a status below 128 and no sanitizer report. The time bounds are generous (a loaded machine, sanitizer
# builds): what they catch is quadratic or exponential work, which took minutes.
BUILD=$(cd "${1:-build}" 2> /dev/null && pwd) || { echo "FAIL: no build directory ${1:-build}"; exit 1; }
GMAT="$BUILD/bin/gmat"
GTRACE="$BUILD/bin/gtrace"
. "$(dirname "$0")/prelude.sh"
serial_only

header='material m lambert { reflectance rgb 0.5 0.5 0.5 }
camera pinhole { from <0, 0, -10> at <0, 0, 0> fov 40 width 16 height 16 spp 1 depth 2 }
light point { position <0, 5, -5> intensity rgb 10 10 10 }'

# ---- 200,000 objects ----
{
    echo "$header"
    awk 'BEGIN { for (i = 0; i < 200000; i++)
        printf "object sphere { center <%g, %g, %g> radius 0.01 material m }\n",
            (i % 100) * 0.05 - 2.5, int(i / 100) % 100 * 0.05 - 2.5, int(i / 10000) * 0.05 }'
} > "$TMP/spheres.scene"
bounded_run "gtrace, 200,000 spheres" 0 30 "$GTRACE" "$TMP/spheres.scene" -o "$TMP/spheres.png" -q
[ -s "$TMP/spheres.png" ] || fail "gtrace, 200,000 spheres: no image"

# ---- long operand lists as textures ----
{
    echo "generator pips csg { space object shape union {"
    awk 'BEGIN { for (i = 0; i < 300000; i++) printf "transform { translate %g %g 0 } sphere 0.004\n",
        (i % 600) / 300.0 - 1, int(i / 600) / 250.0 - 1 }'
    echo "} }"
} > "$TMP/pips.mat"
{
    echo "generator dots cpg { shape union {"
    awk 'BEGIN { for (i = 0; i < 300000; i++) printf "circle %g %g 0.002\n", (i % 600) / 600.0, int(i / 600) / 500.0 }'
    echo "} }"
} > "$TMP/dots.mat"
{
    echo "$header"
    echo 'include "pips.mat"'
    echo 'include "dots.mat"'
    echo "object sphere { center <-1, 0, 0> radius 1 material interpolate { a m b mirror { reflectance rgb 1 1 1 } t pips } }"
    echo "object sphere { center <1, 0, 0> radius 1 material scale { child m factor dots } }"
} > "$TMP/shapes.scene"
bounded_run "gtrace, a union of 300,000 spheres and one of 300,000 circles as textures" 0 120 \
    "$GTRACE" "$TMP/shapes.scene" -o "$TMP/shapes.png" -q
[ -s "$TMP/shapes.png" ] || fail "gtrace, long unions: no image"

# ---- many entries ----
{
    echo 'material m lambert { reflectance rgb 0.5 0.5 0.5 }'
    awk 'BEGIN { for (i = 0; i < 200000; i++) printf "node n%d scale { child m factor constant { value 0.5 } }\n", i }'
} > "$TMP/nodes.mat"
bounded_run "gmat list, 200,000 nodes" 0 30 "$GMAT" list "$TMP/nodes.mat"
n=$(grep -c '^node  *n[0-9]* *scale' "$TMP/out")
[ "$n" = 200000 ] || fail "gmat list, 200,000 nodes: $n listed"
grep -q '^node  *n199999 ' "$TMP/out" || fail "gmat list, 200,000 nodes: the last one is not listed"

# ---- chains of references and self-blending towers: refused at the limit, at once ----
{
    echo 'material n0 lambert { reflectance rgb 0.5 0.5 0.5 }'
    awk 'BEGIN { for (i = 1; i <= 100000; i++) printf "node n%d scale { child n%d factor constant { value 1 } }\n", i, i - 1 }'
} > "$TMP/chain.mat"
bounded_run "gmat eval, a chain of 100,000 references" 1 30 "$GMAT" eval "$TMP/chain.mat" n100000 --in 30 --out 30
want="gmat: $TMP/chain.mat:257:58: scale: the node would be 257 deep, the limit is 256"
[ "$(cat "$TMP/err")" = "$want" ] || fail "chain: expected '$want', got '$(cat "$TMP/err")'"

{
    echo 'material n0 lambert { reflectance rgb 0.5 0.5 0.5 }'
    awk 'BEGIN { for (i = 1; i <= 40; i++) printf "node n%d interpolate { a n%d b n%d t constant { value 0.5 } }\n", i, i - 1, i - 1 }'
} > "$TMP/tower.mat"
bounded_run "gmat eval, a tower of 40 self-blending nodes" 1 30 "$GMAT" eval "$TMP/tower.mat" n40 --in 30 --out 30
want="gmat: $TMP/tower.mat:17:61: interpolate: one call of the node would make 131071 material calls, the limit is 100000"
[ "$(cat "$TMP/err")" = "$want" ] || fail "tower: expected '$want', got '$(cat "$TMP/err")'"

# 16 levels are within the budget (65,535 calls) and evaluate to the leaf's value
head -n 16 "$TMP/tower.mat" > "$TMP/tower15.mat"
bounded_run "gmat eval, a tower of 15 self-blending nodes" 0 30 "$GMAT" eval "$TMP/tower15.mat" n15 --in 30 --out 30
grep reflected "$TMP/out" > "$TMP/top"
"$GMAT" eval "$TMP/tower15.mat" n0 --in 30 --out 30 2>&1 | grep reflected > "$TMP/leaf"
[ -s "$TMP/top" ] && cmp -s "$TMP/top" "$TMP/leaf" || fail "tower of 15: $(cat "$TMP/out") differs from the leaf's $(cat "$TMP/leaf")"

if [ $fails -ne 0 ]; then
    echo "$fails failures"
    exit 1
fi
echo "structure limits: all checks passed"
