#!/bin/sh
# outputs.sh BUILD - output integrity of the tools: destinations checked before any work (a missing
# directory, a format without a writer, a directory or a device as the output), a full disk (a 64 KiB tmpfs in
# a private mount namespace, when this runs as root and unshare works; skipped with a message otherwise) for
# every tool and several formats, SIGINT and SIGTERM at generated moments of a render and its write, and -o
# through a symbolic link. A failed run exits 1..127, names the output, keeps an existing file untouched and
# leaves no temporary (.NAME.XXXXXX.EXT) behind.
SRC=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=$(cd "${1:-build}" 2> /dev/null && pwd) || { echo "FAIL: no build directory ${1:-build}"; exit 1; }
GMAT="$BUILD/bin/gmat"
GPROBE="$BUILD/bin/gprobe"
GTRACE="$BUILD/bin/gtrace"
SCENE="$SRC/examples/scenes/material_lambert.scene"
MAT="$SRC/examples/materials/lambert.mat"
PROBE="$SRC/examples/scenes/sky.hdr"
. "$(dirname "$0")/prelude.sh"
known() { printf 'known content, not to be overwritten\n' > "$1"; }
unchanged() { [ "$(cat "$2" 2> /dev/null)" = "known content, not to be overwritten" ] || fail "$1: $2 was overwritten"; }
no_temporaries() { # what dir
    left=$(ls -A "$2" | grep -E '^\..*\.[A-Za-z0-9]{6}(\.[A-Za-z0-9]+)?$')
    [ -z "$left" ] || fail "$1: temporaries left in $2: $left"
}
# must_fail WHAT EXPECTED-MESSAGE COMMAND...: exit 1..127, the message on stderr, no sanitizer report
must_fail() {
    what=$1
    want=$2
    shift 2
    "$@" > "$TMP/out" 2> "$TMP/err"
    st=$?
    if [ $st -eq 0 ]; then
        fail "$what: succeeded"
    elif [ $st -ge 128 ]; then
        fail "$what: crashed (status $st): $(head -c 1000 "$TMP/err")"
    fi
    grep -q -E "Sanitizer|runtime error:" "$TMP/err" && fail "$what: sanitizer report: $(head -c 1000 "$TMP/err")"
    grep -q -F -- "$want" "$TMP/err" || fail "$what: expected '$want', got: $(cat "$TMP/err")"
}
MAT_NAME=$(sed -n 's/^material \([A-Za-z_][A-Za-z0-9_]*\) .*/\1/p' "$MAT" | head -n 1)

# ---- destinations checked before any work: refused without a render ----
for out in "$TMP/missing/dir/x.png:No such file or directory" "$TMP/x.pfm:no writer for '.pfm'" \
           "$TMP/x.nosuchformat:no writer for '.nosuchformat'" "/dev/full:it is a character device" \
           "/dev/null:it is a character device" "$TMP:it is a directory"; do
    o=${out%%:*}
    msg=${out#*:}
    # not quiet: a render would print its summary line, a refusal before it prints the refusal alone
    must_fail "gtrace -o $o" "$msg" "$GTRACE" "$SCENE" --width 4000 --height 3000 --spp 16 -o "$o"
    [ "$(wc -l < "$TMP/err")" -eq 1 ] || fail "gtrace -o $o: refused only after the render: $(head -c 1000 "$TMP/err")"
    must_fail "gmat swatch -o $o" "$msg" "$GMAT" swatch "$MAT" "$MAT_NAME" -o "$o"
    must_fail "gmat plot -o $o" "$msg" "$GMAT" plot "$MAT" "$MAT_NAME" --in 30 -o "$o"
    must_fail "gprobe convert -o $o" "$msg" "$GPROBE" convert --probe "$PROBE" -o "$o"
    case $o in *.png | *.pfm | *.nosuchformat) ;; *)
        must_fail "gprobe approx -o $o" "$msg" "$GPROBE" approx --probe "$PROBE" --technique adaptive -n 4 -o "$o" ;;
    esac
done
[ -e /dev/null ] && [ -c /dev/null ] || fail "/dev/null was replaced"
no_temporaries "refused destinations" "$TMP"

# ---- -o through a symbolic link (a chain of two): the target is replaced, the links stay ----
known "$TMP/target.png"
ln -s target.png "$TMP/link1.png"
ln -s "$TMP/link1.png" "$TMP/link2.png"
"$GTRACE" "$SCENE" -q --width 32 --height 24 -o "$TMP/link2.png" 2> "$TMP/err" || fail "gtrace -o a link: $(cat "$TMP/err")"
[ -L "$TMP/link1.png" ] && [ -L "$TMP/link2.png" ] || fail "gtrace -o a link replaced the link"
[ "$(head -c 4 "$TMP/target.png" | od -An -c | tr -d ' ')" = "211PNG" ] || fail "gtrace -o a link: the target is not a PNG"
no_temporaries "a link" "$TMP"

