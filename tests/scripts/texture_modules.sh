#!/bin/sh
# Every file of textures/ that holds type records (GENERIC_TYPE) becomes a run-time module by one added line:
# each is copied alone into a scratch directory, given `GENERIC_MODULE(&gtype_ID, ...);` naming its records,
# and compiled as a .so against the public headers only (as `make install` installs them, BUILD/plugins/include)
# with -fvisibility=hidden. Each module must link with no symbol left over but the library's and libc/libm's,
# and load into a program whose registry holds every built-in except the module's own types: the module's
# vtables are registered (not the built-in ones) and the type's example file examples/textures/NAME.txt reads.
set -eu
BUILD=${1:-build}
inc="$BUILD/plugins/include"
[ -f "$inc/generic/node_kit.h" ] || { echo "texture_modules.sh: $inc is not made (run make all first)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
san=""
nm -A "$BUILD/lib/libgeneric.a" 2>/dev/null | grep -q __asan_ && san="-fsanitize=address,undefined"
cat > "$work/loader.c" <<'C'
/* loader MODULE.so EXAMPLE.txt KIND:NAME...: registers every built-in but the named types, loads the module, checks
 * that the named types are the module's, reads the example. */
#include <generic/builtins.h>
#include <generic/plugin.h>
#include <generic/reader.h>
#include <stdio.h>
#include <string.h>

static int named(int argc, char **argv, const GTypeInfo *t)
{
    for (int i = 3; i < argc; i++) {
        char want[128];
        snprintf(want, sizeof want, "%s:%s", gkind_name(t->kind), t->name ? t->name : ((const GClassHeader *)t->vtable)->name);
        if (strcmp(argv[i], want) == 0)
            return 1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    GError err = {0};
    const GTypeInfo *const *b = generic_builtin_types();
    for (int i = 0; b[i]; i++)
        if (!named(argc, argv, b[i]) && gregistry_add(b[i], &err) != G_OK) {
            fprintf(stderr, "%s\n", err.message);
            return 1;
        }
    if (gplugin_load(argv[1], &err) != G_OK) {
        fprintf(stderr, "%s: %s\n", argv[1], err.message);
        return 1;
    }
    int found = 0;
    for (int i = 0; b[i]; i++) {
        if (!named(argc, argv, b[i]))
            continue;
        const char *name = ((const GClassHeader *)b[i]->vtable)->name;
        const GTypeInfo *t = gregistry_find(b[i]->kind, name);
        if (!t || t->vtable == b[i]->vtable) {
            fprintf(stderr, "%s: %s is %s\n", argv[1], name, t ? "the built-in" : "not registered");
            return 1;
        }
        found++;
    }
    if (found != argc - 3) {
        fprintf(stderr, "%s: %d of %d types found among the built-ins\n", argv[1], found, argc - 3);
        return 1;
    }
    GLibrary *lib;
    if (greader_load_file(argv[2], NULL, &lib, &err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    glibrary_destroy(lib);
    return 0;
}
C
cc $san -std=c11 -D_GNU_SOURCE -I"$inc" -rdynamic -o "$work/loader" "$work/loader.c" -Wl,--whole-archive \
    "$BUILD/lib/libgeneric.a" -Wl,--no-whole-archive $(pkg-config --libs OpenImageIO 2>/dev/null) -lstdc++ -fopenmp \
    -ldl -lpthread -lm
n=0
for src in textures/*.c; do
    ids=$(sed -n 's/^GENERIC_TYPE(\([A-Za-z_][A-Za-z0-9_]*\),.*/\1/p' "$src")
    [ -n "$ids" ] || continue
    base=$(basename "$src" .c)
    mkdir -p "$work/$base"
    cp "$src" "$work/$base/"
    echo "GENERIC_MODULE($(printf '&gtype_%s, ' $ids | sed 's/, $//'));" >> "$work/$base/$base.c"
    so="$work/$base/$base.so"
    cc -std=c11 -D_GNU_SOURCE -O1 -fPIC -shared -fvisibility=hidden -Wall -Wextra -Werror -I"$inc" \
        -o "$so" "$work/$base/$base.c" -lm
    # what it leaves unresolved must be the library's: the same link against libgeneric.so with --no-undefined
    cc -shared -o "$so.check" "$so" -Wl,--no-undefined -L"$BUILD/lib" -lgeneric -lm
    # the kinds and keywords of the file's classes, for the loader
    kind=generator
    grep -q 'GKIND_NODE' "$src" && kind=node
    names=$(sed -n 's/^ *\.name = "\([^"]*\)",$/\1/p' "$src")
    args=""
    for nm in $names; do args="$args $kind:$nm"; done
    for nm in $names; do
        "$work/loader" "$so" "examples/textures/$nm.txt" $args
    done
    echo "module $base.so: $(echo $names | tr ' ' ',') loaded in place of the built-in, examples read"
    n=$((n + 1))
done
echo "$n texture files built and loaded as modules"
