#!/bin/sh
# limits.sh BUILD - generated inputs with values the dependencies do not accept, work out of proportion and
# misleading messages: cameras, lights and objects far away or overflowing (Embree would abort), OBJ indices at
# the ends of the integer range, NUL bytes and out-of-range numbers in OBJ files, UTF-8 byte-order marks in
# every text format, BFC grids far outside the spectrum, huge noise parameters, a tower of nested glass at depth
# 1000 with cutoff 0, an irradiance fit of 4096 lights on 8192 normals. Each run must end (within a time
# bound), with status < 128, no sanitizer report, and the exact message.
BUILD=$(cd "${1:-build}" 2> /dev/null && pwd) || { echo "FAIL: no build directory ${1:-build}"; exit 1; }
GTRACE="$BUILD/bin/gtrace"
GMAT="$BUILD/bin/gmat"
GPROBE="$BUILD/bin/gprobe"
SRC=$(cd "$(dirname "$0")/../.." && pwd)
. "$(dirname "$0")/prelude.sh"
serial_only
cd "$TMP" || exit 1

expect() { # WHAT TEXT: stderr holds TEXT
    grep -q -F -- "$2" err || fail "$1: expected '$2', got: $(head -c 1500 err)"
}

# ---- class 3: coordinates Embree does not accept, refused at file:line:col ----
cam() { # FROM AT
    printf 'camera pinhole { from %s at %s fov 35 width 8 height 6 spp 1 depth 2 }\n' "$1" "$2"
    printf 'object sphere { center <0, 0, 0> radius 1 material lambert }\n'
}
for from in "<0, 0, 1.8e18>" "<0, 0, 2e18>" "<0, 0, 1e308>" "<1e16, 0, 0>"; do
    cam "$from" "<0, 0, 0>" > far.scene
    bounded_run "camera from $from" 1 30 "$GTRACE" far.scene -o far.png -q
    expect "camera from $from" "gtrace: far.scene:1:"
    expect "camera from $from" ": the camera's from, at and up must be finite and within [-1e+15, 1e+15]"
done
cam "<0, 0, 1e308>" "<0, 0, -1e308>" > over.scene
bounded_run "camera from 1e308 at -1e308" 1 30 "$GTRACE" over.scene -o far.png -q
expect "camera overflowing" "gtrace: over.scene:1:93: the camera's from, at and up must be finite and within [-1e+15, 1e+15]"
for t in "translate <1e300, 0, 0>" "scale 1e14 translate <9.5e14, 0, 0>" "rotate_axis <0, 0, 1> 45 translate <1e15, 0, 0>"; do
    printf 'camera pinhole { from <0, 0, 5> at <0, 0, 0> width 8 height 6 }\n' > xf.scene
    printf 'object sphere { center <0, 0, 0> radius 1 material lambert transform { %s } }\n' "$t" >> xf.scene
    bounded_run "transform $t" 1 30 "$GTRACE" xf.scene -o far.png -q
    expect "transform $t" "xf.scene:2:"
    expect "transform $t" "(after its transform), beyond the scene's limit of 1e+15"
done
printf 'camera pinhole { from <0, 0, 5> at <0, 0, 0> width 8 height 6 }\nobject sphere { material lambert }\n' > light.scene
printf 'light point { position <0, 1e300, 0> intensity rgb 1 1 1 }\n' >> light.scene
bounded_run "a light at 1e300" 1 30 "$GTRACE" light.scene -o far.png -q
expect "a light at 1e300" "light.scene:3:58: the light lies beyond the scene's limit of 1e+15"
# just inside the bound: renders
printf 'camera pinhole { from <0, 0, 9e14> at <0, 0, 0> fov 1 width 8 height 6 }\n' > near.scene
printf 'object sphere { center <0, 0, 0> radius 1e13 material lambert }\nlight point { position <0, 0, 9e14> intensity rgb 1e30 1e30 1e30 }\n' >> near.scene
bounded_run "a scene just inside the bound" 0 60 "$GTRACE" near.scene -o near.png -q

# OBJ face indices at the ends of the integer range, NUL bytes, numbers out of range, a byte-order mark
mesh() { # OBJ-TEXT (printf format)
    printf "$1" > m.obj
    printf 'camera pinhole { from <0, 0, 5> at <0, 0, 0> width 8 height 6 }\n' > mesh.scene
    printf 'object mesh { file "m.obj" material lambert }\n' >> mesh.scene
}
for idx in -9223372036854775808 9223372036854775807 -99999999999999999999 -2147483648 2147483648 -4; do
    mesh "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 $idx\n"
    bounded_run "OBJ index $idx" 1 30 "$GTRACE" mesh.scene -o m.png -q
    expect "OBJ index $idx" "m.obj:4:7: index out of range"
