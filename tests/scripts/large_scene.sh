#!/bin/sh
# large_scene.sh BUILD - a scene file of 100 MB of plain entries (1,500,000 spheres in one file, written here at run
# time) loads and renders (1x1) under the default memory budget, and the same file under a budget of 64 MiB is
# refused before it is read, naming the file, its size and the budget. Serial: it writes 100 MB and takes a few
# seconds of both processors' time (bounded_run's bound is set out of reach: no time is asserted).
BUILD=$(cd "${1:-build}" 2> /dev/null && pwd) || { echo "FAIL: no build directory ${1:-build}"; exit 1; }
GTRACE="$BUILD/bin/gtrace"
. "$(dirname "$0")/prelude.sh"
need_program "$GTRACE"

{
    echo 'material m lambert { reflectance rgb 0.5 0.5 0.5 }'
    echo 'camera pinhole { from <0, 50, -150> at <0, 0, 0> fov 40 width 1 height 1 spp 1 depth 1 }'
    echo 'light point { position <0, 100, -100> intensity rgb 1000 1000 1000 }'
    awk 'BEGIN { for (k = 0; k < 1500000; k++)
        printf "object sphere { center <%.2f, %.2f, %.2f> radius 0.04 material m }\n",
            (int(k / 1225) - 612) * 0.1, (k % 7) * 0.01, (k % 1225 - 612) * 0.1 }'
} > "$TMP/big.scene"
size=$(wc -c < "$TMP/big.scene")
[ "$size" -ge 100000000 ] || fail "the generated file has $size bytes, not 100 MB"

bounded_run "gtrace, a $size-byte file of 1,500,000 spheres" 0 100000 "$GTRACE" "$TMP/big.scene" -o "$TMP/big.png" \
    --threads 2 -q
[ -s "$TMP/big.png" ] || fail "gtrace, 100 MB file: no image"

bounded_run "gtrace, the same file under a 64 MiB budget" 1 100000 env GENERIC_MEMORY_LIMIT_MB=64 "$GTRACE" \
    "$TMP/big.scene" -o "$TMP/small.png" -q
grep -q "big.scene\" ($size bytes) needs [0-9.]* MiB, over the memory budget: .* of 64 MiB" "$TMP/err" ||
    fail "a file over the budget: $(head -c 2000 "$TMP/err")"
[ -e "$TMP/small.png" ] && fail "a refused scene left an image"
exit $fails
