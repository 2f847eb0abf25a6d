#!/bin/sh
# plugin_cli.sh BUILD - --plugin FILE.so on every tool and subcommand, the module search path
# (GENERIC_PLUGIN_PATH), the error for a missing module (it lists the directories searched), and colour models
# from modules chosen with --colormodel: gtrace after the scene's plugin statement, gmat swatch.
BUILD=$(cd "${1:-build}" 2> /dev/null && pwd) || { echo "FAIL: no build directory ${1:-build}"; exit 1; }
BIN="$BUILD/bin"
PLUGINS="$BUILD/plugins"
for t in gmat gcolor gprobe gtrace; do
    [ -x "$BIN/$t" ] || { echo "FAIL: $BIN/$t is not built"; exit 1; }
done
[ -f "$PLUGINS/grey.so" ] || { echo "FAIL: $PLUGINS/grey.so is not built"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
unset GENERIC_PLUGIN_PATH
fails=0
fail() {
    echo "FAIL: $*"
    fails=$((fails + 1))
}
cd "$TMP" || exit 1

# ---- gcolor: the module's model is listed, checked and reported ----
"$BIN/gcolor" list --plugin "$PLUGINS/grey.so" > out 2>&1 || fail "gcolor list --plugin: $(cat out)"
grep -qx grey out || fail "gcolor list --plugin grey.so does not list grey: $(cat out)"
"$BIN/gcolor" list > out 2>&1
grep -qx grey out && fail "gcolor list lists grey without the module"
"$BIN/gcolor" --plugin "$PLUGINS/grey.so" --models grey > out 2>&1 || fail "gcolor report --plugin: $(cat out)"
grep -q "== grey (1 values" out || fail "gcolor report does not report grey: $(cat out)"
"$BIN/gcolor" check grey --plugin "$PLUGINS/grey.so" > out 2>&1 || fail "gcolor check grey: $(cat out)"

# ---- gmat: every subcommand ----
cat > grey.mat << 'EOM'
material clay oren_nayar { reflectance rgb 0.7 0.5 0.4  sigma 20 }
EOM
ON="$PLUGINS/oren_nayar.so"
G="$PLUGINS/grey.so"
"$BIN/gmat" types --plugin "$ON" > out 2>&1 || fail "gmat types --plugin: $(cat out)"
grep -qx "material oren_nayar" out || fail "gmat types --plugin oren_nayar.so lacks it: $(cat out)"
"$BIN/gmat" list grey.mat --plugin "$ON" > out 2>&1 || fail "gmat list --plugin: $(cat out)"
grep -q "clay .*oren_nayar" out || fail "gmat list: $(cat out)"
"$BIN/gmat" eval grey.mat clay --in 30 --out 40,180 --plugin "$ON" --plugin "$G" --colormodel grey > out 2>&1 ||
    fail "gmat eval --plugin: $(cat out)"
grep -q "colour model grey" out || fail "gmat eval does not compute in grey: $(cat out)"
"$BIN/gmat" albedo grey.mat clay --in 30 --plugin "$ON" > out 2>&1 || fail "gmat albedo --plugin: $(cat out)"
"$BIN/gmat" plot grey.mat clay --in 30 -o plot.png --size 64 --plugin "$ON" > out 2>&1 || fail "gmat plot --plugin: $(cat out)"
"$BIN/gmat" check grey.mat clay --plugin "$ON" --plugin "$G" --colormodel grey --samples 16 > out 2>&1 ||
    fail "gmat check --plugin: $(cat out)"
"$BIN/gmat" swatch grey.mat clay -o swatch.png --size 16 --samples 1 --plugin "$ON" --plugin "$G" --colormodel grey \
    > out 2>&1 || fail "gmat swatch with the module's colour model: $(cat out)"
[ -s swatch.png ] || fail "gmat swatch --colormodel grey wrote no image"
"$BIN/gmat" laser grey.mat clay --elevation 30 --plugin "$ON" > out 2>&1 || fail "gmat laser --plugin: $(cat out)"
for cmd in eval albedo plot list check types swatch laser; do
    "$BIN/gmat" $cmd grey.mat clay --plugin nothere.so > out 2>&1 && fail "gmat $cmd --plugin nothere.so succeeded"
    grep -q "nothere.so" out || fail "gmat $cmd: the missing module is not named: $(cat out)"
done

# ---- gprobe: every subcommand loads before it runs ----
for cmd in eval approx irradiance convert compare sky; do
    "$BIN/gprobe" $cmd --plugin "$G" --help > out 2>&1 || fail "gprobe $cmd --plugin grey.so --help: $(cat out)"
    "$BIN/gprobe" $cmd --plugin nothere.so --help > out 2>&1 && fail "gprobe $cmd --plugin nothere.so succeeded"
    grep -q "cannot load module 'nothere.so'" out || fail "gprobe $cmd: no message for the missing module: $(cat out)"
done
"$BIN/gprobe" sky -o sky.hdr --height 16 --plugin "$G" > out 2>&1 || fail "gprobe sky --plugin: $(cat out)"

# ---- gtrace: --plugin, and --colormodel resolved after the scene's plugin statement ----
cat > scene.scene << 'EOM'
plugin "grey.so"
material matte lambert { reflectance rgb 0.5 0.5 0.5 }
camera pinhole { from <0, 1, 4> at <0, 0.5, 0> fov 40 width 16 height 12 spp 1 depth 2 }
object sphere { center <0, 0.5, 0> radius 0.5 material matte }
light point { position <2, 4, 3> intensity rgb 20 20 20 }
EOM
sed 1d scene.scene > plain.scene
"$BIN/gtrace" plain.scene -o plain.exr --plugin "$G" --colormodel grey > out 2>&1 || fail "gtrace --plugin --colormodel grey: $(cat out)"
grep -q "grey," out || fail "gtrace --plugin: not rendered in grey: $(cat out)"
GENERIC_PLUGIN_PATH="$PLUGINS" "$BIN/gtrace" scene.scene -o grey.exr --colormodel grey --allow-plugins > out 2>&1 ||
    fail "gtrace --colormodel grey with plugin \"grey.so\" in the scene: $(cat out)"
grep -q "16x12, 1 spp, depth 2, grey," out || fail "gtrace: the scene's module's model was not used: $(cat out)"
"$BIN/gtrace" plain.scene -o x.exr --plugin nothere.so > out 2>&1 && fail "gtrace --plugin nothere.so succeeded"

# ---- the search path: a bare name is found in GENERIC_PLUGIN_PATH, in order; errors list the directories ----
mkdir empty
GENERIC_PLUGIN_PATH="$TMP/empty:$PLUGINS" "$BIN/gcolor" list --plugin grey.so > out 2>&1 ||
    fail "a bare name in GENERIC_PLUGIN_PATH is not found: $(cat out)"
grep -qx grey out || fail "the module found on the path did not register grey: $(cat out)"
GENERIC_PLUGIN_PATH="$TMP/empty:/nonexistent/dir" "$BIN/gcolor" list --plugin grey.so > out 2>&1 &&
    fail "a module that is on no searched directory was found"
grep -q "cannot load module 'grey.so': file not found in $TMP/empty, /nonexistent/dir, .*, \. " out ||
    fail "the error does not list the directories searched: $(cat out)"
# a bare name: GENERIC_PLUGIN_PATH and the installed directory come before the base directory, so a module
# dropped beside a scene (or in the current directory) under an installed module's name is not taken
mkdir -p "$TMP/installed" "$TMP/here"
cp "$PLUGINS/bands.so" "$TMP/installed/grey.so"
cp "$PLUGINS/grey.so" "$TMP/here/grey.so"
(cd "$TMP/here" && GENERIC_PLUGIN_PATH="$TMP/installed" "$BIN/gcolor" list --plugin grey.so) > out 2>&1 ||
    fail "the module on GENERIC_PLUGIN_PATH did not load: $(cat out)"
grep -qx grey out && fail "the module in the current directory was taken before GENERIC_PLUGIN_PATH's: $(cat out)"
"$BIN/gcolor" list --plugin grey.so > out 2>&1 && fail "a bare name without GENERIC_PLUGIN_PATH was found"
grep -q "GENERIC_PLUGIN_PATH is not set" out || fail "the error does not say the path is unset: $(cat out)"
# a name with a slash is a path, never searched
GENERIC_PLUGIN_PATH="$PLUGINS" "$BIN/gcolor" list --plugin ./grey.so > out 2>&1 && fail "./grey.so was searched for"
# in a file: the file's directory first (a copy next to the scene), then the path
mkdir scenes
cp "$PLUGINS/grey.so" scenes/
cp scene.scene scenes/
(cd / && "$BIN/gtrace" "$TMP/scenes/scene.scene" -o "$TMP/next.exr" --colormodel grey -q --allow-plugins) > out 2>&1 ||
    fail "plugin \"grey.so\" next to the scene is not found: $(cat out)"
"$BIN/gtrace" scene.scene -o x.exr --allow-plugins > out 2>&1 && fail "plugin \"grey.so\" found without a path"
grep -q "scene.scene:1:8: cannot load module 'grey.so': file not found in .*\. (" out ||
    fail "a file's missing module: no positioned message listing the directory: $(cat out)"

if [ $fails -gt 0 ]; then
    echo "$fails failure(s)"
    exit 1
fi
echo "plugin_cli: all passed"
