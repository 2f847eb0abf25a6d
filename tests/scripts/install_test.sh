#!/bin/sh
# Installs everything into a staging directory (DESTDIR, the default PREFIX /usr/local) and checks what a user gets:
# - every installed tool answers --version and runs one real command; the installed gtrace reads a PLY through its
#   installed mesh reader process (PREFIX/lib/generic/gtrace-mesh);
# - an installed example plug-in loads by its bare name from the default directory PREFIX/lib/generic/plugins
#   (the staged tree is bind-mounted over PREFIX in a private mount namespace; skipped, and said so, without
#   unshare);
# - a program built with `cc x.c $(pkg-config --cflags --libs generic)` runs against the staged shared library,
#   and a module built with the staged .pc's Cflags as docs/building.md shows (-std=c11, M_PI) loads into a tool;
# - a man page per tool when help2man is installed;
# - `make uninstall` leaves no file in the staging tree.
set -eu
BUILD=${1:-build}
PREFIX=/usr/local
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
make --no-print-directory -s install BUILD="$BUILD" DESTDIR="$stage" > "$stage/install.log" 2>&1 ||
    { cat "$stage/install.log"; echo "FAIL: make install"; exit 1; }
src=$(pwd)
root="$stage$PREFIX"
mkdir "$stage/work"
cd "$stage/work"

# ---- the library through pkg-config ----
export PKG_CONFIG_SYSROOT_DIR="$stage"
export PKG_CONFIG_PATH="$root/lib/pkgconfig"
# a library built with sanitizers needs their run-time in the program too
san=""
nm -A "$src/$BUILD/lib/libgeneric.a" 2>/dev/null | grep -q __asan_ && san="-fsanitize=address,undefined"
cc $san "$src/tests/scripts/pkgconfig_user.c" -o x $(pkg-config --cflags --libs generic)
out=$(LD_LIBRARY_PATH="$root/lib" ./x) || fail "the program built with the installed .pc: $out"
echo "installed library: D65 white XYZ = $out"

# ---- every installed tool: --version and one real command ----
tools="gcolor gmat gprobe gtrace"
for t in $tools; do
    [ -x "$root/bin/$t" ] || { fail "$t is not installed in bin/"; continue; }
    v=$("$root/bin/$t" --version 2>&1) || fail "$t --version exits non-zero"
    case "$v" in "$t (libgeneric) "[0-9]*) ;; *) fail "$t --version says: $v" ;; esac
done
[ $fails -eq 0 ] || { echo "$fails failure(s)"; exit 1; }
bin="$root/bin"
"$bin/gcolor" list > out 2>&1 && grep -qx rgb out || fail "gcolor list does not list rgb: $(cat out)"
"$bin/gmat" list "$src/examples/materials/lambert.mat" > out 2>&1 && [ -s out ] ||
    fail "gmat list lambert.mat: $(cat out)"
"$bin/gprobe" sky -o sky.hdr --height 16 > out 2>&1 || fail "gprobe sky: $(cat out)"
"$bin/gprobe" irradiance --probe sky.hdr --normal 0,0,1 > out 2>&1 || fail "gprobe irradiance: $(cat out)"
awk '{ for (i = 1; i <= NF; i++) if ($i + 0 > 0) pos = 1 } END { exit !pos }' out ||
    fail "gprobe irradiance of a sunny sky is not positive: $(cat out)"
cat > one.scene <<'S'
colormodel rgb
camera pinhole { from <0, 0, 3> at <0, 0, 0> fov 40 width 16 height 16 spp 1 depth 1 }
light background { color rgb 1 1 1 }
object sphere { center <0, 0, 0> radius 1 material lambert { reflectance rgb 0.5 0.5 0.5 } }
S
"$bin/gtrace" one.scene -o one.png -q > out 2>&1 && [ -s one.png ] || fail "gtrace one.scene: $(cat out)"
[ -x "$root/lib/generic/gtrace-mesh" ] || fail "the mesh reader is not installed in lib/generic/"
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n' > tri.ply
printf 'element face 1\nproperty list uchar int vertex_indices\nend_header\n-1 -1 0\n1 -1 0\n0 1 0\n3 0 1 2\n' >> tri.ply
sed 's|object sphere { center <0, 0, 0> radius 1|object mesh { file "tri.ply"|' one.scene > mesh.scene
"$bin/gtrace" mesh.scene -o mesh.png -q > out 2>&1 && [ -s mesh.png ] || fail "gtrace mesh.scene (a PLY): $(cat out)"
# the shipped OpenColorIO config, installed in share/generic/ocio/ and found from the installed tool
[ -f "$root/share/generic/ocio/config.ocio" ] || fail "the OpenColorIO config is not installed in share/generic/ocio/"
env -u OCIO "$bin/gtrace" one.scene -o view.png -q --view Nope > out 2>&1 && fail "gtrace --view Nope succeeded"
grep -q "$root/share/generic/ocio/config.ocio.*its views: Standard, Log, Raw" out ||
    fail "gtrace --view does not find the installed OpenColorIO config: $(cat out)"
env -u OCIO "$bin/gtrace" one.scene -o view.png -q --view Raw > out 2>&1 && [ -s view.png ] ||
    fail "gtrace --view Raw: $(cat out)"

