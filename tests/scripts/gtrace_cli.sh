#!/bin/sh
# gtrace_cli.sh BUILD - the gtrace command line: --help, bad arguments, scene errors with file:line:col and
# a non-zero status, no output file after a failure, a small render in every colour model, -q.
BUILD=${1:-build}
GT="$BUILD/bin/gtrace"
if [ ! -x "$GT" ]; then
    echo "FAIL: $GT is not built"
    exit 1
fi
. "$(dirname "$0")/prelude.sh"

"$GT" --help > "$TMP/help" 2>&1 || fail "--help exits with $?"
grep -q "usage: gtrace SCENE -o OUT" "$TMP/help" || fail "--help does not print the usage"

"$GT" > /dev/null 2>&1
[ $? -eq 2 ] || fail "no arguments: expected exit status 2"
"$GT" x.scene -o "$TMP/x.png" --spp zero > "$TMP/err" 2>&1
[ $? -eq 2 ] || fail "--spp zero: expected exit status 2"
grep -q -- "--spp expects a whole number" "$TMP/err" || fail "--spp zero: no clear message: $(cat "$TMP/err")"
"$GT" x.scene -o "$TMP/x.png" --integrator bogus > "$TMP/err" 2>&1
[ $? -eq 2 ] || fail "--integrator bogus: expected exit status 2"
grep -q -- "--integrator expects whitted, path, sppm or light" "$TMP/err" || fail "--integrator bogus: no clear message: $(cat "$TMP/err")"

cat > "$TMP/good.scene" << 'EOF'
material grey lambert { reflectance rgb 0.5 0.5 0.5 }
camera pinhole { from <0, 1, 4> at <0, 0.5, 0> fov 40 width 40 height 30 spp 1 depth 2 }
object plane { point <0, 0, 0> normal <0, 1, 0> material grey }
object sphere { center <0, 0.5, 0> radius 0.5 material dielectric { index 1.5 } }
light point { position <2, 4, 3> intensity rgb 20 20 20 }
EOF
cat > "$TMP/bad.scene" << 'EOF'
material grey lambert { reflectance rgb 0.5 0.5 0.5 }
object sphere { center <0, 0.5, 0> radius 0.5 material grey colour 3 }
EOF

"$GT" "$TMP/bad.scene" -o "$TMP/bad.png" > "$TMP/err" 2>&1
st=$?
[ $st -ne 0 ] || fail "a bad scene exits with status 0"
grep -q "bad.scene:2:61: object sphere: unknown parameter 'colour'" "$TMP/err" ||
    fail "a bad scene's message lacks file:line:col: $(cat "$TMP/err")"
[ ! -e "$TMP/bad.png" ] || fail "a failed run left an output file"

"$GT" "$TMP/good.scene" -o "$TMP/nodir/out.png" > "$TMP/err" 2>&1 && fail "writing into a missing directory succeeded"
[ ! -e "$TMP/nodir/out.png" ] || fail "a failed write left a file"
"$GT" "$TMP/good.scene" -o "$TMP/out.unknownformat" > "$TMP/err" 2>&1 && fail "an unknown output format succeeded"
ls "$TMP" | grep -q "unknownformat" && fail "a failed write left a (temporary) file: $(ls "$TMP")"

for m in rgb spectrum9 spectrum bispectral; do
    "$GT" "$TMP/good.scene" -o "$TMP/$m.exr" --colormodel $m > "$TMP/out" 2>&1 || fail "--colormodel $m: $(cat "$TMP/out")"
    [ -s "$TMP/$m.exr" ] || fail "--colormodel $m wrote no image"
    grep -q "40x30, 1 spp, depth 2, $m," "$TMP/out" || fail "--colormodel $m: no summary line: $(cat "$TMP/out")"
    grep -q "M rays/s" "$TMP/out" || fail "the summary line lacks rays/s"
done
for m in rgb bispectral; do
    "$GT" "$TMP/good.scene" -o "$TMP/path_$m.exr" --colormodel $m --integrator path --spp 4 > "$TMP/out" 2>&1 ||
        fail "--integrator path --colormodel $m: $(cat "$TMP/out")"
    grep -q "40x30, 4 spp, depth 2, $m," "$TMP/out" || fail "--integrator path: no summary line: $(cat "$TMP/out")"
done
# the particle integrators: a small render each, and their options' bounds named
for i in sppm light; do
    "$GT" "$TMP/good.scene" -o "$TMP/$i.exr" --integrator $i --passes 2 --photons 2000 > "$TMP/out" 2>&1 ||
        fail "--integrator $i: $(cat "$TMP/out")"
    [ -s "$TMP/$i.exr" ] || fail "--integrator $i wrote no image"
done
for bad in "--passes 0:[1, 1000000]" "--photons 100000001:[1, 100000000]" "--radius -1:--radius expects a number" \
    "--alpha 1.5:--alpha expects a number"; do
    opt=${bad%%:*}
    # shellcheck disable=SC2086
    "$GT" "$TMP/good.scene" -o "$TMP/x.png" --integrator sppm $opt > "$TMP/err" 2>&1
    [ $? -eq 2 ] || fail "$opt: expected exit status 2"
    grep -qF -- "${bad#*:}" "$TMP/err" || fail "$opt: the bound is not named: $(cat "$TMP/err")"
done
"$GT" "$TMP/good.scene" -o "$TMP/x.png" --colormodel nosuchmodel > "$TMP/err" 2>&1 && fail "an unknown colour model succeeded"
grep -q "nosuchmodel" "$TMP/err" || fail "an unknown colour model is not named: $(cat "$TMP/err")"

"$GT" "$TMP/good.scene" -o "$TMP/q.png" -q --width 20 --threads 1 > "$TMP/out" 2>&1 || fail "-q run failed"
[ -s "$TMP/out" ] && fail "-q printed: $(cat "$TMP/out")"
[ -s "$TMP/q.png" ] || fail "-q wrote no image"
if command -v iinfo > /dev/null; then
    iinfo "$TMP/q.png" | grep -q "20 x  *15," || fail "--width 20 did not keep the aspect: $(iinfo "$TMP/q.png")"
fi

# the viewing illuminant: an unknown name is a usage error listing the known ones; a named one and a blackbody render
"$GT" "$TMP/good.scene" -o "$TMP/x.png" --illuminant F13 > "$TMP/err" 2>&1
[ $? -eq 2 ] || fail "--illuminant F13: expected exit status 2"
grep -q "unknown illuminant 'F13' (known: A, B, C, D50.*F11.*LED-B1.*blackbody K)" "$TMP/err" ||
    fail "--illuminant F13: the known names are not listed: $(cat "$TMP/err")"
for ill in F11 "blackbody 3200"; do
    "$GT" "$TMP/good.scene" -o "$TMP/ill.png" -q --width 16 --threads 1 --illuminant "$ill" > "$TMP/err" 2>&1 ||
        fail "--illuminant $ill failed: $(cat "$TMP/err")"
done

[ $fails -eq 0 ] && echo "gtrace command line: all checks passed"
[ $fails -eq 0 ]
