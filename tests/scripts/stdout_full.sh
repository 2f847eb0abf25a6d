#!/bin/sh
# stdout_full.sh BUILD - no silent success: every printing command of every tool (examples/common/cli.h's
# cli_finish_stdout) exits 1 with "cannot write the standard output" on standard error when its standard output is
# /dev/full or a closed descriptor, and 0 with the same output into a pipe; a command that prints nothing (a render
# with -q) still succeeds with standard output closed.
BUILD=${1:-build}
BIN="$BUILD/bin"
. "$(dirname "$0")/prelude.sh"
for t in gtrace gmat gcolor gprobe; do
    need_program "$BIN/$t"
done
[ -w /dev/full ] || { echo "SKIP: no /dev/full"; exit 0; }

cat > "$TMP/good.mat" << 'E'
material grey lambert { reflectance rgb 0.5 0.5 0.5 }
E
cat > "$TMP/good.scene" << 'E'
material grey lambert { reflectance rgb 0.5 0.5 0.5 }
camera pinhole { from <0, 1, 4> at <0, 0.5, 0> fov 40 width 16 height 12 spp 1 depth 2 }
object sphere { center <0, 0.5, 0> radius 0.5 material grey }
light point { position <2, 4, 3> intensity rgb 20 20 20 }
E
"$BIN/gprobe" sky -o "$TMP/sky.hdr" --height 16 > /dev/null 2>&1 || fail "gprobe sky could not make a probe"

checked=0
# prints WHAT COMMAND...: COMMAND prints into a pipe and exits 0; into /dev/full and into a closed descriptor it
# exits 1 naming the failure.
prints() {
    what=$1
    shift
    "$@" 2> "$TMP/err" | cat > "$TMP/out"
    [ -s "$TMP/out" ] || fail "$what: printed nothing into a pipe: $(head -c 400 "$TMP/err")"
    for sink in full closed; do
        if [ $sink = full ]; then
            "$@" > /dev/full 2> "$TMP/err"
        else
            "$@" >&- 2> "$TMP/err"
        fi
        st=$?
        checked=$((checked + 1))
        [ $st -eq 1 ] || fail "$what > $sink: exit status $st, expected 1"
        grep -q "cannot write the standard output" "$TMP/err" ||
            fail "$what > $sink: no message: $(head -c 400 "$TMP/err")"
        grep -q -E "Sanitizer|runtime error:" "$TMP/err" && fail "$what > $sink: sanitizer report"
    done
}

for cmd in "gtrace" "gtrace merge" "gtrace types" "gcolor" "gcolor list" "gmat" "gmat eval" "gmat list" \
           "gmat types" "gprobe" "gprobe irradiance"; do
    tool=${cmd%% *}
    sub=${cmd#"$tool"}
    # shellcheck disable=SC2086
    prints "$cmd --help" "$BIN/$tool" $sub --help
    # shellcheck disable=SC2086
    prints "$cmd --version" "$BIN/$tool" $sub --version
done
prints "gtrace types" "$BIN/gtrace" types
prints "gtrace types --markdown" "$BIN/gtrace" types --markdown
prints "gmat list" "$BIN/gmat" list "$TMP/good.mat"
prints "gmat types" "$BIN/gmat" types
prints "gmat eval" "$BIN/gmat" eval "$TMP/good.mat" grey --in 30 --out 30
prints "gcolor list" "$BIN/gcolor" list
prints "gcolor --models=rgb --rgb" "$BIN/gcolor" --models=rgb --rgb=0.1,0.2,0.3
prints "gprobe irradiance" "$BIN/gprobe" irradiance --probe "$TMP/sky.hdr" --normal 0,0,1

# a command that prints nothing does not fail for want of a standard output
"$BIN/gtrace" "$TMP/good.scene" -q -o "$TMP/ok.png" >&- 2> "$TMP/err" ||
    fail "a quiet render with standard output closed failed: $(head -c 400 "$TMP/err")"
[ -s "$TMP/ok.png" ] || fail "the quiet render wrote no image"
echo "$checked writes into /dev/full or a closed standard output refused"
exit $fails
