#!/bin/sh
# readme_examples.sh BUILD - the "Adding a ..." examples of README.md, built the two ways README promises.
#
# Every example is the complete source of one type: a fenced ```c block directly preceded by the line
#     <!-- readme-example: DIR/NAME.c -->
# (DIR: colormodels, materials or textures), with one or more GENERIC_TYPE / GENERIC_TYPE_NAMED (or *_PARAMS)
# records, and the README text right after it names the line `GENERIC_MODULE(&gtype_ID);` that makes it a module.
# Each is taken verbatim and
#   a) built-in: dropped into its DIR in a copy of the source tree, where `make lib` builds the library; a small
#      program then checks that each record is in the generated built-in list and registered by
#      generic_register_builtins(). The copy is compared with the tree: the examples must be the only change
#      (one new file each, no file edited). Skipped for a sanitizer build (it rebuilds the library, ~1 min).
#   b) module: compiled with that GENERIC_MODULE line appended as a .so against the staged public headers
#      (BUILD/plugins/include, as `make install` installs them) with -fvisibility=hidden, not linked with
#      libgeneric, exporting nothing but the module's two symbols; a program linked with BUILD/lib/libgeneric.a
#      (-rdynamic) loads it with gplugin_load and uses each type it registers: a colour model is created and
#      round-trips rgb; a material or node is read from a one-line file and evaluated; a generator is read
#      inside an interpolate node, which is evaluated. The one-line file is the example's "Text format:" line
#      when its comment has one (e.g. "Text format:  node NAME tint { child lambert }"), else the bare keyword.
set -eu
BUILD=${1:-build}
src=$(pwd)
readme="$src/README.md"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
problems=0
problem() { echo "readme_examples: $*" >&2; problems=$((problems + 1)); }
die() { echo "readme_examples: $*" >&2; exit 1; }

# ---- extraction: $tmp/examples/DIR/NAME.c, and $tmp/list with "DIR/NAME.c LINE" per example ----
mkdir -p "$tmp/examples"
awk -v out="$tmp/examples" -v list="$tmp/list" '
    function fail(msg) { printf "README.md:%d: %s\n", NR, msg > "/dev/stderr"; bad = 1 }
    state == 2 {
        if ($0 == "```") { close(file); state = 0; next }
        print > file; next
    }
    state == 1 {
        if ($0 != "```c") { fail("the line after a readme-example marker must open a ```c block"); state = 0; next }
        state = 2; next
    }
    /^<!-- readme-example:/ {
        if (!match($0, /^<!-- readme-example: (colormodels|materials|textures)\/[A-Za-z0-9_]+\.c -->$/)) {
            fail("malformed marker (expected <!-- readme-example: colormodels|materials|textures/NAME.c -->)")
            next
        }
        path = $3
        if (path in seen) { fail("example " path " given twice"); next }
        seen[path] = 1
        dir = path; sub(/\/.*/, "", dir)
        system("mkdir -p \"" out "/" dir "\"")
        file = out "/" path
        printf "%s %d\n", path, NR > list
        state = 1
    }
    END {
        if (state == 2) fail("the last example block is not closed")
        exit bad
    }' "$readme" || die "README.md has malformed examples (above)"
[ -s "$tmp/list" ] || die "README.md has no <!-- readme-example: DIR/NAME.c --> block"
n_examples=$(wc -l < "$tmp/list")

# The record ids of a source file, in order.
ids_of() {
    sed -n 's/^GENERIC_TYPE\(_NAMED\)\{0,1\}\(_PARAMS\)\{0,1\}([[:space:]]*\([A-Za-z_][A-Za-z0-9_]*\).*/\3/p' "$1"
}
# The GENERIC_MODULE line of an example: every record it has.
module_line() { printf 'GENERIC_MODULE(%s);\n' "$(ids_of "$1" | sed 's/^/\&gtype_/' | paste -sd, - | sed 's/,/, /g')"; }

while read -r path line; do
    f="$tmp/examples/$path"
    if [ -z "$(ids_of "$f")" ]; then
        problem "$path (README.md:$line): no GENERIC_TYPE record"
        continue
    fi
    # the text after the block must say which line makes it a module
    end=$(awk -v from="$line" 'NR > from + 1 && $0 == "```" { print NR; exit }' "$readme")
    for id in $(ids_of "$f"); do
        sed -n "$((end + 1)),$((end + 15))p" "$readme" | grep -qF "GENERIC_MODULE(&gtype_$id" ||
            problem "$path (README.md:$line): the text after it does not name the line GENERIC_MODULE(&gtype_$id);"
    done
    if [ -e "$src/$path" ]; then
        problem "$path (README.md:$line): the tree has that file already (an example must be a new type)"
    fi
