#!/bin/sh
# pkgconfig_uninstalled.sh BUILD - the uninstalled generic.pc that `make` writes (BUILD/pkgconfig/generic.pc,
# lib/build.mk), used from the tree as docs/building.md shows, with nothing installed:
# - `cc pkgconfig_user.c $(pkg-config --cflags --libs generic)` builds a program that runs without
#   LD_LIBRARY_PATH against BUILD/lib/libgeneric.so (the file's run path) and prints the XYZ of white light;
# - an example plug-in built with its Cflags (-std=c11, M_PI from <math.h>) loads into the tree's gmat.
SRC=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=$(cd "${1:-build}" 2> /dev/null && pwd) || { echo "FAIL: no build directory ${1:-build}"; exit 1; }
. "$(dirname "$0")/prelude.sh"
need_program "$BUILD/bin/gmat"
need_command pkg-config pkg-config
[ -f "$BUILD/pkgconfig/generic.pc" ] || { echo "FAIL: make wrote no $BUILD/pkgconfig/generic.pc"; exit 1; }
export PKG_CONFIG_PATH="$BUILD/pkgconfig"
unset PKG_CONFIG_SYSROOT_DIR LD_LIBRARY_PATH
cd "$TMP" || exit 1

# a library built with sanitizers needs their run-time in the program too
san=""
nm -D "$BUILD/lib/libgeneric.so" 2> /dev/null | grep -q __asan_ && san="-fsanitize=address,undefined"
flags=$(pkg-config --cflags --libs generic) || fail "pkg-config --cflags --libs generic"
echo "pkg-config --cflags --libs generic: $flags"
# shellcheck disable=SC2086 # the flags' words
if cc $san "$SRC/tests/scripts/pkgconfig_user.c" -o user $flags > out 2>&1; then
    out=$(./user 2>&1) || fail "the program built with the uninstalled .pc: $out"
    echo "program: D65 white XYZ = $out"
    lib=$(ldd ./user | awk '$1 ~ /^libgeneric\.so/ { print $3 }')
    [ "$lib" = "$BUILD/lib/libgeneric.so.0" ] || fail "the program found libgeneric at '$lib', not in $BUILD/lib"
else
    fail "a program does not build with the uninstalled .pc: $(cat out)"
fi

# shellcheck disable=SC2046 # the flags' words
if cc -std=c11 -O2 -fPIC -shared -fvisibility=hidden -Wall -Wextra -Werror $(pkg-config --cflags generic) \
    "$SRC/examples/plugins/oren_nayar.c" -o on.so -lm > out 2>&1; then
    "$BUILD/bin/gmat" types --plugin ./on.so > out 2>&1 ||
        fail "the module built with the .pc does not load: $(cat out)"
    grep -qw oren_nayar out || fail "the module built with the .pc registered no oren_nayar: $(cat out)"
    echo "module: oren_nayar.c built with the uninstalled .pc's Cflags loads into gmat"
else
    fail "oren_nayar.c does not build with the uninstalled .pc's Cflags: $(cat out)"
fi
exit $fails
