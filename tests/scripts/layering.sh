#!/bin/sh
# The layering of docs/ARCHITECTURE.md: lib/ knows no concrete type, and a type file uses only public headers.
#   1. no file of lib/ includes anything from colormodels/, colors/, materials/ or textures/;
#   2. no object of lib/ refers to a symbol defined by an object of those directories (no link cycle);
#   3. every file of those directories includes only public headers (generic/...) and system headers.
set -eu
BUILD=${1:-build}
status=0
inc=$(grep -rn '#include' lib/ | grep -E '"(\.\./)*(colormodels|colors|materials|textures)/' || true)
if [ -n "$inc" ]; then
    echo "layering: lib/ includes concrete types:"; echo "$inc"; status=1
fi
# the objects of the sources that exist (a build tree may hold objects of files moved since)
objects() {
    for f in "$@"; do
        [ -f "$f" ] || continue
        o="$BUILD/obj/${f%.*}.o"
        [ -f "$o" ] || { echo "layering: $o is not built" >&2; return 1; }
        echo "$o"
    done
}
types=$(objects colormodels/*.c colors/*.c materials/*.c materials/*/*.c textures/*.c) || exit 1
core=$(objects lib/*/*.c lib/*/*.cpp) || exit 1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck disable=SC2086
nm --defined-only $types | awk 'NF == 3 && $2 ~ /[TDRB]/ { print $3 }' | sort -u > "$tmp/defined"
# shellcheck disable=SC2086
nm -u $core | awk '{ print $NF }' | sort -u > "$tmp/used"
cycle=$(comm -12 "$tmp/defined" "$tmp/used")
if [ -n "$cycle" ]; then
    echo "layering: lib/ refers to symbols of concrete types:"; echo "$cycle" | sed 's/^/  /'; status=1
fi
priv=$(grep -n '#include "' colormodels/*.c colors/*.c materials/*.c materials/*/*.c textures/*.c |
    grep -v '#include "generic/' || true)
if [ -n "$priv" ]; then
    echo "layering: type files include private headers:"; echo "$priv"; status=1
fi
n=$(echo "$types" | wc -w)
m=$(echo "$core" | wc -w)
[ $status -eq 0 ] && echo "layering: $m core objects refer to none of the $n type objects; type files use public headers only"
exit $status