done < "$tmp/list"
[ "$problems" -eq 0 ] || die "$problems problem(s) in README.md's examples"
echo "README.md: $n_examples example(s): $(cut -d' ' -f1 "$tmp/list" | paste -sd' ' -)"

# ---- linking a program against a libgeneric.a (flags as the Makefile's DEPLIBS; sanitizers when it has them) ----
san=""
nm -A "$BUILD/lib/libgeneric.a" 2>/dev/null | grep -q __asan_ && san="-fsanitize=address,undefined"
deplibs="-lpng -fopenmp -ldl -lpthread -lm"
link_program() { # out.c include-dir libgeneric.a out
    # shellcheck disable=SC2086
    cc -std=c11 -D_GNU_SOURCE -O0 -g -Wall -Wextra -Werror $san -I"$2" -rdynamic -o "$4" "$1" \
        -Wl,--whole-archive "$3" -Wl,--no-whole-archive $san $deplibs
}

# ---- a) built-in ----
if [ -n "$san" ]; then
    echo "built-in: skipped for a sanitizer build ($BUILD); the normal build checks it"
else
    tree="$tmp/tree"
    mkdir -p "$tree"
    dirs="include lib colormodels materials textures scripts share"
    for d in $dirs; do cp -R "$src/$d" "$tree/"; done
    # the build: the top Makefile, every folder's build.mk it includes, the pkg-config template
    (cd "$src" && find . -path ./build -prune -o -name build.mk -print) | while read -r f; do
        mkdir -p "$tree/$(dirname "$f")" && cp "$src/$f" "$tree/$f"
    done
    cp "$src/Makefile" "$src/generic.pc.in" "$tree/"
    while read -r path line; do cp "$tmp/examples/$path" "$tree/$path"; done < "$tmp/list"
    added=0
    edited=0
    for d in $dirs; do
        out=$(diff -rq "$src/$d" "$tree/$d" || true)
        added=$((added + $(printf '%s\n' "$out" | grep -c "^Only in $tree" || true)))
        edited=$((edited + $(printf '%s\n' "$out" | grep -c " differ$" || true)))
        if printf '%s\n' "$out" | grep -q "^Only in $src"; then problem "built-in: the copy of $d lacks files"; fi
    done
    echo "built-in: $added file(s) added, $edited file(s) edited in a copy of the tree"
    [ "$added" -eq "$n_examples" ] || problem "built-in: $added files added for $n_examples examples"
    [ "$edited" -eq 0 ] || problem "built-in: $edited files of the tree differ from the original"
    if ! (unset MAKEFLAGS MFLAGS MAKELEVEL; cd "$tree" && make -s -j2 lib OPT=-O0) > "$tmp/make.log" 2>&1; then
        tail -n 40 "$tmp/make.log" >&2
        die "built-in: make lib failed in the copy of the tree with the examples added"
    fi
    # the checker: each record in the generated list and registered under its name, with its own vtable
    {
        echo '#include <generic/builtins.h>'
        echo '#include <stdio.h>'
        while read -r path line; do
            for id in $(ids_of "$tmp/examples/$path"); do echo "extern const GTypeInfo gtype_$id;"; done
        done < "$tmp/list"
        cat <<'C'
static int check(const GTypeInfo *rec, const char *id, const char *file)
{
    int listed = 0;
    for (const GTypeInfo *const *t = generic_builtin_types(); *t; t++)
        listed |= *t == rec;
    GTypeInfo full = *rec;
    GError err;
    if (gtypeinfo_complete(&full, &err) != G_OK) {
        printf("%s: gtype_%s: %s\n", file, id, err.message);
        return 1;
    }
    const GTypeInfo *found = gregistry_find(rec->kind, full.name);
    if (!listed || !found || found->vtable != rec->vtable || found->parse != rec->parse) {
        printf("%s: gtype_%s ('%s') is %s\n", file, id, full.name,
               !listed ? "not in the generated built-in list" : "not registered by generic_register_builtins");
        return 1;
    }
    printf("built-in: %s registers %s '%s'\n", file, gkind_name(rec->kind), full.name);
    return 0;
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK) {
        printf("generic_register_builtins: %s\n", err.message);
        return 1;
    }
    int bad = 0;
C
        while read -r path line; do
            for id in $(ids_of "$tmp/examples/$path"); do echo "    bad += check(&gtype_$id, \"$id\", \"$path\");"; done
        done < "$tmp/list"
        echo '    return bad != 0;'
        echo '}'
    } > "$tmp/builtin_check.c"
    link_program "$tmp/builtin_check.c" "$tree/include" "$tree/build/lib/libgeneric.a" "$tmp/builtin_check" ||
        die "built-in: the checker does not build"
    "$tmp/builtin_check" || problem "built-in: some example types are not built in (above)"
fi