# ---- SIGINT and SIGTERM at generated moments of a render and its EXR write: no temporary stays ----
# A signal that lands after the finished file was renamed into place (the process still tearing down) exits
# non-zero with the complete new image there: that image, equal pixel for pixel to an undisturbed render's (its
# DateTime differs), is the other outcome allowed; anything else must have left the old file untouched.
"$GTRACE" "$SCENE" -q --width 1200 --height 900 --spp 1 -o "$TMP/ref.exr" 2> /dev/null || fail "the reference render failed"
known "$TMP/int.exr"
for delay in 0.1 0.3 0.6 0.9; do
    for sig in INT TERM; do
        "$GTRACE" "$SCENE" -q --width 1200 --height 900 --spp 1 -o "$TMP/int.exr" 2> /dev/null &
        pid=$!
        sleep $delay
        kill -$sig $pid 2> /dev/null
        wait $pid 2> /dev/null
        st=$?
        no_temporaries "SIG$sig after ${delay}s" "$TMP"
        if [ $st -ne 0 ] && oiiotool --fail 0 --diff "$TMP/int.exr" "$TMP/ref.exr" > /dev/null 2>&1; then
            known "$TMP/int.exr" # the signal came after the rename: the complete image, start again
        elif [ $st -ne 0 ]; then
            unchanged "SIG$sig after ${delay}s" "$TMP/int.exr"
        else
            known "$TMP/int.exr" # the render finished before the signal: start again from a known file
        fi
    done
done

# ---- a full disk: every tool and format fails, keeps the old file, leaves nothing ----
if [ "$(id -u)" = 0 ] && unshare -m true 2> /dev/null; then
    cat > "$TMP/full.sh" << EOF
set -e
mount -t tmpfs -o size=64k tmpfs "$TMP/disk"
for f in png jpg exr tif hdr; do printf 'known content, not to be overwritten\n' > "$TMP/disk/old.\$f"; done
printf 'known content, not to be overwritten\n' > "$TMP/disk/old.txt"
dd if=/dev/zero of="$TMP/disk/fill" bs=1k count=64 2> /dev/null || true
set +e
for f in png jpg exr tif hdr; do
    "$GTRACE" "$SCENE" -q --width 400 --height 300 -o "$TMP/disk/old.\$f"; echo "gtrace \$f \$?"
    "$GMAT" swatch "$MAT" "$MAT_NAME" -o "$TMP/disk/old.\$f" > /dev/null; echo "swatch \$f \$?"
    "$GPROBE" convert --probe "$PROBE" -o "$TMP/disk/old.\$f"; echo "convert \$f \$?"
done
"$GPROBE" approx --probe "$PROBE" --technique adaptive -n 16 -o "$TMP/disk/old.txt"; echo "approx txt \$?"
for f in png jpg exr tif hdr txt; do cat "$TMP/disk/old.\$f" > "$TMP/kept.\$f"; done
ls -A "$TMP/disk" > "$TMP/disk_list"
EOF
    mkdir "$TMP/disk"
    if unshare -m sh "$TMP/full.sh" > "$TMP/full_out" 2> "$TMP/full_err"; then
        while read -r tool fmt st; do
            if [ "$st" -eq 0 ] || [ "$st" -ge 128 ]; then
                fail "full disk: $tool .$fmt exited $st: $(grep -m 1 "old.$fmt" "$TMP/full_err")"
            fi
        done < "$TMP/full_out"
        grep -q "No space left on device" "$TMP/full_err" || fail "full disk: no 'No space left on device': $(head -c 1000 "$TMP/full_err")"
        grep -q -E "Sanitizer|runtime error:" "$TMP/full_err" && fail "full disk: sanitizer report"
        for f in png jpg exr tif hdr txt; do unchanged "full disk .$f" "$TMP/kept.$f"; done
        extra=$(grep -v -x -E "old\.(png|jpg|exr|tif|hdr|txt)|fill" "$TMP/disk_list")
        [ -z "$extra" ] || fail "full disk: files left: $extra"
    else
        echo "skip: a full disk (mounting a tmpfs in a private namespace failed: $(head -c 200 "$TMP/full_err"))"
    fi
else
    echo "skip: a full disk needs root and unshare -m (a 64 KiB tmpfs in a private mount namespace)"
fi

echo "$fails failures"
[ $fails -eq 0 ]
