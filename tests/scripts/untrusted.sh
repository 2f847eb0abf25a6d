#!/bin/sh
# untrusted.sh BUILD - the tools on inputs that must not succeed wrongly or act without consent:
#   - gcolor: an unknown model is a usage error, a conversion that fails or overflows is reported for its sample
#     (never printed with another sample's values) and makes the exit status 1; magnitudes 1e0..1e300 either
#     convert to finite values or fail so;
#   - plug-ins: a `plugin` statement is refused without --allow-plugins or GENERIC_ALLOW_PLUGINS=1 (the message
#     names them); a file that is not a module is refused before its ELF constructor runs;
#   - --confine DIR: every path form that leaves DIR (../, absolute, a symbolic link, a module found elsewhere)
#     is refused at its name for includes, BFC files, images, meshes and plug-ins; paths inside DIR still work;
#   - gtrace's mesh reader process: one that crashes on a file (GENERIC_DECODE_FAULT=by-name) is a refusal of that
#     file at its entry, naming how the reader ended;
#   - messages: control characters of a file name are escaped, and nothing of a file that does not begin with
#     a statement (or of a BFC file before its grid line) is quoted.
SRC=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=$(cd "${1:-build}" 2> /dev/null && pwd) || { echo "FAIL: no build directory ${1:-build}"; exit 1; }
GCOLOR="$BUILD/bin/gcolor"
GMAT="$BUILD/bin/gmat"
GTRACE="$BUILD/bin/gtrace"
PLUGINS="$BUILD/plugins"
for t in "$GCOLOR" "$GMAT" "$GTRACE"; do
    [ -x "$t" ] || { echo "FAIL: $t is not built"; exit 1; }
done
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fails=0
checked=0
fail() {
    echo "FAIL: $*"
    fails=$((fails + 1))
}
# expect STATUS WHAT COMMAND...: runs COMMAND (stdout in $TMP/out, stderr in $TMP/err), checks its exit status
expect() {
    want=$1
    what=$2
    shift 2
    "$@" > "$TMP/out" 2> "$TMP/err"
    st=$?
    checked=$((checked + 1))
    [ "$st" -eq "$want" ] || fail "$what: exit status $st, expected $want: $(head -c 2000 "$TMP/err")"
    if grep -q -E "Sanitizer|runtime error:" "$TMP/err"; then
        fail "$what: sanitizer report: $(head -c 2000 "$TMP/err")"
    fi
}
has() { # WHAT FILE TEXT: FILE contains TEXT
    grep -q -F -- "$3" "$2" || fail "$1: expected '$3' in: $(head -c 2000 "$2")"
}

# ---- gcolor ----
expect 2 "gcolor --models with an unknown model" "$GCOLOR" --models rgb,nosuch
has "gcolor --models rgb,nosuch" "$TMP/err" "gcolor: --models: unknown colour model 'nosuch' (registered: "
[ -s "$TMP/out" ] && fail "gcolor --models rgb,nosuch printed a report: $(cat "$TMP/out")"
expect 2 "gcolor --rgb nan" "$GCOLOR" --rgb nan,0,0
expect 1 "gcolor --rgb 1e300" "$GCOLOR" --models rgb,spectrum --rgb 1e300,0,0 --rgb 0.5,0.5,0.5
has "gcolor --rgb 1e300" "$TMP/out" "rgb 1e300,0,0      conversion to sRGB and XYZ failed"
has "gcolor --rgb 1e300" "$TMP/out" "rgb 0.5,0.5,0.5    brightness 0.5000  -> sRGB 0.5000 0.5000 0.5000"
has "gcolor --rgb 1e300" "$TMP/err" "gcolor: spectrum: 'rgb 1e300,0,0': the conversion to sRGB and XYZ failed"
e=0
while [ $e -le 300 ]; do # every magnitude: finite values and status 0, or the sample failed and status 1
    "$GCOLOR" --rgb "1e$e,1e$e,0" > "$TMP/out" 2> "$TMP/err"
    st=$?
    checked=$((checked + 1))
    grep -i -q -E "inf|nan" "$TMP/out" && fail "gcolor --rgb 1e$e printed a value that is not finite: $(cat "$TMP/out")"
    if [ $st -eq 0 ]; then
        grep -q "failed" "$TMP/out" && fail "gcolor --rgb 1e$e: a failed sample with status 0"
    elif [ $st -eq 1 ]; then
        grep -q "conversion .* failed" "$TMP/out" || fail "gcolor --rgb 1e$e: status 1 without a failed sample"
    else
        fail "gcolor --rgb 1e$e: exit status $st: $(cat "$TMP/err")"
    fi
    e=$((e + 20))
done