# ---- b) module ----
inc="$BUILD/plugins/include"
[ -f "$inc/generic/plugin.h" ] || die "module: $inc has no staged headers (run make first)"
cat > "$tmp/loader.c" <<'C'
/* loader MODULE.so [USAGE]: loads a module and uses every type it registers. */
#include <generic/builtins.h>
#include <generic/plugin.h>
#include <generic/reader.h>
#include <generic/surfpoint.h>
#include <generic/texture.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

static int fail(const char *what, const GError *err)
{
    printf("%s%s%s\n", what, err ? ": " : "", err ? err->message : "");
    return 1;
}

/* a colour model: greys and white light in any model; every colour when it has 3 values or more */
static int use_colormodel(const char *name)
{
    GColorModel *m;
    GError err;
    if (gcolormodel_create(name, NULL, &m, &err) != G_OK)
        return fail("gcolormodel_create", &err);
    GColor c;
    if (gcolor_alloc(&c, m) != G_OK) {
        gcolormodel_destroy(m);
        return fail("gcolor_alloc", NULL);
    }
    double worst = 0.0, worst_grey = 0.0, white[3] = {1, 1, 1}, xyz[3];
    for (int role = 0; role < 2; role++)
        for (int i = 0; i < 27; i++) {
            double in[3] = {i % 3 * 0.5, i / 3 % 3 * 0.5, i / 9 * 0.5}, out[3];
            if (gcolor_from_rgb(&c, in, (GColorRole)role) != G_OK || gcolor_to_rgb(&c, (GColorRole)role, out) != G_OK)
                out[0] = out[1] = out[2] = INFINITY; /* a failed conversion counts as the worst error */
            for (int k = 0; k < 3; k++) {
                double e = fabs(out[k] - in[k]);
                worst = fmax(worst, e);
                if (in[0] == in[1] && in[1] == in[2])
                    worst_grey = fmax(worst_grey, e);
            }
        }
    if (gcolor_from_rgb(&c, white, GCOLOR_LIGHT) != G_OK || gcolor_to_xyz(&c, GCOLOR_LIGHT, xyz) != G_OK)
        xyz[1] = INFINITY;
    printf("module: colormodel '%s': %d values, rgb round trip max error %.2g (greys %.2g), white light Y %.6f\n",
           name, m->nvalues, worst, worst_grey, xyz[1]);
    int bad = worst_grey > 1e-5 || fabs(xyz[1] - 1.0) > 1e-4 || (m->nvalues >= 3 && worst > 1e-5);
    gcolor_free(&c);
    gcolormodel_destroy(m);
    return bad ? fail("the round trip is not exact", NULL) : 0;
}

/* a material, node or generator: the value of the usage line (keyword and parameters), else the keyword */
static int use_entry(GKind kind, const char *name, const char *usage, const char *dir)
{
    char value[1024];
    int from_usage = 0;
    snprintf(value, sizeof value, "%s", name);
    char w1[128], w2[128];
    int n1 = 0;
    size_t len = strlen(name);
    if (usage && sscanf(usage, " %127s %n%127s", w1, &n1, w2) == 2 && strcmp(w1, gkind_name(kind)) == 0) {
        const char *rest = usage + n1; /* [NAME] TYPE ... */
        if (strcmp(w2, name) != 0)
            for (rest += strlen(w2); *rest == ' ' || *rest == '\t'; rest++)
                ;
        if (strncmp(rest, name, len) == 0 && (rest[len] == '\0' || rest[len] == ' ' || rest[len] == '\t'))
            from_usage = snprintf(value, sizeof value, "%s", rest) > 0;
    }
    char text[1400];
    if (kind == GKIND_GENERATOR)
        snprintf(text, sizeof text, "node readme_check interpolate { a lambert  b mirror  t %s }\n", value);
    else
        snprintf(text, sizeof text, "%s readme_check %s\n", gkind_name(kind), value);
    char path[4200];
    snprintf(path, sizeof path, "%s/readme_check.mat", dir);
    FILE *f = fopen(path, "w");
    if (!f || fputs(text, f) < 0 || fclose(f) != 0)
        return fail("cannot write the test file", NULL);
    GLibrary *lib;
    GError err;
    text[strlen(text) - 1] = '\0';
    if (greader_load_file(path, NULL, &lib, &err) != G_OK) {
        printf("reading \"%s\"%s: %s\n", text, !from_usage ? "" : " (the example's \"Text format:\" line)",
               err.message);
        return 1;
    }
    GMaterial *mat = glibrary_material(lib, "readme_check");
    const GColorModel *m = glibrary_colormodel(lib);
    GScratch *s = gscratch_create(0);
    int bad = !mat || !s;
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < 64 && !bad; i++) {
        GScratchMark mark = gscratch_mark(s);
        GSurfPoint sp;
        gsurfpoint_init(&sp, m, s);
        sp.geometric_normal = gvec3(0, 0, 1);
        sp.object_point = sp.point = gvec3(0.37 * i - 3.0, 0.11 * i, 0.05 * i);
        sp.dpdu = sp.object_dpdu = gvec3(1, 0, 0);
        sp.dpdv = sp.object_dpdv = gvec3(0, 1, 0);
        sp.u = (i % 8) / 8.0 + 0.01;
        sp.v = (i / 8) / 8.0 + 0.01;
        sp.material = mat;
        GColor illum, out;
        double rgb[3] = {1, 1, 1};
        bad |= gcolor_scratch(&illum, m, s) != G_OK || gcolor_scratch(&out, m, s) != G_OK;
        if (!bad) {
            bad |= gcolor_from_rgb(&illum, rgb, GCOLOR_LIGHT) != G_OK;
            GVec3 in = gvec3_normalize(gvec3(0.3, 0.1, 1)), view = gvec3_normalize(gvec3(-0.2, 0.4, 1));
            bad |= gmaterial_reflection(mat, &sp, in, &illum, view, &out) != G_OK || !gcolor_is_nonnegative(&out);
            double b = gcolor_brightness(&out);
            lo = fmin(lo, b);
            hi = fmax(hi, b);
            bad |= gmaterial_diffuse(mat, &sp, &out) != G_OK || !gcolor_is_finite(&out);
        }
        gscratch_release(s, mark);
    }
    printf("module: %s '%s' from \"%s\": reflection brightness %.4g..%.4g over 64 points%s\n", gkind_name(kind),
           name, text, lo, hi, bad ? ": FAILED (not finite and >= 0)" : "");
    gscratch_destroy(s);
    glibrary_destroy(lib);
    return bad;
}