# ---- the example plug-ins, found by bare name in the default directory ----
for p in "$src"/examples/plugins/*.c; do
    so=$(basename "$p" .c).so
    [ -f "$root/lib/generic/plugins/$so" ] || fail "$so is not installed in lib/generic/plugins/"
done
"$bin/gcolor" list --plugin nothere.so > out 2>&1 && fail "a missing module was found"
grep -q "not found in \(.*, \)\{0,1\}$PREFIX/lib/generic/plugins, \. (" out ||
    fail "the installed plug-in directory is not searched before the current directory: $(cat out)"
if unshare -rm true 2>/dev/null; then
    unshare -rm sh -c "mount --bind '$root' '$PREFIX' && '$PREFIX/bin/gcolor' list --plugin grey.so" > out 2>&1 ||
        fail "grey.so is not found by its bare name in $PREFIX/lib/generic/plugins: $(cat out)"
    grep -qx grey out || fail "the installed grey.so did not register grey: $(cat out)"
    echo "installed plug-in: grey.so loaded by bare name from $PREFIX/lib/generic/plugins"
else
    echo "installed plug-in: SKIPPED loading by bare name (no unshare -rm to bind the stage over $PREFIX)"
fi

# ---- a module built with the installed .pc, as docs/building.md shows, loaded into the installed tool ----
cat > halfgrey.c <<'C'
#include <generic/material.h>
#include <generic/plugin.h>
#include <math.h>
/* M_PI is not ISO C: the .pc's Cflags must make <math.h> define it under -std=c11. */
static const double quarter_turn = M_PI / 2;
C
cp "$src/examples/plugins/oren_nayar.c" on.c
cc -std=c11 -O2 -fPIC -shared -fvisibility=hidden -Wall -Wextra -Werror $(pkg-config --cflags generic) on.c \
    -o on.so -lm > out 2>&1 || fail "oren_nayar.c does not build with the installed .pc's Cflags: $(cat out)"
cc -std=c11 -fsyntax-only -Wall -Wextra -Wno-unused-const-variable $(pkg-config --cflags generic) halfgrey.c \
    > out 2>&1 || fail "M_PI is not defined under -std=c11 with the .pc's Cflags: $(cat out)"
if [ -f on.so ]; then
    "$bin/gmat" types --plugin ./on.so > out 2>&1 || fail "the module built with the .pc does not load: $(cat out)"
    grep -qw oren_nayar out || fail "the module built with the .pc registered no oren_nayar: $(cat out)"
fi

# ---- man pages ----
if command -v help2man > /dev/null 2>&1; then
    for t in $tools; do
        m="$root/share/man/man1/$t.1"
        [ -s "$m" ] && grep -q "^\.TH \"*$(echo "$t" | tr a-z A-Z)" "$m" || fail "no man page $m"
    done
else
    grep -q "help2man not found" "$stage/install.log" || fail "make install did not say that it wrote no man pages"
    echo "man pages: SKIPPED (help2man is not installed)"
fi

# ---- the Python package, where Debian's python3 looks under PREFIX (lib/python3.X/dist-packages) ----
py=/usr/bin/python3
pydir="$root/lib/python$("$py" -c 'import sys; print("%d.%d" % sys.version_info[:2])')/dist-packages"
pycheck='import generic; m = generic.load("'"$src"'/examples/materials/lambert.mat").material("grey"); '
pycheck="$pycheck"'print(m.reflection([0, 0, 1], [0, 0, 1], [0, 0, 1])[0, 1])'
if [ -n "$san" ]; then
    echo "installed Python package: SKIPPED in a sanitizer build (python.sh says why)"
elif ! [ -f "$pydir/generic/__init__.py" ]; then
    fail "the Python package is not installed in $pydir/generic"
elif "$py" -c "import cffi, numpy" 2> /dev/null; then
    out=$(PYTHONPATH="$pydir" GENERIC_LIBDIR="$root/lib" "$py" -c "$pycheck" 2>&1) ||
        fail "the installed Python package: $out"
    case "$out" in 0.159*) ;; *) fail "the installed package's lambert reflects $out, not 0.5 / pi" ;; esac
    if unshare -rm true 2> /dev/null; then
        if out=$(unshare -rm sh -c "mount --bind '$root' '$PREFIX' && cd / && env -u PYTHONPATH $py -c '$pycheck'" 2>&1)
        then
            echo "installed Python package: imported by $py from ${pydir#"$stage"}: lambert reflects $out"
        else
            fail "python3 does not import the package installed in $PREFIX: $out"
        fi
    fi
else
    fail "$py lacks cffi or numpy (scripts/deps.sh)"
fi

# ---- uninstall leaves nothing ----
cd "$src"
make --no-print-directory -s uninstall BUILD="$BUILD" DESTDIR="$stage" > /dev/null 2>&1 || fail "make uninstall"
left=$(find "$stage$PREFIX" ! -type d)
[ -z "$left" ] || fail "make uninstall left: $left"

if [ $fails -gt 0 ]; then
    echo "$fails failure(s)"
    exit 1
fi
echo "install: tools, plug-ins, .pc, man pages and uninstall: ok"
