#!/bin/sh
# exit_status.sh BUILD - the exit status every tool promises in its --help: 0 on success, 1 when the work failed
# (a missing or broken input file, an unknown material or module, a failed write), 2 for a usage error (an
# unknown option - named in the message, also when it is the last argument -, a missing or bad value, a value
# given to an option that takes none, an unknown command or colour model name given to gcolor). Every tool and
# command also answers --help and --version with 0, and takes --option=value like --option value.
BUILD=${1:-build}
BIN="$BUILD/bin"
for t in gtrace gmat gcolor gprobe; do
    [ -x "$BIN/$t" ] || { echo "FAIL: $BIN/$t is not built"; exit 1; }
done
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fails=0 checked=0
fail() {
    echo "FAIL: $*"
    fails=$((fails + 1))
}
# expect STATUS WHAT [grep -F pattern of the output, or ""] -- COMMAND...
expect() {
    want=$1 what=$2 pattern=$3
    shift 4
    "$@" > "$TMP/out" 2>&1
    st=$?
    checked=$((checked + 1))
    [ "$st" -eq "$want" ] || fail "$what: exit status $st, expected $want: $(head -c 600 "$TMP/out")"
    grep -q -E "Sanitizer|runtime error:" "$TMP/out" && fail "$what: sanitizer report: $(head -c 600 "$TMP/out")"
    if [ -n "$pattern" ]; then
        grep -q -F -- "$pattern" "$TMP/out" || fail "$what: expected '$pattern' in: $(head -c 600 "$TMP/out")"
    fi
}

cat > "$TMP/good.mat" << 'E'
material grey lambert { reflectance rgb 0.5 0.5 0.5 }
E
printf 'material grey lambert { reflectance rgb 0.5 0.5 }\n' > "$TMP/broken.mat"
cat > "$TMP/good.scene" << 'E'
material grey lambert { reflectance rgb 0.5 0.5 0.5 }
camera pinhole { from <0, 1, 4> at <0, 0.5, 0> fov 40 width 32 height 24 spp 1 depth 2 }
object sphere { center <0, 0.5, 0> radius 0.5 material grey }
light point { position <2, 4, 3> intensity rgb 20 20 20 }
E
printf 'camera pinhole { from <0, 1, 4> at <0, 0.5, 0> fov 40 width 32 height 24\n' > "$TMP/broken.scene"
"$BIN/gprobe" sky -o "$TMP/sky.hdr" --height 16 > /dev/null 2>&1 || fail "gprobe sky could not make a probe"
printf 'not an image' > "$TMP/bad.hdr"

# ---- every tool and command: --help, --version, an unknown option (also as the last argument) ----
for cmd in "gtrace" "gtrace merge" "gtrace types" "gcolor" "gcolor list" "gcolor check" "gmat" "gmat eval" \
           "gmat albedo" "gmat plot" "gmat list" "gmat check" "gmat types" "gmat swatch" "gmat laser" "gprobe" \
           "gprobe eval" "gprobe approx" "gprobe irradiance" "gprobe convert" "gprobe compare" "gprobe sky"; do
    tool=${cmd%% *}
    sub=${cmd#"$tool"}
    # shellcheck disable=SC2086
    expect 0 "$cmd --help" "usage: $cmd" -- "$BIN/$tool" $sub --help
    grep -q "Exit status" "$TMP/out" || fail "$cmd --help does not document the exit status"
    # shellcheck disable=SC2086
    expect 0 "$cmd --version" "$tool (libgeneric) " -- "$BIN/$tool" $sub --version
    case $cmd in gmat | gprobe) continue ;; esac # a command is expected first
    # shellcheck disable=SC2086
    expect 2 "$cmd --no-such-option" "unknown option '--no-such-option'" -- "$BIN/$tool" $sub --no-such-option
    # shellcheck disable=SC2086
    expect 2 "$cmd ... --no-such-option=3" "unknown option '--no-such-option'" -- "$BIN/$tool" $sub x --no-such-option=3
    # shellcheck disable=SC2086
    expect 2 "$cmd -Z" "unknown option '-Z'" -- "$BIN/$tool" $sub -Z
    # shellcheck disable=SC2086
    expect 2 "$cmd --help=yes" "option '--help' takes no value" -- "$BIN/$tool" $sub --help=yes
done
expect 2 "gmat with no command" "usage: gmat COMMAND" -- "$BIN/gmat"
expect 2 "gmat frobnicate" "unknown command 'frobnicate'" -- "$BIN/gmat" frobnicate x y
expect 2 "gprobe with no command" "usage: gprobe COMMAND" -- "$BIN/gprobe"
expect 2 "gprobe frobnicate" "unknown command 'frobnicate'" -- "$BIN/gprobe" frobnicate
expect 2 "gcolor frobnicate" "unknown command or argument 'frobnicate'" -- "$BIN/gcolor" frobnicate
"$BIN/gmat" --help > "$TMP/help" 2>&1
for c in eval albedo plot list check types swatch laser; do
    grep -q "^  $c " "$TMP/help" || fail "gmat --help does not name the command $c"
