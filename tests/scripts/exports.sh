#!/bin/sh
# The shared library exports exactly the public API: the names that the headers of include/generic/ (and its kit/ and
# services/) declare with GENERIC_API (export.h), written out or by a macro, against `nm -D --defined-only` of
# libgeneric.so. Also checks that every function declared at file level in a public header carries GENERIC_API, so a
# declaration cannot silently miss it.
set -eu
BUILD=${1:-build}
so="$BUILD/lib/libgeneric.so"
[ -f "$so" ] || { echo "exports: $so not built"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Declarations: the headers as the library's compiler sees them (preprocessed with GENERIC_BUILD, where GENERIC_API
# is __attribute__((visibility("default")))), so that the declarations a macro writes count too (the methods of
# GMATERIAL_METHODS, material.h). Each statement with the mark, its attributes removed: the name is the identifier
# before the first '(' (a function) or before ';' / '[' / '=' (a variable).
for h in include/generic/*.h include/generic/*/*.h; do
    ${CC:-cc} -E -P -DGENERIC_BUILD -D_GNU_SOURCE -Iinclude -x c "$h" || { echo "exports: cannot preprocess $h"; exit 1; }
done > "$tmp/headers.i"
tr '\n' ' ' < "$tmp/headers.i" | sed 's/visibility *( *"default" *)/GENERIC_API_MARK/g' | tr ';{}' '\n\n\n' |
    grep GENERIC_API_MARK | sed -E 's/.*GENERIC_API_MARK//; s/__attribute__ *\(\(([^()]|\([^()]*\))*\)\)//g' | awk '{
    d = $0
    p = index(d, "(")
    if (p) d = substr(d, 1, p - 1); else { sub(/[;\[=].*/, "", d) }
    n = split(d, w, /[^A-Za-z0-9_]+/)
    for (i = n; i > 0; i--) if (w[i] != "") { print w[i]; break }
}' | sort -u > "$tmp/declared"

# Prototypes at file level without the macro: a line that starts with a type and has name( but is not a
# typedef, a macro, a static inline helper or inside a struct (those lines are indented).
grep -n -E '^[A-Za-z_][A-Za-z0-9_ \*]*[ \*]g[a-z0-9_]+\(' include/generic/*.h include/generic/*/*.h |
    grep -v -E ':(GENERIC_API|typedef|static|#)' > "$tmp/unmarked" || true
if [ -s "$tmp/unmarked" ]; then
    echo "exports: public declarations without GENERIC_API:"
    cat "$tmp/unmarked"
    exit 1
fi

# every defined dynamic symbol but the linker's own (C++ ones included: none may leak from the shims)
nm -D --defined-only "$so" | awk '$3 !~ /^(_init|_fini|__bss_start|_edata|_end)$/ { print $3 }' | sort -u > "$tmp/exported"

extra=$(comm -13 "$tmp/declared" "$tmp/exported")
missing=$(comm -23 "$tmp/declared" "$tmp/exported")
nd=$(wc -l < "$tmp/declared")
ne=$(wc -l < "$tmp/exported")
echo "exports: $nd declared with GENERIC_API, $ne exported by libgeneric.so"
status=0
if [ -n "$extra" ]; then
    echo "exports: exported but not public API:"; echo "$extra" | sed 's/^/  /'; status=1
fi
if [ -n "$missing" ]; then
    echo "exports: declared but not exported (or not defined):"; echo "$missing" | sed 's/^/  /'; status=1
fi
exit $status
