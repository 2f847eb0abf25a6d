#!/bin/sh
# Installs the library into a staging directory and builds a program outside the tree with
# `cc x.c $(pkg-config --cflags --libs generic)`, then runs it against the staged shared library.
set -eu
BUILD=${1:-build}
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
make --no-print-directory -s install BUILD="$BUILD" PREFIX=/usr DESTDIR="$stage" >/dev/null
cat > "$stage/x.c" <<'C'
#include <generic/builtins.h>
#include <generic/color.h>
#include <stdio.h>
int main(void)
{
    GError err;
    GColorModel *m;
    if (generic_register_builtins(&err) != G_OK || gcolormodel_create("rgb", NULL, &m, &err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    float s[3];
    GColor c;
    if (gcolor_wrap(&c, m, s, 3) != G_OK)
        return 1;
    double w[3] = {1, 1, 1}, xyz[3];
    if (gcolor_from_rgb(&c, w, GCOLOR_LIGHT) != G_OK || gcolor_to_xyz(&c, GCOLOR_LIGHT, xyz) != G_OK)
        return 1;
    gcolormodel_destroy(m);
    printf("%.4f %.4f %.4f\n", xyz[0], xyz[1], xyz[2]);
    return (xyz[1] > 0.999 && xyz[1] < 1.001) ? 0 : 1;
}
C
export PKG_CONFIG_SYSROOT_DIR="$stage"
export PKG_CONFIG_PATH="$stage/usr/lib/pkgconfig"
# a library built with sanitizers needs their run-time in the program too
san=""
nm -A "$BUILD/lib/libgeneric.a" 2>/dev/null | grep -q __asan_ && san="-fsanitize=address,undefined"
cc $san "$stage/x.c" -o "$stage/x" $(pkg-config --cflags --libs generic)
out=$(LD_LIBRARY_PATH="$stage/usr/lib" "$stage/x")
echo "installed library: D65 white XYZ = $out"
