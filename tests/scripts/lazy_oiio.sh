#!/bin/sh
# lazy_oiio.sh BUILD - OpenImageIO is mapped only when an image needs it (lib/image/oiio_module.h):
#   1. gtrace --help, gmat --help, gcolor list, a small render to PNG (libpng) and to EXR (OpenEXRCore, loaded on
#      first use) never map libOpenImageIO (the dynamic loader's own record, LD_DEBUG=files); the PNG is a valid
#      8-bit sRGB picture, the EXR holds the background's linear values, and only the EXR render maps OpenEXRCore;
#   2. the same render to TIFF does map it (the check above can fail), and reads back;
#   3. without the module (GENERIC_OIIO_MODULE naming a missing file, or a file that is not a module) the TIFF
#      render fails with a message naming libgeneric_oiio.so and leaves no output, while PNG and EXR still work;
#   4. an installed library (make install into a staging directory) finds its module and its image decoder in
#      PREFIX/lib/generic/ (the read back below goes through the decoder process).
set -u
BUILD=${1:-build}
GT="$BUILD/bin/gtrace"
. "$(dirname "$0")/prelude.sh"
unset GENERIC_OIIO_MODULE

# maps NAME CMD...: CMD's stdout and stderr to TMP/NAME.*, the shared objects it loaded to TMP/NAME.objects
maps() {
    name=$1
    shift
    LD_DEBUG=files LD_DEBUG_OUTPUT="$TMP/$name.ld" "$@" > "$TMP/$name.out" 2> "$TMP/$name.err"
    st=$?
    cat "$TMP/$name.ld".* 2>/dev/null | sed -n 's/.*file=\([^ ]*\) .*generating link map.*/\1/p' > "$TMP/$name.objects"
    rm -f "$TMP/$name.ld".*
    return $st
}

cat > "$TMP/s.scene" << 'EOF2'
camera pinhole { from <0, 0, 4> at <0, 0, 0> fov 40 width 8 height 6 spp 1 }
object sphere { center <0, 0, 0> radius 1 material lambert { reflectance rgb 0.5 0.5 0.5 } }
light point { position <2, 2, 4> intensity rgb 10 10 10 }
light background { color rgb 0.2 0.3 0.4 }
EOF2

# ---- 1. no OpenImageIO without an image that needs it ----
for c in "gtrace --help" "gmat --help" "gcolor list" "gtrace $TMP/s.scene -o $TMP/o.exr -q" \
         "gtrace $TMP/s.scene -o $TMP/o.png -q"; do
    # shellcheck disable=SC2086
    set -- $c
    tool=$1
    shift
    maps probe "$BUILD/bin/$tool" "$@" || fail "$c: exit status $?: $(cat "$TMP/probe.err")"
    [ -s "$TMP/probe.objects" ] || fail "$c: LD_DEBUG=files recorded no shared object (the check is blind)"
    if grep -q 'libOpenImageIO' "$TMP/probe.objects"; then
        fail "$c maps OpenImageIO: $(grep libOpenImageIO "$TMP/probe.objects" | head -1)"
    fi
    case $c in
    *o.exr*) grep -q 'libOpenEXRCore' "$TMP/probe.objects" || fail "$c does not map OpenEXRCore (the check is blind)" ;;
    *) ! grep -q 'libOpenEXRCore' "$TMP/probe.objects" || fail "$c maps OpenEXRCore" ;;
    esac
done
n=$(wc -l < "$TMP/probe.objects")
[ "$n" -le 20 ] || fail "a PNG render maps $n shared objects (expected at most 20)"
# the PNG: 8x6, 8-bit RGB, the sRGB chunk; the background pixel (corner) is the sRGB encoding of 0.2 0.3 0.4
if command -v oiiotool > /dev/null; then
    info=$(oiiotool --info -v "$TMP/o.png" 2>&1)
    echo "$info" | grep -q "oiio:ColorSpace: \"sRGB\"" || fail "the PNG is not tagged sRGB: $info"
    echo "$info" | grep -Eq '8 x +6, 3 channel, uint8 png' || fail "the PNG's header: $info"
    corner=$(oiiotool "$TMP/o.png" --cut 1x1+0+0 --printstats 2>&1 | sed -n 's/.*Stats Avg: *\([0-9. ]*\)(float).*/\1/p')
    echo "$corner" | awk '{ d = ($1 - 124/255)^2 + ($2 - 149/255)^2 + ($3 - 170/255)^2; exit !(d < 1e-4) }' ||
        fail "PNG background pixel $corner, expected the sRGB encoding of 0.2 0.3 0.4 (124 149 170)/255"
fi

