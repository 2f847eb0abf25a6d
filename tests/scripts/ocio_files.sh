#!/bin/sh
# ocio_files.sh BUILD - every LUT file an OpenColorIO config names is checked before OpenColorIO reads any
# (lib/image/ocio_display.cpp): a config whose colour space names a FIFO or /dev/zero (through a link) is refused
# with the file and the colour space named, and nothing is written, instead of blocking on the FIFO or reading
# gigabytes; the same config with a regular LUT renders.
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
echo "ocio_files: LUTs that are a FIFO or a device refused before OpenColorIO reads them"
exit $fails
