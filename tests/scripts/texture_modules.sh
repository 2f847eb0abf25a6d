#!/bin/sh
# Every file of textures/ that holds type records (GENERIC_TYPE) becomes a run-time module by one added line:
# each is copied alone into a scratch directory, given `GENERIC_MODULE(&gtype_ID, ...);` naming its records,
# and compiled as a .so against the public headers only (as `make install` installs them, BUILD/plugins/include)
# with -fvisibility=hidden. Each module must link with no symbol left over but the library's and libc/libm's,
# and load into a program whose registry holds every built-in except the module's own types: the module's
# vtables are registered (not the built-in ones) and the type's example file examples/textures/NAME.txt reads.
# The README's node and generator examples get the same treatment, with the file that follows each.
set -eu
BUILD=${1:-build}
inc="$BUILD/plugins/include"
[ -f "$inc/generic/node_kit.h" ] || { echo "texture_modules.sh: $inc is not made (run make all first)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
san=""
nm -A "$BUILD/lib/libgeneric.a" 2>/dev/null | grep -q __asan_ && san="-fsanitize=address,undefined"
cat > "$work/loader.c" <<'C'
/* loader MODULE.so|- EXAMPLE.txt KIND:NAME...: registers every built-in but the named types, loads the module
 * (- : the example's plugin statement does), reads the example, and checks that each named type is registered
 * with the module's vtable, not a built-in one. */
#include <generic/builtins.h>
#include <generic/plugin.h>
#include <generic/reader.h>
#include <stdio.h>
#include <string.h>

static const char *key(const GTypeInfo *t, char *buf, size_t size)
{
    snprintf(buf, size, "%s:%s", gkind_name(t->kind), t->name ? t->name : ((const GClassHeader *)t->vtable)->name);
    return buf;
}

static int named(int argc, char **argv, const GTypeInfo *t)
{
    char k[128];
    for (int i = 3; i < argc; i++)
        if (strcmp(argv[i], key(t, k, sizeof k)) == 0)
            return 1;
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
    if (strcmp(argv[1], "-") != 0 && gplugin_load(argv[1], &err) != G_OK) {
        fprintf(stderr, "%s: %s\n", argv[1], err.message);
        return 1;
    }
    GLibrary *lib;
    GReaderOptions allow = {.allow_plugins = 1}; /* the example's plugin statement loads the module */
    if (greader_load_file(argv[2], &allow, &lib, &err) != G_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    glibrary_destroy(lib);
    for (int i = 3; i < argc; i++) {
        int kind = 0;
        const char *colon = strchr(argv[i], ':');
        while (kind < GKIND_COUNT && (strncmp(argv[i], gkind_name((GKind)kind), (size_t)(colon - argv[i])) != 0 ||
                                      gkind_name((GKind)kind)[colon - argv[i]] != '\0'))
            kind++;
        const GTypeInfo *t = kind < GKIND_COUNT ? gregistry_find((GKind)kind, colon + 1) : NULL;
        for (int j = 0; t && b[j]; j++)
            if (b[j]->vtable == t->vtable)
                t = NULL;
        if (!t) {
            fprintf(stderr, "%s: %s is not registered from the module\n", argv[1], argv[i]);
            return 1;
        }
    }
    return 0;
}
C
cc $san -std=c11 -D_GNU_SOURCE -I"$inc" -rdynamic -o "$work/loader" "$work/loader.c" -Wl,--whole-archive \
    "$BUILD/lib/libgeneric.a" -Wl,--no-whole-archive $(pkg-config --libs OpenImageIO 2>/dev/null) -lstdc++ -fopenmp \
    -ldl -lpthread -lm
# module DIR SRC EXAMPLE|-: builds SRC (copied into DIR) as a module and loads it; EXAMPLE - : DIR/use.txt, whose
# plugin statement loads it.
n=0
module() {
    dir=$1 src=$2 example=$3
    ids=$(sed -n 's/^GENERIC_TYPE(\([A-Za-z_][A-Za-z0-9_]*\),.*/\1/p' "$src")
    base=$(basename "$src" .c)
    mkdir -p "$dir"
    [ "$src" -ef "$dir/$base.c" ] || cp "$src" "$dir/"
    # as a built-in: compiles against the public headers alone
    cc -std=c11 -D_GNU_SOURCE -fPIC -Wall -Wextra -Werror -I"$inc" -c -o "$dir/$base.o" "$dir/$base.c"
    echo "GENERIC_MODULE($(printf '&gtype_%s, ' $ids | sed 's/, $//'));" >> "$dir/$base.c"
    so="$dir/$base.so"
    cc -std=c11 -D_GNU_SOURCE -O1 -fPIC -shared -fvisibility=hidden -Wall -Wextra -Werror -I"$inc" \
        -o "$so" "$dir/$base.c" -lm
    # what it leaves unresolved must be the library's: the same link against libgeneric.so with --no-undefined
    cc -shared -o "$so.check" "$so" -Wl,--no-undefined -L"$BUILD/lib" -lgeneric -lm
    # the kinds and keywords of the file's classes, for the loader
    kind=generator
    grep -q 'GKIND_NODE' "$src" && kind=node
    names=$(sed -n 's/^ *\.name = "\([^"]*\)",$/\1/p' "$src")
    args=""
    for nm in $names; do args="$args $kind:$nm"; done
    if [ "$example" = - ]; then
        "$work/loader" - "$dir/use.txt" $args
    else
        for nm in $names; do "$work/loader" "$so" "$example/$nm.txt" $args; done
    fi
    echo "module $base.so: $(echo $names | tr ' ' ',') built as a built-in and as a module, loaded, example read"
    n=$((n + 1))
}
for src in textures/*.c; do
    grep -q '^GENERIC_TYPE(' "$src" || continue
    module "$work/$(basename "$src" .c)" "$src" examples/textures
done
# The README's examples (<!-- readme-example: textures/NAME.c --> before the source, readme-example-use before a
# text file that uses it), verbatim.
for ex in $(sed -n 's/^<!-- readme-example: textures\/\([A-Za-z0-9_]*\)\.c -->$/\1/p' README.md); do
    mkdir -p "$work/readme/$ex"
    awk -v m="<!-- readme-example: textures/$ex.c -->" '$0 == m { on = 1; next } on == 1 && /^```/ { on = 2; next }
        on == 2 && /^```$/ { exit } on == 2 { print }' README.md > "$work/readme/$ex/$ex.c"
    awk -v m="<!-- readme-example-use: textures/$ex.c -->" '$0 == m { on = 1; next } on == 1 && /^```/ { on = 2; next }
        on == 2 && /^```$/ { exit } on == 2 { print }' README.md > "$work/readme/$ex/use.txt"
    [ -s "$work/readme/$ex/$ex.c" ] && [ -s "$work/readme/$ex/use.txt" ] || {
        echo "README example textures/$ex.c: source or use block missing" >&2
        exit 1
    }
    module "$work/readme/$ex" "$work/readme/$ex/$ex.c" -
done
echo "$n texture files built and loaded as modules"