# ---- plug-ins need consent ----
cd "$TMP" || exit 1
cp "$PLUGINS/grey.so" "$TMP/grey.so"
printf 'plugin "grey.so"\nmaterial m lambert\n' > uses_plugin.mat
expect 1 "a plugin statement without consent" "$GMAT" list uses_plugin.mat
has "plugin statement without consent" "$TMP/err" "gmat: uses_plugin.mat:1:8: plugin statements are not allowed: a module runs native code, so a file may load one only with consent (--allow-plugins, GENERIC_ALLOW_PLUGINS=1"
expect 0 "a plugin statement with --allow-plugins" "$GMAT" list uses_plugin.mat --allow-plugins
GENERIC_ALLOW_PLUGINS=1 expect 0 "a plugin statement with GENERIC_ALLOW_PLUGINS=1" "$GMAT" list uses_plugin.mat
GENERIC_ALLOW_PLUGINS=yes expect 1 "GENERIC_ALLOW_PLUGINS=yes (only 1 allows)" "$GMAT" list uses_plugin.mat
printf 'plugin "nothere.so"\n' > missing_plugin.mat
expect 1 "a missing module with --allow-plugins" "$GMAT" list missing_plugin.mat --allow-plugins
has "a missing module" "$TMP/err" "cannot load module 'nothere.so': file not found in"
for so in constructor_only bad_abi no_init; do # refused before any of their code runs
    rm -f "$TMP/ran"
    printf 'plugin "%s"\n' "$PLUGINS/$so.so" > "p_$so.mat"
    GENERIC_TEST_CONSTRUCTOR_MARK="$TMP/ran" expect 1 "plugin $so.so" "$GMAT" list "p_$so.mat" --allow-plugins
    has "plugin $so.so" "$TMP/err" "nothing of it was run"
    [ -e "$TMP/ran" ] && fail "plugin $so.so: its ELF constructor ran"
    GENERIC_TEST_CONSTRUCTOR_MARK="$TMP/ran" expect 1 "--plugin $so.so" "$GMAT" list uses_plugin.mat --plugin "$PLUGINS/$so.so"
    [ -e "$TMP/ran" ] && fail "--plugin $so.so: its ELF constructor ran"
done
rm -f "$TMP/ran"
GENERIC_TEST_CONSTRUCTOR_MARK="$TMP/ran" expect 2 "plugin failing_init.so (a module: it runs)" "$GMAT" list \
    uses_plugin.mat --plugin "$PLUGINS/failing_init.so"
[ -e "$TMP/ran" ] || fail "the constructor marker does not work: failing_init.so's constructor did not run"

# ---- --confine DIR ----
mkdir -p box/sub box/data outside
cp "$SRC/tests/bad/tiny.BFC" box/data/tiny.BFC
cp "$SRC/tests/bad/tiny.BFC" outside/tiny.BFC
cp "$SRC/examples/textures/picture.png" box/data/picture.png
cp "$SRC/examples/textures/picture.png" outside/picture.png
cp "$PLUGINS/grey.so" outside/grey.so
printf 'material inner lambert\n' > box/sub/inner.mat
printf 'material secret_outer lambert\n' > outside/outer.mat
ln -s ../outside box/escape
ln -s sub box/alias
# confined ITEM PATH WANT: a file in box/ that reads PATH (as ITEM: include, bfc, image, plugin); WANT in|out
n=0
confined() {
    n=$((n + 1))
    case $1 in
    include) printf 'include "%s"\nmaterial m lambert\n' "$2" > "box/c$n.mat" ;;
    bfc) printf 'color c bfc "%s"\nmaterial m lambert { reflectance c }\n' "$2" > "box/c$n.mat" ;;
    image) printf 'node m image { child lambert file "%s" }\n' "$2" > "box/c$n.mat" ;;
    plugin) printf 'plugin "%s"\nmaterial m lambert\n' "$2" > "box/c$n.mat" ;;
    esac
    if [ "$3" = in ]; then
        expect 0 "--confine box: $1 \"$2\"" "$GMAT" list "box/c$n.mat" --confine box --allow-plugins
    else
        expect 1 "--confine box: $1 \"$2\"" "$GMAT" list "box/c$n.mat" --confine box --allow-plugins
        has "--confine box: $1 \"$2\"" "$TMP/err" "is outside the directory the load is confined to"
        grep -q -E "^gmat: box/c$n.mat:[0-9]+:[0-9]+: " "$TMP/err" || fail "--confine: $1 \"$2\": no file:line:col: $(cat "$TMP/err")"
        # the same file loads without --confine (the path itself is fine)
        expect 0 "without --confine: $1 \"$2\"" "$GMAT" list "box/c$n.mat" --allow-plugins
    fi
}
for p in sub/inner.mat ./sub/inner.mat sub/../sub/inner.mat alias/inner.mat "$TMP/box/sub/inner.mat"; do
    confined include "$p" in
done
for p in ../outside/outer.mat sub/../../outside/outer.mat escape/outer.mat "$TMP/outside/outer.mat" \
    alias/../../outside/outer.mat; do
    confined include "$p" out
