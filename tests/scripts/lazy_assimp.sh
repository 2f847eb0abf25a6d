#!/bin/sh
# lazy_assimp.sh BUILD - gtrace maps assimp only when it reads a PLY, STL or glTF file itself
# (examples/gtrace/geometry/mesh_assimp_lib.h):
#   1. a render of analytic shapes never maps libassimp (the dynamic loader's record of the gtrace process,
#      LD_DEBUG=files);
#   2. a PLY mesh read through the mesh reader process (the default): the gtrace process does not map it either;
#   3. the same mesh read in gtrace (GENERIC_DECODE=inprocess) maps it, and gives the same picture byte for byte,
#      which differs from the picture without the mesh (the mesh was read and is seen).
set -u
BUILD=${1:-build}
GT="$BUILD/bin/gtrace"
. "$(dirname "$0")/prelude.sh"
need_program "$GT"

# maps NAME CMD...: CMD's output to TMP/NAME.err; the shared objects the gtrace process itself loaded (not a reader
# process it starts, whose record names another program) to TMP/NAME.objects
maps() {
    name=$1
    shift
    LD_DEBUG=files LD_DEBUG_OUTPUT="$TMP/$name.ld" "$@" > "$TMP/$name.err" 2>&1
    st=$?
    for f in "$TMP/$name.ld".*; do
        grep -q 'initialize program: .*gtrace$' "$f" 2> /dev/null || continue
        sed -n 's/.*file=\([^ ]*\) .*generating link map.*/\1/p' "$f"
    done > "$TMP/$name.objects"
    rm -f "$TMP/$name.ld".*
    return $st
}

cat > "$TMP/s.scene" << 'EOF2'
camera pinhole { from <0, 0, 4> at <0, 0, 0> fov 40 width 8 height 6 spp 1 }
object sphere { center <2, 0, -2> radius 0.5 material lambert { reflectance rgb 0.5 0.5 0.5 } }
light point { position <2, 2, 4> intensity rgb 10 10 10 }
light background { color rgb 0.2 0.3 0.4 }
EOF2
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n' > "$TMP/tri.ply"
printf 'element face 1\nproperty list uchar int vertex_indices\nend_header\n-1 -1 0\n1 -1 0\n0 1 0\n3 0 1 2\n' \
    >> "$TMP/tri.ply"
{
    cat "$TMP/s.scene"
    echo 'object mesh { file "tri.ply" material lambert { reflectance rgb 0.8 0.2 0.2 } }'
} > "$TMP/mesh.scene"

# ---- 1. analytic shapes ----
maps shapes "$GT" "$TMP/s.scene" -o "$TMP/shapes.png" -q || fail "render of shapes: $(cat "$TMP/shapes.err")"
[ -s "$TMP/shapes.objects" ] || fail "LD_DEBUG=files recorded no shared object of gtrace (the check is blind)"
grep -q 'libassimp' "$TMP/shapes.objects" && fail "a render of analytic shapes maps assimp"

# ---- 2. a PLY mesh through the reader process ----
unset GENERIC_DECODE
maps reader "$GT" "$TMP/mesh.scene" -o "$TMP/reader.png" -q || fail "mesh through the reader: $(cat "$TMP/reader.err")"
[ -s "$TMP/reader.objects" ] || fail "LD_DEBUG=files recorded no shared object of gtrace (the check is blind)"
grep -q 'libassimp' "$TMP/reader.objects" && fail "gtrace maps assimp for a mesh its reader process reads"

# ---- 3. the same mesh in gtrace ----
GENERIC_DECODE=inprocess maps inproc "$GT" "$TMP/mesh.scene" -o "$TMP/inproc.png" -q ||
    fail "mesh in gtrace: $(cat "$TMP/inproc.err")"
grep -q 'libassimp' "$TMP/inproc.objects" || fail "a mesh read in gtrace does not map assimp (the checks above are blind)"
cmp -s "$TMP/reader.png" "$TMP/inproc.png" || fail "the mesh read in gtrace renders otherwise than through the reader"
cmp -s "$TMP/shapes.png" "$TMP/inproc.png" && fail "the picture with the mesh equals the one without it"
exit $fails