# the EXR: the background's linear values
if command -v oiiotool > /dev/null; then
    corner=$(oiiotool "$TMP/o.exr" --cut 1x1+0+0 --printstats 2>&1 | sed -n 's/.*Stats Avg: *\([0-9. ]*\)(float).*/\1/p')
    echo "$corner" | awk '{ d = ($1 - 0.2)^2 + ($2 - 0.3)^2 + ($3 - 0.4)^2; exit !(d < 1e-6) }' ||
        fail "EXR background pixel $corner, expected 0.2 0.3 0.4"
fi

# ---- 2. a TIFF output maps it, and reads back ----
maps tif "$GT" "$TMP/s.scene" -o "$TMP/o.tif" -q || fail "TIFF render: exit status $?: $(cat "$TMP/tif.err")"
grep -q 'libOpenImageIO' "$TMP/tif.objects" || fail "a TIFF render does not map OpenImageIO (the check above is blind)"
grep -q 'libgeneric_oiio.so' "$TMP/tif.objects" || fail "a TIFF render does not load the module"
if command -v oiiotool > /dev/null; then
    oiiotool --info "$TMP/o.tif" 2>&1 | grep -Eq '8 x +6, 3 channel, uint8 tiff' ||
        fail "the TIFF's header: $(oiiotool --info "$TMP/o.tif" 2>&1)"
fi

# ---- 3. a missing or broken module is a clear error, and PNG output does not need it ----
printf 'not a shared object\n' > "$TMP/broken.so"
for m in "$TMP/missing.so" "$TMP/broken.so"; do
    GENERIC_OIIO_MODULE=$m "$GT" "$TMP/s.scene" -o "$TMP/m.tif" -q > "$TMP/m.err" 2>&1
    st=$?
    [ $st -ne 0 ] || fail "TIFF render without a module ($m) succeeded"
    grep -q 'libgeneric_oiio.so' "$TMP/m.err" || fail "no module ($m): message does not name it: $(cat "$TMP/m.err")"
    grep -q "$m" "$TMP/m.err" || fail "no module ($m): message does not say what was tried: $(cat "$TMP/m.err")"
    [ ! -e "$TMP/m.tif" ] || fail "no module ($m): an output was left"
    for ext in png exr; do
        GENERIC_OIIO_MODULE=$m "$GT" "$TMP/s.scene" -o "$TMP/m.$ext" -q > "$TMP/m.err" 2>&1 ||
            fail "$ext render without a module ($m) failed: $(cat "$TMP/m.err")"
    done
done

# ---- 4. an installed library finds its installed module ----
stage="$TMP/stage"
make --no-print-directory -s install BUILD="$BUILD" PREFIX=/usr DESTDIR="$stage" > /dev/null ||
    fail "make install failed"
[ -f "$stage/usr/lib/generic/libgeneric_oiio.so" ] || fail "make install does not install the module"
[ -x "$stage/usr/lib/generic/generic-decode" ] || fail "make install does not install the image decoder"
cat > "$TMP/x.c" << 'EOF2'
#include <generic/builtins.h>
#include <generic/services/image.h>
#include <stdio.h>
int main(int argc, char **argv)
{
    GError err;
    GImage img, back;
    if (argc < 2 || generic_register_builtins(&err) != G_OK || gimage_create(&img, 2, 1, 3, &err) != G_OK)
        return 1;
    for (int i = 0; i < 6; i++)
        img.pixels[i] = 0.25f * (float)i;
    if (gimage_write(argv[1], &img, NULL, &err) != G_OK || gimage_read(argv[1], 0, &back, &err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    int ok = back.width == 2 && back.height == 1 && back.pixels[5] == 1.25f;
    gimage_free(&img);
    gimage_free(&back);
    return ok ? 0 : 1;
}
EOF2
san=""
nm -A "$BUILD/lib/libgeneric.a" 2>/dev/null | grep -q __asan_ && san="-fsanitize=address,undefined"
# shellcheck disable=SC2086
if cc $san -I"$stage/usr/include" "$TMP/x.c" -o "$TMP/x" -L"$stage/usr/lib" -lgeneric -lm; then
    LD_LIBRARY_PATH="$stage/usr/lib" "$TMP/x" "$TMP/x.exr" > "$TMP/x.err" 2>&1 ||
        fail "a program on the installed library cannot write and read EXR: $(cat "$TMP/x.err")"
    GENERIC_DECODE=inprocess LD_LIBRARY_PATH="$stage/usr/lib" "$TMP/x" "$TMP/y.exr" > "$TMP/x.err" 2>&1 ||
        fail "a program on the installed library cannot read EXR in its own process: $(cat "$TMP/x.err")"
else
    fail "cannot build against the installed library"
fi

if [ $fails -eq 0 ]; then
    echo "lazy_oiio: no OpenImageIO for --help, list, PNG or EXR output ($n shared objects for a render); TIFF loads it; a missing module is a clear error; the installed library finds its module"
fi
[ $fails -eq 0 ]