done

# ---- gtrace ----
GT="$BIN/gtrace"
expect 0 "gtrace --width=16 --spp=1" "" -- "$GT" "$TMP/good.scene" -q -o "$TMP/ok.png" --width=16 --spp=1
expect 0 "gtrace --output=FILE" "" -- "$GT" "$TMP/good.scene" -q --output="$TMP/ok2.png" --width 16
[ -s "$TMP/ok2.png" ] || fail "gtrace --output=FILE wrote nothing"
expect 2 "gtrace --spp without a value" "option '--spp' needs a value" -- "$GT" "$TMP/good.scene" -o "$TMP/x.png" --spp
expect 2 "gtrace --spp zero" "--spp expects a whole number" -- "$GT" "$TMP/good.scene" -o "$TMP/x.png" --spp=zero
expect 2 "gtrace --quiet=1" "option '--quiet' takes no value" -- "$GT" "$TMP/good.scene" -o "$TMP/x.png" --quiet=1
expect 2 "gtrace without -o" "no output file given" -- "$GT" "$TMP/good.scene"
expect 2 "gtrace with two scenes" "more than one scene file" -- "$GT" "$TMP/good.scene" "$TMP/good.scene" -o "$TMP/x.png"
expect 2 "gtrace --crop outside" "--crop" -- "$GT" "$TMP/good.scene" -o "$TMP/x.png" --crop 0,0,64,64
expect 2 "gtrace --sampler unknown" "--sampler expects sobol or independent" -- "$GT" "$TMP/good.scene" -o "$TMP/x.png" \
    --sampler halton
expect 2 "gtrace --equiangular unknown" "--equiangular expects on or off" -- "$GT" "$TMP/good.scene" -o "$TMP/x.png" \
    --equiangular yes
expect 2 "gtrace --plugin without a value" "--plugin needs a value" -- "$GT" "$TMP/good.scene" -o "$TMP/x.png" --plugin
expect 2 "gtrace --confine not a directory" "--confine" -- "$GT" "$TMP/good.scene" -o "$TMP/x.png" --confine=/nonexistent
expect 1 "gtrace of a missing scene" "No such file" -- "$GT" "$TMP/none.scene" -o "$TMP/x.png"
expect 1 "gtrace of a broken scene" "broken.scene:" -- "$GT" "$TMP/broken.scene" -o "$TMP/x.png"
expect 1 "gtrace --colormodel nosuch" "unknown colour model 'nosuch'" -- "$GT" "$TMP/good.scene" -o "$TMP/x.png" --colormodel nosuch
expect 1 "gtrace into a missing directory" "No such file" -- "$GT" "$TMP/good.scene" -o "$TMP/none/x.png"
expect 1 "gtrace --plugin nothere.so" "nothere.so" -- "$GT" "$TMP/good.scene" -o "$TMP/x.png" --plugin nothere.so
expect 2 "gtrace types nothing" "unexpected argument 'nothing'" -- "$GT" types nothing

# ---- gmat ----
GM="$BIN/gmat"
expect 0 "gmat eval --in=30 --out=30" "reflected" -- "$GM" eval "$TMP/good.mat" grey --in=30 --out=30
expect 0 "gmat list of a scene" "grey" -- "$GM" list "$TMP/good.scene"
expect 2 "gmat eval --in without a value" "option '--in' needs a value" -- "$GM" eval "$TMP/good.mat" grey --in
expect 2 "gmat eval --in 95" "--in: '95'" -- "$GM" eval "$TMP/good.mat" grey --in 95 --out 0
expect 2 "gmat eval without --out" "--out THETA[,PHI] is required" -- "$GM" eval "$TMP/good.mat" grey --in 10
expect 2 "gmat eval, an extra argument" "unexpected argument 'extra'" -- "$GM" eval "$TMP/good.mat" grey extra --in 1 --out 1
expect 2 "gmat plot without -o" "-o PLOT.png is required" -- "$GM" plot "$TMP/good.mat" grey --in 10
expect 2 "gmat plot --size=10" "--size: '10'" -- "$GM" plot "$TMP/good.mat" grey --in 10 -o "$TMP/p.png" --size=10
expect 2 "gmat types nothing" "unexpected argument 'nothing'" -- "$GM" types nothing
expect 2 "gmat swatch without -o" "-o SWATCH.png is required" -- "$GM" swatch "$TMP/good.mat" grey
expect 2 "gmat laser --wavelength=x" "--wavelength: 'x'" -- "$GM" laser "$TMP/good.mat" grey --wavelength=x
for c in eval albedo plot check swatch laser; do
    case $c in
    eval | albedo | plot | check) args="--in 10 --out 10 -o $TMP/p.png" ;;
    swatch) args="-o $TMP/p.png --size 16" ;;
    laser) args="--elevation 30" ;;
    esac
    # shellcheck disable=SC2086
    expect 1 "gmat $c of a missing file" "No such file" -- "$GM" $c "$TMP/none.mat" grey $args
    # shellcheck disable=SC2086
    expect 1 "gmat $c of a broken file" "broken.mat:1:" -- "$GM" $c "$TMP/broken.mat" grey $args
    # shellcheck disable=SC2086
    expect 1 "gmat $c of an unknown material" "nosuch" -- "$GM" $c "$TMP/good.mat" nosuch $args