done
confined bfc data/tiny.BFC in
confined bfc ../outside/tiny.BFC out
confined bfc escape/tiny.BFC out
confined image data/picture.png in
confined image ../outside/picture.png out
confined image "$TMP/outside/picture.png" out
confined plugin ../outside/grey.so out
printf 'plugin "grey.so"\nmaterial m lambert\n' > box/bare.mat
GENERIC_PLUGIN_PATH="$TMP/outside" expect 0 "without --confine: plugin \"grey.so\" from GENERIC_PLUGIN_PATH" \
    "$GMAT" list box/bare.mat --allow-plugins
GENERIC_PLUGIN_PATH="$TMP/outside" expect 1 "--confine: plugin \"grey.so\" from GENERIC_PLUGIN_PATH" \
    "$GMAT" list box/bare.mat --confine box --allow-plugins
has "--confine: a module from GENERIC_PLUGIN_PATH" "$TMP/err" "is outside the directory the load is confined to"
expect 1 "--confine: the file itself outside" "$GMAT" list outside/outer.mat --confine box
has "--confine: the file itself" "$TMP/err" "is outside the directory the load is confined to"
expect 2 "--confine a file" "$GMAT" list box/sub/inner.mat --confine box/sub/inner.mat
has "--confine a file" "$TMP/err" "not a directory"
# gtrace: a mesh outside the directory
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > outside/tri.obj
cat > box/mesh.scene << 'EOM'
camera pinhole { from <0, 0, 3> at <0, 0, 0> fov 40 width 8 height 8 spp 1 depth 1 }
object mesh { file "../outside/tri.obj" material lambert }
light point { position <0, 2, 3> intensity rgb 10 10 10 }
EOM
expect 1 "gtrace --confine: a mesh outside" "$GTRACE" box/mesh.scene -o "$TMP/mesh.png" -q --confine box
has "gtrace --confine: a mesh outside" "$TMP/err" "is outside the directory the load is confined to"
expect 0 "gtrace without --confine: the same mesh" "$GTRACE" box/mesh.scene -o "$TMP/mesh.png" -q
# gtrace: a PLY whose reader process crashes
{
    printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n'
    printf 'element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n'
} > box/fault-crash.ply
sed 's|"../outside/tri.obj"|"fault-crash.ply"|' box/mesh.scene > box/crash.scene
GENERIC_DECODE_FAULT=by-name expect 1 "gtrace: a mesh reader that crashes" "$GTRACE" box/crash.scene -o "$TMP/c.png" \
    -q
# under AddressSanitizer the reader's fault is caught by the sanitizer, which reports it and exits 1
if nm -A "$BUILD/lib/libgeneric.a" 2> /dev/null | grep -q __asan_; then
    crash_end="ended (exit status 1) without an answer"
else
    crash_end="crashed (Segmentation fault)"
fi
has "a mesh reader that crashes" "$TMP/err" \
    "box/crash.scene:2:15: box/fault-crash.ply: cannot read mesh: its reader gtrace-mesh $crash_end"
expect 0 "gtrace: the same mesh, its reader sound" "$GTRACE" box/crash.scene -o "$TMP/c.png" -q

# ---- messages quote nothing raw ----
esc=$(printf 'x\033[31mred')
printf 'material m lambert {\n' > "$esc.mat"
expect 1 "a file name with ESC bytes" "$GMAT" list "$esc.mat"
grep -q "$(printf '\033')" "$TMP/err" && fail "a file name with ESC bytes: the raw byte is printed: $(cat -v "$TMP/err")"
has "a file name with ESC bytes" "$TMP/err" 'x\x1b[31mred.mat'
printf 'include "%s"\n' "$(printf 'no\033]0;title\007such')" > esc_include.mat
expect 1 "an include of a name with control characters" "$GMAT" list esc_include.mat
grep -q "$(printf '\033')" "$TMP/err" && fail "include with ESC: the raw byte is printed: $(cat -v "$TMP/err")"
for i in 1 2 3 4 5 6 7 8 9 10 11 12; do echo "user$i:topsecret$i:/home/user$i:/bin/sh"; done > foreign.txt
printf '1.2.3 topsecret\n' > foreign_number.txt
printf '"topsecret string\n' > foreign_string.txt
for f in foreign.txt foreign_number.txt foreign_string.txt; do
    printf 'include "%s"\n' "$f" > "inc_$f.mat"
    expect 1 "include of $f" "$GMAT" list "inc_$f.mat"
    grep -q "topsecret" "$TMP/err" && fail "include of $f: its text is quoted: $(cat "$TMP/err")"
    has "include of $f" "$TMP/err" "$f:1:1: not a libgeneric text file: it does not begin with a statement"
    printf 'color c bfc "%s"\n' "$f" > "bfc_$f.mat"
    expect 1 "bfc of $f" "$GMAT" list "bfc_$f.mat"
    grep -q "topsecret" "$TMP/err" && fail "bfc of $f: its text is quoted: $(cat "$TMP/err")"
done

echo "$checked runs checked, $fails failures"
[ $fails -eq 0 ]
