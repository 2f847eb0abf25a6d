#!/bin/sh
# Every file of colormodels/, colors/, materials/ and textures/ is one type that becomes a run-time module by one
# added line: each is copied alone into a scratch directory, compiled as it is against the public headers only (as
# `make install` installs them, BUILD/plugins/include), then given `GENERIC_MODULE(&gtype_ID, ...);` naming its
# records and compiled as a .so with -fvisibility=hidden. Each module must link with no symbol left over but
# the library's and libc/libm's, and load into a program whose registry holds every built-in except the
# module's own types: the module's vtables are registered (not the built-in ones) and a file using the type
# reads (examples/textures/NAME.txt, examples/materials/NAME.mat, for a colour literal examples/materials/colors.mat
# when it uses it, else a one-line default instance).
set -eu
BUILD=${1:-build}
inc="$BUILD/plugins/include"
[ -f "$inc/generic/kit/node_kit.h" ] || { echo "type_modules.sh: $inc is not made (run make all first)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# the loader is linked outside the build tree, so it is told where the OpenImageIO module is (image textures)
GENERIC_OIIO_MODULE="$(cd "$BUILD" && pwd)/lib/generic/libgeneric_oiio.so"
export GENERIC_OIIO_MODULE
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
        while (kind < gkind_count() && (strncmp(argv[i], gkind_name((GKind)kind), (size_t)(colon - argv[i])) != 0 ||
                                      gkind_name((GKind)kind)[colon - argv[i]] != '\0'))
            kind++;
        const GTypeInfo *t = kind < gkind_count() ? gregistry_find((GKind)kind, colon + 1) : NULL;
        for (int j = 0; t && b[j]; j++)
            if (b[j]->kind == t->kind && (t->vtable ? b[j]->vtable == t->vtable : b[j]->parse == t->parse))
                t = NULL; /* the built-in's record, not the module's */
        if (!t) {
            fprintf(stderr, "%s: %s is not registered from the module\n", argv[1], argv[i]);
            return 1;
        }
    }
    return 0;
}
C
cc $san -std=c11 -D_GNU_SOURCE -I"$inc" -rdynamic -o "$work/loader" "$work/loader.c" -Wl,--whole-archive \
    "$BUILD/lib/libgeneric.a" -Wl,--no-whole-archive -lpng -fopenmp \
    -ldl -lpthread -lm
# module DIR SRC: builds SRC (copied into DIR) as a built-in object and as a module, and loads the module.
n=0
module() {
    dir=$1 src=$2
    ids=$(sed -n 's/^GENERIC_TYPE\(_NAMED\)\{0,1\}\(_PARAMS\)\{0,1\}(\([A-Za-z_][A-Za-z0-9_]*\),.*/\3/p' "$src")
    [ -n "$ids" ] || { echo "type_modules.sh: $src has no GENERIC_TYPE record: every file here must be a type" >&2; exit 1; }
    base=$(basename "$src" .c)
    mkdir -p "$dir"
    cp "$src" "$dir/"
    # as a built-in: compiles against the public headers alone
    cc -std=c11 -D_GNU_SOURCE -fPIC -Wall -Wextra -Werror -I"$inc" -c -o "$dir/$base.o" "$dir/$base.c"
    echo "GENERIC_MODULE($(printf '&gtype_%s, ' $ids | sed 's/, $//'));" >> "$dir/$base.c"
    so="$dir/$base.so"
    cc -std=c11 -D_GNU_SOURCE -O1 -fPIC -shared -fvisibility=hidden -Wall -Wextra -Werror -I"$inc" \
        -o "$so" "$dir/$base.c" -lm
    # what it leaves unresolved must be the library's: the same link against libgeneric.so with --no-undefined
    cc -shared -o "$so.check" "$so" -Wl,--no-undefined -L"$BUILD/lib" -lgeneric -lm
    # KIND:NAME of each record, and a file that uses the first
    args=""
    example=""
    for id in $ids; do
        line=$(grep -E "^GENERIC_TYPE(_NAMED)?(_PARAMS)?\($id," "$src")
        kind=$(echo "$line" | sed 's/.*GKIND_\([A-Z]*\).*/\1/' | tr 'A-Z' 'a-z')
        case "$line" in
        GENERIC_TYPE_NAMED*) name=$(echo "$line" | sed 's/^[^"]*"\([^"]*\)".*/\1/') ;;
        *) # the keyword of the class named in the record
            cls=$(echo "$line" | sed 's/^[^,]*,[^,]*, *&\([A-Za-z_0-9]*\).*/\1/')
            name=$(awk -v c="$cls" '$0 ~ "GMaterialClass " c " =|GGeneratorClass " c " =|GColorModelClass " c " =|GNodeBlendClass " c " =" { on = 1 }
                on && /\.name = "/ { sub(/.*\.name = "/, ""); sub(/".*/, ""); print; exit }' "$src") ;;
        esac
        [ -n "$name" ] || { echo "type_modules.sh: cannot find the keyword of record $id in $src" >&2; exit 1; }
        args="$args $kind:$name"
        [ -n "$example" ] && continue
        case $kind in
        node | generator) [ -f "examples/textures/$name.txt" ] && example="examples/textures/$name.txt" ;;
        material) [ -f "examples/materials/$name.mat" ] && example="examples/materials/$name.mat" ;;
        color) grep -q -E "^color +[A-Za-z_]+ +$name( |\$)" examples/materials/colors.mat &&
            example="examples/materials/colors.mat" ;;
        esac
        if [ -z "$example" ]; then
            example="$dir/use.txt"
            case $kind in
            colormodel) printf 'colormodel %s\nmaterial m lambert { reflectance rgb 0.5 0.4 0.3 }\n' "$name" > "$example" ;;
            *) printf '%s m %s\n' "$kind" "$name" > "$example" ;;
            esac
        fi
    done
    "$work/loader" "$so" "$example" $args
    echo "module $base.so:$args built as a built-in and as a module, loaded, $example read"
    n=$((n + 1))
}
for src in colormodels/*.c colors/*.c materials/*.c materials/*/*.c textures/*.c; do
    [ -f "$src" ] || continue
    module "$work/${src%.c}" "$src" # colors/scale.c and textures/scale.c: a directory each
done
echo "$n type files built and loaded as modules"
