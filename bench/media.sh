#!/bin/sh
# media.sh [BUILD] - what participating media cost in gtrace's path tracer, and the memory a grid medium takes.
#
# 1. Speed: examples/scenes/media_fog.scene (a homogeneous atmosphere, a spot light) and
#    examples/gtrace/media/vdb/media_cloud.scene (a grid medium of a 64^3 OpenVDB cloud written by make_grid.py) at
#    96x72, 4 samples per pixel, 1 thread, in every colour model: render time and camera samples per second (from
#    gtrace's summary line), the fastest of RUNS rounds (default 3).
# 2. Memory: the peak resident size (GNU time) of gtrace rendering the cloud scene with a grid of MEM_N^3 voxels
#    (default 256: large enough to stand out of the libraries' own memory) at 8x6, 1 spp, against the same scene with
#    the grid medium replaced by a homogeneous one (what the grid adds), and the grid's own size: its dense copy in
#    floats (the active voxels' bounding box x 4 bytes) and the .vdb file.
# A benchmark: it prints figures and never fails on time. Needs python3-openvdb and the reader gtrace-vdb.
BUILD=${1:-build}
GT="$BUILD/bin/gtrace"
SRC=$(cd "$(dirname "$0")/.." && pwd)
[ -x "$GT" ] || { echo "bench-media: $GT is not built"; exit 1; }
[ -x "$BUILD/lib/generic/gtrace-vdb" ] || { echo "bench-media: the OpenVDB reader is not built (libopenvdb-dev)"; exit 1; }
[ -x /usr/bin/time ] || { echo "bench-media: needs GNU time (/usr/bin/time, Debian package time)"; exit 1; }
PY=python3
$PY -c 'import pyopenvdb' 2>/dev/null || PY=/usr/bin/python3
$PY -c 'import pyopenvdb' 2>/dev/null || { echo "bench-media: needs python3-openvdb"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
N=${GRID_N:-64}
$PY "$SRC/examples/gtrace/media/vdb/make_grid.py" cloud "$TMP/cloud.vdb" "$N" || exit 1
cp "$SRC/examples/gtrace/media/vdb/media_cloud.scene" "$TMP/cloud.scene"
cp "$SRC/examples/scenes/media_fog.scene" "$TMP/fog.scene"
RUNS=${RUNS:-3}
W=96 H=72 SPP=4
run() { # SCENE MODEL: render seconds
    "$GT" "$TMP/$1.scene" -o "$TMP/out.exr" --width $W --height $H --spp $SPP --colormodel "$2" \
        --integrator path --threads 1 2>&1 |
        awk '/^gtrace: .* rays/ { for (i = 1; i <= NF; i++) if ($i == "s,") t = $(i - 1) } END { if (t == "") exit 1; print t }'
}
echo "path integrator, ${W}x${H}, $SPP spp, 1 thread, the fastest of $RUNS rounds"
printf '%-7s %-11s %8s %12s\n' scene model "s" "samples/s"
r=0
while [ $r -lt "$RUNS" ]; do
    for scene in fog cloud; do
        for model in rgb spectrum9 spectrum bispectral; do
            out=$(run "$scene" "$model") || out="failed"
            echo "$scene $model $out" >> "$TMP/speed"
        done
    done
    r=$((r + 1))
done
for scene in fog cloud; do
    for model in rgb spectrum9 spectrum bispectral; do
        awk -v s="$scene" -v m="$model" -v n=$((W * H * SPP)) '
            $1 == s && $2 == m && $3 != "failed" && (t == "" || $3 < t) { t = $3 }
            END { if (t == "") printf "%-7s %-11s %8s\n", s, m, "failed"
                  else printf "%-7s %-11s %8.3f %12.0f\n", s, m, t, (t > 0 ? n / t : 0) }' "$TMP/speed"
    done
done

# ---- memory ----
M=${MEM_N:-256}
$PY "$SRC/examples/gtrace/media/vdb/make_grid.py" cloud "$TMP/cloud.vdb" "$M" || exit 1
sed 's|grid { file "cloud.vdb" grid density|homogeneous {|; s|transform { scale 1.4 translate <0, 1.6, 0> }||' \
    "$TMP/cloud.scene" > "$TMP/flat.scene"
peak() { # SCENE: peak resident KiB
    /usr/bin/time -f '%M' "$GT" "$TMP/$1.scene" -o "$TMP/small.exr" --width 8 --height 6 --spp 1 --integrator path \
        --threads 1 -q 2>&1 >/dev/null | tail -1
}
# the dense copy spans the active voxels' bounding box
box=$($PY -c "import pyopenvdb as v; lo, hi = v.read('$TMP/cloud.vdb', 'density').evalActiveVoxelBoundingBox()
print(*(b - a + 1 for a, b in zip(lo, hi)))") || exit 1
set -- $box
grid_kib=$(($1 * $2 * $3 * 4 / 1024))
file_kib=$(($(wc -c < "$TMP/cloud.vdb") / 1024))
cloud=$(peak cloud) flat=$(peak flat)
echo
echo "memory: the cloud scene with a ${M}^3 grid ${cloud} KiB peak resident, the same with a homogeneous medium" \
     "${flat} KiB: the grid adds $((cloud - flat)) KiB for a dense copy of $1x$2x$3 floats, ${grid_kib} KiB" \
     "(the .vdb file ${file_kib} KiB)"