done
mesh "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nv 1 2\0003\n"
bounded_run "OBJ with a NUL byte" 1 30 "$GTRACE" mesh.scene -o m.png -q
expect "OBJ with a NUL byte" "m.obj:5:6: a NUL byte (not a text file?)"
mesh "v 1e400 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
bounded_run "OBJ v 1e400" 1 30 "$GTRACE" mesh.scene -o m.png -q
expect "OBJ v 1e400" "m.obj:1:3: number out of range (beyond +-1.8e308)"
mesh "v 0 0 0\nv 1 0 0\nv 0 1 inf\nf 1 2 3\n"
bounded_run "OBJ v inf" 1 30 "$GTRACE" mesh.scene -o m.png -q
expect "OBJ v inf" "m.obj:3:7: expected a finite number"
mesh "v 1e16 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
bounded_run "OBJ vertex at 1e16" 1 30 "$GTRACE" mesh.scene -o m.png -q
expect "OBJ vertex at 1e16" "the object reaches 1e+16 (after its transform)"
# ---- class 10: byte-order marks are accepted in scenes, OBJ and BFC files ----
mesh "\357\273\277v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
{ printf '\357\273\277'; cat mesh.scene; } > bom.scene
bounded_run "scene and OBJ with a byte-order mark" 0 60 "$GTRACE" bom.scene -o bom.png -q
{ printf '\357\273\277'; cat "$SRC/tests/bad/tiny.BFC"; } > bom.BFC
printf '\357\273\277color c bfc "bom.BFC"\n' > bom.mat
bounded_run "material and BFC with a byte-order mark" 0 30 "$GMAT" list bom.mat
printf '\357\273\277material m lambert { reflectance rgb 0.5 0.5 0.5 }\n\357\273\277material n lambert\n' > bom2.mat
bounded_run "a byte-order mark inside the text" 1 30 "$GMAT" list bom2.mat
expect "a byte-order mark inside the text" "bom2.mat:2:1: unexpected character byte 0xef"

# ---- class 3: BFC grids far outside the spectrum (float-to-int conversions of grid positions) ----
for grid in "1e300 1e300 10 3 1e300 10" "1e300 1e300 1 3 -1e300 1e299" "400 420 10 3 -1e300 1e299"; do
    set -- $grid
    { sed -n 1,10p "$SRC/tests/bad/tiny.BFC"; printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$@"
      printf 'r:c:\t%s\t%s\t%s\n' "$5" "$(awk "BEGIN{printf \"%g\", $5+$6}")" "$(awk "BEGIN{printf \"%g\", $5+2*$6}")"
      printf '%s\t0.5\t0.1\t0.1\nEOD\n' "$1"; } > far.BFC
    printf 'color c bfc "far.BFC"\nmaterial m lambert { reflectance c }\n' > far.mat
    for model in rgb spectrum bispectral; do
        "$GMAT" list far.mat --colormodel $model > out 2> err
        st=$?
        [ $st -lt 128 ] || fail "BFC grid $grid in $model: status $st"
        grep -q -E "Sanitizer|runtime error:" err && fail "BFC grid $grid in $model: $(head -c 1500 err)"
    done
    echo "ok BFC grid $grid"
done

# ---- class 3: noise at huge frequency times a huge radius ----
printf 'camera pinhole { from <0, 0, 9e14> at <0, 0, 0> fov 1 width 8 height 6 }\n' > noise.scene
printf 'object sphere { center <0, 0, 0> radius 1e13 material bump { child lambert height fbm { frequency 1e9 octaves 16 lacunarity 1000 } strength 0.1 } }\n' >> noise.scene
printf 'light point { position <0, 0, 9e14> intensity rgb 1e30 1e30 1e30 }\n' >> noise.scene
bounded_run "noise of frequency 1e9 x 1000^15 on a sphere of radius 1e13" 0 60 "$GTRACE" noise.scene -o noise.png -q

# ---- class 9: work a scene can demand is bounded ----
printf 'camera pinhole { from <0, 0, 4> at <0, 0, 0> fov 35 width 16 height 12 spp 1 depth 1000 cutoff 0 }\n' > tower.scene
printf 'object sphere { center <0, 0, 0> radius 1 material dielectric { index 1.5 } }\n' >> tower.scene
printf 'object sphere { center <0, 0, 0> radius 0.5 material dielectric { index 1.5 } }\n' >> tower.scene
printf 'light point { position <0, 5, 5> intensity rgb 10 10 10 }\n' >> tower.scene
bounded_run "nested glass at depth 1000, cutoff 0" 0 120 "$GTRACE" tower.scene -o tower.png -q
expect "nested glass" "camera samples reached the limit of 4096 reflected and refracted rays per sample"
bounded_run "nested glass with --max-rays 64" 0 120 "$GTRACE" tower.scene -o tower.png -q --max-rays 64
expect "nested glass --max-rays 64" "reached the limit of 64 reflected and refracted rays per sample"
bounded_run "--max-rays 0" 1 10 "$GTRACE" tower.scene -o tower.png -q --max-rays 0
expect "--max-rays 0" "gtrace: --max-rays expects a whole number in [1, 1000000], got '0'"
cp "$SRC/examples/scenes/sky.hdr" .
printf 'camera pinhole { from <0, 0, 4> at <0, 0, 0> width 8 height 6 }\nobject sphere { material lambert }\n' > fit.scene
printf 'light probe { file "sky.hdr" technique irradiance count 4096 fit_normals 8192 }\n' >> fit.scene
bounded_run "an irradiance fit of 4096 lights on 8192 normals" 1 10 "$GTRACE" fit.scene -o fit.png -q
expect "irradiance fit 4096" "fit.scene:3:79: technique irradiance fits at most 128 lights"
sed 's/count 4096/count 100/' fit.scene > fit2.scene
bounded_run "an irradiance fit of 100 lights on 8192 normals" 1 10 "$GTRACE" fit2.scene -o fit.png -q
expect "irradiance fit 100 x 8192" "fit2.scene:3:78: technique irradiance: count x fit_normals exceeds the limit of 524288"
bounded_run "gprobe irradiance of 4096 lights" 1 10 \
    "$GPROBE" approx --probe sky.hdr --technique irradiance -n 4096 -o l.txt
expect "gprobe irradiance 4096" "irradiance optimisation of 4096 lights: the limit is 128 lights"

[ $fails -eq 0 ] && echo "limits: all passed"
[ $fails -eq 0 ]
