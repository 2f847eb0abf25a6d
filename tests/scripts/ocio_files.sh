#!/bin/sh
# ocio_files.sh BUILD - every LUT file an OpenColorIO config names is checked before OpenColorIO reads any
# (lib/image/ocio_display.cpp): a config whose colour space names a FIFO or /dev/zero (through a link) is refused
# with the file and the colour space named, and nothing is written, instead of blocking on the FIFO or reading
# gigabytes; the same config with a regular LUT renders. Under --confine DIR, a LUT outside DIR (at ../, through a
# symbolic link, by an absolute path) and a search path outside DIR are refused, naming the file and the folder.
BUILD=${1:-build}
GT="$BUILD/bin/gtrace"
. "$(dirname "$0")/prelude.sh"
need_program "$GT"
[ -f share/ocio/config.ocio ] || { echo "FAIL: run from the source tree (share/ocio/config.ocio)"; exit 1; }
GT="$(cd "$(dirname "$GT")" && pwd)/gtrace"
CONFIG="$(pwd)/share/ocio/config.ocio"
cd "$TMP" || exit 1
mkfifo fifo.cube
ln -s /dev/zero zero.cube
printf 'LUT_1D_SIZE 2\n0 0 0\n1 1 1\n' > ok.cube
for lut in ok fifo zero; do
    sed -e 's/search_path: ""/search_path: "."/' \
        -e 's/    - !<View> {name: Raw, colorspace: raw}/&\n    - !<View> {name: Lut, colorspace: lut}/' \
        -e 's/active_views: \[Standard, Log, Raw\]/active_views: [Standard, Log, Raw, Lut]/' \
        "$CONFIG" > $lut.ocio
    printf '\n  - !<ColorSpace>\n    name: lut\n    family: display\n    bitdepth: 32f\n    isdata: false\n' >> $lut.ocio
    printf '    from_scene_reference: !<FileTransform> {src: %s.cube, interpolation: linear}\n' $lut >> $lut.ocio
done
cat > s.scene << 'E'
camera pinhole { from <0, 0, 4> at <0, 0, 0> fov 40 width 8 height 6 spp 1 }
object sphere { center <0, 0, 0> radius 1 material lambert { reflectance rgb 0.5 0.5 0.5 } }
light point { position <2, 2, 4> intensity rgb 10 10 10 }
E
timeout 120 "$GT" s.scene -o ok.png -q --ocio-config ok.ocio --view Lut > out 2>&1 ||
    fail "a config with a regular LUT failed: $(cat out)"
[ -s ok.png ] || fail "a config with a regular LUT wrote no image"
for lut in fifo zero; do
    timeout 120 "$GT" s.scene -o $lut.png -q --ocio-config $lut.ocio --view Lut > out 2>&1
    st=$?
    [ $st -eq 1 ] || fail "$lut LUT: exit status $st, expected 1: $(cat out)"
    what=$([ $lut = fifo ] && echo "a FIFO" || echo "a device")
    grep -q "colour space 'lut' names \".*$lut.cube\", which is $what, not a regular file" out ||
        fail "$lut LUT: message: $(cat out)"
    [ -e $lut.png ] && fail "$lut LUT: an image was written"
done
# /dev/zero named directly
config_with() { # NAME SRC [SEARCH_PATH]: NAME.ocio whose colour space 'lut' reads SRC
    sed -e "s|search_path: \"\"|search_path: \"${3:-.}\"|" \
        -e 's/    - !<View> {name: Raw, colorspace: raw}/&\n    - !<View> {name: Lut, colorspace: lut}/' \
        -e 's/active_views: \[Standard, Log, Raw\]/active_views: [Standard, Log, Raw, Lut]/' "$CONFIG" > "$1.ocio"
    printf '\n  - !<ColorSpace>\n    name: lut\n    family: display\n    bitdepth: 32f\n    isdata: false\n' >> "$1.ocio"
    printf '    from_scene_reference: !<FileTransform> {src: %s, interpolation: linear}\n' "$2" >> "$1.ocio"
}
config_with devzero /dev/zero
timeout 120 "$GT" s.scene -o devzero.png -q --ocio-config devzero.ocio --view Lut > out 2>&1
st=$?
[ $st -eq 1 ] || fail "/dev/zero LUT: exit status $st, expected 1: $(cat out)"
grep -q "colour space 'lut' names \"/dev/zero\", which is a device, not a regular file" out ||
    fail "/dev/zero LUT: message: $(cat out)"
# under --confine DIR: LUTs and search paths outside DIR (../, a symbolic link, an absolute path) are refused with
# the file named; a LUT inside renders; a FIFO inside is still refused as a FIFO
mkdir -p in outside
cp s.scene in/
printf 'LUT_1D_SIZE 2\n0 0 0\n1 1 1\n' > outside/secret.cube
cp ok.cube in/ok.cube
ln -s "$TMP/outside/secret.cube" in/link.cube
mkfifo in/fifo.cube
cd in || exit 1
config_with inside ok.cube
config_with dotdot ../outside/secret.cube
config_with link link.cube
config_with absolute "$TMP/outside/secret.cube"
config_with search secret.cube ../outside
config_with fifo fifo.cube
timeout 120 "$GT" --confine . s.scene -o inside.png -q --ocio-config inside.ocio --view Lut > out 2>&1 ||
    fail "--confine: a LUT inside failed: $(cat out)"
[ -s inside.png ] || fail "--confine: a LUT inside wrote no image"
for c in dotdot link absolute search fifo; do
    timeout 120 "$GT" --confine . s.scene -o $c.png -q --ocio-config $c.ocio --view Lut > out 2>&1
    st=$?
    [ $st -eq 1 ] || fail "--confine, $c: exit status $st, expected 1: $(cat out)"
    case $c in
    search) expect='its search path "../outside" lies outside the confined folder . (--confine)' ;;
    fifo) expect="names \".*fifo.cube\", which is a FIFO, not a regular file" ;;
    *) expect="colour space 'lut' names \".*\", which lies outside the confined folder . (--confine)" ;;
    esac
    grep -q "$expect" out || fail "--confine, $c: message: $(cat out)"
    [ -e $c.png ] && fail "--confine, $c: an image was written"
done
# the same configs without --confine read the LUT outside (the rule is --confine's)
timeout 120 "$GT" s.scene -o dotdot.png -q --ocio-config dotdot.ocio --view Lut > out 2>&1 ||
    fail "a LUT at ../ without --confine failed: $(cat out)"
echo "ocio_files: LUTs that are a FIFO or a device, and under --confine LUTs and search paths outside the folder," \
     "refused before OpenColorIO reads them"
exit $fails
