#!/bin/sh
# readme_examples.sh BUILD - the examples of README.md and docs/, run the way the documentation says.
#
# The documentation marks what it shows with an HTML comment on the line before a fenced block:
#   <!-- doc-example: DIR/NAME.c [as PATH] -->   a ```c block: the complete source of one new type (DIR:
#        colormodels, materials or textures), with GENERIC_TYPE / GENERIC_TYPE_NAMED records; the text right
#        after it names the line `GENERIC_MODULE(&gtype_ID);` that makes it a module. With `as PATH` a run
#        below (doc-run) also finds it at PATH.
#   <!-- doc-example-use: DIR/NAME.c -->   a ``` block: a file that uses the module of that example.
#   <!-- doc-file: PATH -->   a ``` block: a file the reader saves at PATH (relative to the top of the tree).
#   <!-- doc-run -->   a ```sh block: commands the reader runs from the top of the tree.
# Checks:
#   a) built-in: every doc-example dropped into its DIR in a copy of the source tree, where `make lib` builds the
#      library; a program checks that each record is in the generated built-in list and registered by
#      generic_register_builtins(). The copy must differ from the tree by the examples alone (one new file each).
#      Skipped for a sanitizer build (it rebuilds the library, ~1 min).
#   b) module: each doc-example with its GENERIC_MODULE line appended, compiled as a .so against the staged public
#      headers (BUILD/plugins/include, as `make install` installs them) with -fvisibility=hidden, not linked with
#      libgeneric, exporting nothing but the module's two symbols. A program linked with BUILD/lib/libgeneric.a
#      (-rdynamic) loads it with gplugin_load and uses each type it registers: a colour model is created and
#      round-trips rgb; a material or node is read from a one-line file and evaluated; a generator is read inside
#      an interpolate node, which is evaluated. The one-line file is the example's "Text format:" line when its
#      comment has one, else the bare keyword. Then the conformance checks run on each type: `gcolor check` on a
#      colour model, `gmat check` on that one-line entry.
#   c) use: each doc-example-use file is saved beside the example's module and read by `gmat list
#      --allow-plugins`; `gmat check` runs on every material and node it defines.
#   d) run: the doc-file and doc-run blocks of each page, in the page's order, as one shell script (`set -e`) in an
#      empty directory where `build` is BUILD and `examples` the tree's examples/: every command must succeed.
set -eu
BUILD=${1:-build}
src=$(pwd)
build_abs=$(cd "$BUILD" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
problems=0
problem() { echo "readme_examples: $*" >&2; problems=$((problems + 1)); }
die() { echo "readme_examples: $*" >&2; exit 1; }
# tools outside the build tree find the OpenImageIO module here (image textures, non-PNG output)
GENERIC_OIIO_MODULE="$build_abs/lib/generic/libgeneric_oiio.so"
export GENERIC_OIIO_MODULE

pages=""
for f in README.md docs/*.md docs/reference/*.md; do
    [ -f "$f" ] && pages="$pages $f"
done

# ---- extraction ----
# $tmp/examples/DIR/NAME.c and $tmp/list ("DIR/NAME.c PAGE LINE" per example); $tmp/uses/NAME.N.txt and
# $tmp/uselist ("DIR/NAME.c FILE PAGE LINE"); $tmp/run/PAGE.sh, the page's files and commands in order.
mkdir -p "$tmp/examples" "$tmp/uses" "$tmp/run"
: > "$tmp/list"
: > "$tmp/uselist"
for page in $pages; do
    runfile="$tmp/run/$(echo "$page" | tr '/' '_').sh"
    echo "$page" > "$runfile.page"
    awk -v out="$tmp/examples" -v list="$tmp/list" -v uses="$tmp/uses" -v uselist="$tmp/uselist" \
        -v run="$runfile" -v page="$page" '
    function fail(msg) { printf "%s:%d: %s\n", page, NR, msg > "/dev/stderr"; bad = 1 }
    function runline(s) { print s > run; nrun++ }
    function fence_ok(want) {
        if (want == "" ? $0 !~ /^```/ : $0 != "```" want) {
            fail("the line after a doc marker must open a ```" want " block"); state = 0; return 0
        }
        return 1
    }
    state == 2 {
        if ($0 == "```") {
            if (file != "") close(file)
            if (also != "") runline("DOC_FILE_END")
            state = 0; next
        }
        if (file != "") print > file
        if (also != "") runline($0)
        if (kind == "run") runline($0)
        next
    }
    state == 1 {
        if (!fence_ok(want)) next
        state = 2; next
    }
    /^<!-- readme-example/ { fail("readme-example markers are called doc-example now"); next }
    /^<!-- doc-example: / {
        if (!match($0, "^<!-- doc-example: (colormodels|materials|textures)/[A-Za-z0-9_]+[.]c" \
                       "( as [A-Za-z0-9_./-]+)? -->$")) {
            fail("malformed marker (expected <!-- doc-example: colormodels|materials|textures/NAME.c [as PATH] -->)")
            next
        }
        path = $3
        if (path in seen) { fail("example " path " given twice"); next }
        seen[path] = 1
        dir = path; sub(/\/.*/, "", dir)
        system("mkdir -p \"" out "/" dir "\"")
        file = out "/" path
        also = $4 == "as" ? $5 : ""
        if (also != "") {
            runline("mkdir -p \"$(dirname \"" also "\")\"")
            runline("cat > \"" also "\" <<\047DOC_FILE_END\047")
        }
        printf "%s %s %d\n", path, page, NR >> list
        kind = "example"; want = "c"; state = 1; next
    }
    /^<!-- doc-example-use: / {
        if (!match($0, /^<!-- doc-example-use: (colormodels|materials|textures)\/[A-Za-z0-9_]+\.c -->$/)) {
            fail("malformed marker (expected <!-- doc-example-use: DIR/NAME.c -->)"); next
        }
        nuse++
        name = $3; sub(/.*\//, "", name); sub(/\.c$/, "", name)
        file = uses "/" name "." nuse ".txt"; also = ""
        printf "%s %s %s %d\n", $3, file, page, NR >> uselist
        kind = "use"; want = ""; state = 1; next
    }
    /^<!-- doc-file: / {
        if (!match($0, /^<!-- doc-file: [A-Za-z0-9_.\/-]+ -->$/) || $3 ~ /^\// || $3 ~ /\.\./) {
            fail("malformed marker (expected <!-- doc-file: RELATIVE/PATH -->)"); next
        }
        file = ""; also = $3
        runline("mkdir -p \"$(dirname \"" also "\")\""); runline("cat > \"" also "\" <<\047DOC_FILE_END\047")
        kind = "file"; want = ""; state = 1; next
    }
    /^<!-- doc-run -->$/ { file = ""; also = ""; kind = "run"; want = "sh"; state = 1; next }
    /^<!-- doc-/ { fail("unknown doc marker: " $0); next }
    END {
        if (state != 0) fail("the last marked block is not closed")
        exit bad
    }' "$page" || die "$page has malformed doc markers (above)"
done
n_examples=$(wc -l < "$tmp/list")
[ "$n_examples" -gt 0 ] || die "no page has a <!-- doc-example: DIR/NAME.c --> block"

# The record ids of a source file, in order.
ids_of() {
    sed -n 's/^GENERIC_TYPE\(_NAMED\)\{0,1\}\(_PARAMS\)\{0,1\}([[:space:]]*\([A-Za-z_][A-Za-z0-9_]*\).*/\3/p' "$1"
}
# The GENERIC_MODULE line of an example: every record it has.
module_line() { printf 'GENERIC_MODULE(%s);\n' "$(ids_of "$1" | sed 's/^/\&gtype_/' | paste -sd, - | sed 's/,/, /g')"; }

while read -r path page line; do
    f="$tmp/examples/$path"
    if [ -z "$(ids_of "$f")" ]; then
        problem "$path ($page:$line): no GENERIC_TYPE record"
        continue
    fi
    # the text after the block must say which line makes it a module
    end=$(awk -v from="$line" 'NR > from + 1 && $0 == "```" { print NR; exit }' "$page")
    for id in $(ids_of "$f"); do
        sed -n "$((end + 1)),$((end + 15))p" "$page" | grep -qF "GENERIC_MODULE(&gtype_$id" ||
            problem "$path ($page:$line): the text after it does not name the line GENERIC_MODULE(&gtype_$id);"
    done
    if [ -e "$src/$path" ]; then
        problem "$path ($page:$line): the tree has that file already (an example must be a new type)"
    fi
done < "$tmp/list"
while read -r path file page line; do
    grep -q "^$path " "$tmp/list" || problem "$page:$line: doc-example-use of $path, which no doc-example gives"
done < "$tmp/uselist"
[ "$problems" -eq 0 ] || die "$problems problem(s) in the documentation's examples"
echo "examples: $n_examples: $(awk '{ printf "%s%s (%s)", (NR > 1 ? ", " : ""), $1, $2 }' "$tmp/list")"

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
    # the source tree without what builds and runs leave in it
    for e in "$src"/* "$src"/.[!.]*; do
        [ -e "$e" ] || continue
        case "$(basename "$e")" in build | out | try | .git) continue ;; esac
        cp -R "$e" "$tree/"
    done
    while read -r path page line; do cp "$tmp/examples/$path" "$tree/$path"; done < "$tmp/list"
    out=$(diff -rq -x build -x out -x try -x .git "$src" "$tree" || true)
    added=$(printf '%s\n' "$out" | grep -c "^Only in $tree" || true)
    edited=$(printf '%s\n' "$out" | grep -c " differ$" || true)
    if printf '%s\n' "$out" | grep -q "^Only in $src"; then problem "built-in: the copy of the tree lacks files"; fi
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
        while read -r path page line; do
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
        while read -r path page line; do
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
/* loader MODULE.so WORKDIR [USAGE]: loads a module and uses every type it registers; prints a line
 * `check colormodel NAME` or `check FILE ENTRY` for each type, for the conformance checks that follow. */
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
    printf("check colormodel %s\n", name); /* the script runs gcolor check on it */
    /* the sigmoid uplift (the kit's default) meets every colour but the perfect white within 1e-5: 1 1 1 comes back
     * as 0.99987 1.00005 0.99991 (docs/reference/colour.md, "RGB to spectrum") */
    int bad = worst_grey > 2e-4 || fabs(xyz[1] - 1.0) > 1e-4 || (m->nvalues >= 3 && worst > 2e-4);
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
    snprintf(path, sizeof path, "%s/check_%s.mat", dir, name);
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
    if (!bad) /* the script runs gmat check on it */
        printf("check %s %s\n", path, "readme_check");
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
while read -r path page line; do
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
    if ! "$tmp/loader" "$tmp/modules/$name.so" "$tmp/modules" "$usage" > "$tmp/loader.out" < /dev/null; then
        cat "$tmp/loader.out"
        problem "module: $name.so does not load or its type does not work (above)"
        continue
    fi
    grep -v '^check ' "$tmp/loader.out" || true
    # the conformance checks a type writer runs
    while read -r _ what entry; do
        if [ "$what" = colormodel ]; then
            cmd="gcolor check $entry"
            set -- "$BUILD/bin/gcolor" check "$entry"
        else
            cmd="gmat check $(basename "$what") $entry"
            set -- "$BUILD/bin/gmat" check "$what" "$entry"
        fi
        rc=0
        "$@" --plugin "$tmp/modules/$name.so" > "$tmp/check.out" 2>&1 < /dev/null || rc=$?
        if [ "$rc" -ne 0 ]; then
            cat "$tmp/check.out"
            problem "module: $cmd --plugin $name.so fails (status $rc, above)"
        else
            echo "module: $cmd --plugin $name.so: $(grep -c 'PASS' "$tmp/check.out") properties pass"
        fi
    done << CHECKS
$(grep '^check ' "$tmp/loader.out")
CHECKS
done < "$tmp/list"

# ---- c) use ----
while read -r path file page line; do
    name=$(basename "$path" .c)
    [ -f "$tmp/modules/$name.so" ] || continue # its module failed above
    use="$tmp/modules/use_$(basename "$file" .txt).mat"
    cp "$file" "$use"
    if ! "$BUILD/bin/gmat" list "$use" --allow-plugins > "$tmp/list.out" 2>&1 < /dev/null; then
        cat "$tmp/list.out"
        problem "use: $page:$line: gmat list --allow-plugins fails on it (above)"
        continue
    fi
    checked=0
    awk '$1 == "material" || $1 == "node" { print $2 }' "$tmp/list.out" > "$tmp/entries"
    while read -r entry; do
        if "$BUILD/bin/gmat" check "$use" "$entry" --allow-plugins > "$tmp/check.out" 2>&1 < /dev/null; then
            checked=$((checked + 1))
        else
            cat "$tmp/check.out"
            problem "use: $page:$line: gmat check fails on '$entry' (above)"
        fi
    done < "$tmp/entries"
    echo "use: $page:$line ($name.so): read, $checked entries pass gmat check"
done < "$tmp/uselist"

# ---- d) run ----
for script in "$tmp"/run/*.sh; do
    [ -s "$script" ] || continue
    page=$(cat "$script.page")
    work="$tmp/work/$(basename "$script" .sh)"
    mkdir -p "$work"
    ln -s "$build_abs" "$work/build"
    ln -s "$src/examples" "$work/examples"
    if (cd "$work" && sh -ex "$script") > "$tmp/run.log" 2>&1; then
        echo "run: $page: $(grep -c '^+ ' "$tmp/run.log") commands succeed"
    else
        tail -n 30 "$tmp/run.log" >&2
        problem "run: a command of $page fails (above; the last one shown)"
    fi
done

[ "$problems" -eq 0 ] || die "$problems problem(s)"
echo "readme_examples: $n_examples example(s) work as built-ins and as modules; every page's commands run"