done
expect 1 "gmat list of a broken file" "broken.mat:1:" -- "$GM" list "$TMP/broken.mat"
expect 1 "gmat list of a broken scene" "broken.scene:1:1: the camera entry has no closing '}'" -- "$GM" list "$TMP/broken.scene"
expect 1 "gmat eval --colormodel nosuch" "unknown colour model 'nosuch'" -- "$GM" eval "$TMP/good.mat" grey --in 1 --out 1 --colormodel=nosuch

# ---- gcolor ----
GC="$BIN/gcolor"
expect 0 "gcolor --models=rgb --rgb=0.1,0.2,0.3" "rgb 0.1,0.2,0.3" -- "$GC" --models=rgb --rgb=0.1,0.2,0.3
expect 0 "gcolor check rgb --step=5" "rgb: PASS" -- "$GC" check rgb --step=5
expect 2 "gcolor check of an unknown model" "unknown colour model 'nosuch'" -- "$GC" check nosuch
expect 2 "gcolor --models with an unknown model" "unknown colour model 'nosuch'" -- "$GC" --models rgb,nosuch
expect 2 "gcolor check without a model" "no MODEL given" -- "$GC" check
expect 2 "gcolor check, two models" "unexpected argument 'spectrum'" -- "$GC" check rgb spectrum
expect 2 "gcolor --rgb without a value" "option '--rgb' needs a value" -- "$GC" --rgb
expect 2 "gcolor --rgb 1,2" "--rgb expects three finite numbers" -- "$GC" --rgb 1,2
expect 2 "gcolor check --step=0" "--step expects a number" -- "$GC" check rgb --step=0
expect 2 "gcolor list x" "unexpected argument 'x'" -- "$GC" list x
expect 1 "gcolor --plugin nothere.so" "nothere.so" -- "$GC" list --plugin nothere.so

# ---- gprobe ----
GP="$BIN/gprobe"
expect 0 "gprobe irradiance --probe=FILE --normal=0,0,1" "" -- "$GP" irradiance --probe="$TMP/sky.hdr" --normal=0,0,1
expect 0 "gprobe approx -n4 -t adaptive" "" -- "$GP" approx --probe "$TMP/sky.hdr" -tadaptive -n4 -o "$TMP/l.txt" -q
expect 2 "gprobe approx --probe without a value" "option '--probe' needs a value" -- "$GP" approx --probe
expect 2 "gprobe approx, an unknown technique" "unknown technique 'nosuch'" -- "$GP" approx --probe "$TMP/sky.hdr" -t nosuch -n 4 -o "$TMP/l.txt"
expect 2 "gprobe approx -n 0" "-n expects a whole number" -- "$GP" approx --probe "$TMP/sky.hdr" -t adaptive -n 0 -o "$TMP/l.txt"
expect 2 "gprobe irradiance without --normal" "--normal X,Y,Z is required" -- "$GP" irradiance --probe "$TMP/sky.hdr"
expect 2 "gprobe irradiance --format=cube" "--format expects" -- "$GP" irradiance --probe "$TMP/sky.hdr" --normal 0,0,1 --format=cube
expect 2 "gprobe convert, an extra argument" "unexpected argument 'extra'" -- "$GP" convert --probe "$TMP/sky.hdr" -o "$TMP/c.exr" extra
expect 2 "gprobe compare, one image" "give an image and its reference" -- "$GP" compare "$TMP/sky.hdr"
expect 2 "gprobe sky --height=2" "--height expects" -- "$GP" sky -o "$TMP/s.hdr" --height=2
expect 2 "gprobe eval --counts=x" "--counts" -- "$GP" eval --probe "$TMP/sky.hdr" --counts=x
for c in "irradiance --normal 0,0,1" "convert -o $TMP/c.exr" "approx -t adaptive -n 4 -o $TMP/l.txt"; do
    # shellcheck disable=SC2086
    expect 1 "gprobe ${c%% *} of a missing probe" "No such file" -- "$GP" $c --probe "$TMP/none.hdr"
    # shellcheck disable=SC2086
    expect 1 "gprobe ${c%% *} of a broken probe" "bad.hdr" -- "$GP" $c --probe "$TMP/bad.hdr"
done
expect 1 "gprobe compare of missing images" "No such file" -- "$GP" compare "$TMP/none.exr" "$TMP/none2.exr"

[ $fails -eq 0 ] && echo "exit_status: $checked runs, every status as documented"
echo "$checked runs checked, $fails failures"
exit $((fails > 0))