int main(int argc, char **argv)
{
    if (argc < 3)
        return fail("usage: loader MODULE.so WORKDIR [USAGE]", NULL);
    GError err;
    if (generic_register_builtins(&err) != G_OK)
        return fail("generic_register_builtins", &err);
    const GTypeInfo *before[GKIND_MAX][256];
    int nbefore[GKIND_MAX];
    for (int k = 0; k < gkind_count(); k++)
        nbefore[k] = gregistry_list((GKind)k, before[k], 256);
    if (gplugin_load(argv[1], &err) != G_OK)
        return fail("gplugin_load", &err);
    int added = 0, bad = 0;
    for (int k = 0; k < gkind_count(); k++) {
        const GTypeInfo *now[256];
        int n = gregistry_list((GKind)k, now, 256);
        for (int i = nbefore[k]; i < n && i < 256; i++) {
            added++;
            if (k == GKIND_COLORMODEL)
                bad += use_colormodel(now[i]->name);
            else if (k == GKIND_MATERIAL || k == GKIND_NODE || k == GKIND_GENERATOR)
                bad += use_entry((GKind)k, now[i]->name, argc > 3 ? argv[3] : NULL, argv[2]);
            else
                printf("module: %s '%s' registered (not exercised)\n", gkind_name((GKind)k), now[i]->name);
        }
    }
    if (!added)
        return fail("the module registered no type", NULL);
    return bad != 0;
}
C
link_program "$tmp/loader.c" "$inc" "$BUILD/lib/libgeneric.a" "$tmp/loader" || die "module: the loader does not build"
mkdir -p "$tmp/modules"
while read -r path line; do
    name=$(basename "$path" .c)
    m="$tmp/modules/$name.c"
    { cat "$tmp/examples/$path"; module_line "$tmp/examples/$path"; } > "$m"
    # shellcheck disable=SC2086
    if ! cc -std=c11 -D_GNU_SOURCE -O2 -g -fPIC -shared -fvisibility=hidden -Wall -Wextra -Werror $san -I"$inc" \
            -o "$tmp/modules/$name.so" "$m" -lm 2> "$tmp/cc.log"; then
        cat "$tmp/cc.log" >&2
        problem "module: $path with '$(module_line "$tmp/examples/$path")' does not compile against $inc"
        continue
    fi
    exported=$(nm -D --defined-only "$tmp/modules/$name.so" | awk '{ print $NF }' | grep -v '^_' | sort | paste -sd' ' -)
    [ "$exported" = "generic_module_abi generic_module_init" ] ||
        problem "module: $name.so exports '$exported', not just generic_module_abi generic_module_init"
    usage=$(sed -n 's/.*Text format:[[:space:]]*//p' "$tmp/examples/$path" | head -n 1 | sed 's/[[:space:]]*\*\/[[:space:]]*$//')
    if ! "$tmp/loader" "$tmp/modules/$name.so" "$tmp/modules" "$usage"; then
        problem "module: $name.so does not load or its type does not work (above)"
    fi
done < "$tmp/list"

[ "$problems" -eq 0 ] || die "$problems problem(s)"
echo "readme_examples: $n_examples example(s) work as built-ins and as modules"
