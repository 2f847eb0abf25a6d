#!/bin/sh
# bad_inputs.sh BUILD - the tools on the corpus of broken inputs in tests/bad/: every material, texture and BFC
# file (gmat), every probe file (gprobe), every scene (gtrace), broken plug-ins and a file over the size limit.
# Each must fail with a clear message on stderr - `file:line:col: message` for text, the file's name for images -
# and an exit status from 1 to 127: a status of 128 or more (a signal) or a sanitizer report is a crash. No tool
# may leave a partial result: an output file that exists before a failing run keeps its content. FIFOs,
# devices and directories as every kind of input, and generated lying image headers, are refused. A probe with
# NaN, infinite and negative pixels loads, and the number of pixels set to 0 is reported.
SRC=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=$(cd "${1:-build}" 2> /dev/null && pwd) || { echo "FAIL: no build directory ${1:-build}"; exit 1; }
GMAT="$BUILD/bin/gmat"
GPROBE="$BUILD/bin/gprobe"
GTRACE="$BUILD/bin/gtrace"
PLUGINS="$BUILD/plugins"
for t in "$GMAT" "$GPROBE" "$GTRACE"; do
    if [ ! -x "$t" ]; then
        echo "FAIL: $t is not built"
        exit 1
    fi
done
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fails=0
checked=0
fail() {
    echo "FAIL: $*"
    fails=$((fails + 1))
}

# run WHAT COMMAND...: runs a command that must fail cleanly; its stderr is left in $TMP/err.
run_fails() {
    what=$1
    shift
    "$@" > "$TMP/out" 2> "$TMP/err"
    st=$?
    checked=$((checked + 1))
    if [ $st -eq 0 ]; then
        fail "$what: succeeded"
    elif [ $st -ge 128 ]; then
        fail "$what: crashed (status $st): $(head -c 2000 "$TMP/err")"
    fi
    if grep -q -E "Sanitizer|runtime error:" "$TMP/err"; then
        fail "$what: sanitizer report: $(head -c 2000 "$TMP/err")"
    fi
    if [ ! -s "$TMP/err" ]; then
        fail "$what: no message on stderr"
    fi
}

# An existing output with known content, to check that failed runs leave it alone.
known() { # file
    printf 'known content, not to be overwritten\n' > "$1"
}
unchanged() { # what file
    if [ "$(cat "$2" 2>/dev/null)" != "known content, not to be overwritten" ]; then
        fail "$1: the existing output $2 was overwritten"
    fi
}

# ---- the checks of one corpus file, run by two workers at a time ----
check_mat() { # a material, texture or BFC file: gmat list, in its model (and the bispectral one)
    f=$1
    want=$(head -n 1 "$f" | sed -n 's/^# expect: //p')
    prefix=${want%%...*}
    if grep -q -E "^(object|light|camera) " "$f"; then
        # gmat list reads past a scene's object, light and camera entries (only gtrace knows them): gtrace
        # reports the error in them
        "$GMAT" list "$f" > "$TMP/out" 2>&1 || fail "gmat list $f does not read past the scene entries: $(cat "$TMP/out")"
        run_fails "gtrace $f" "$GTRACE" "$f" -o "$TMP/never.png" -q
        grep -q -F "gtrace: $prefix" "$TMP/err" || fail "gtrace $f: expected '$want', got: $(cat "$TMP/err")"
        return
    fi
    run_fails "gmat list $f" "$GMAT" list "$f"
    if grep -q -E "registered by test_reader" "$f"; then
        # a type only the reader's test registers: here it is an unknown name, still at file:line:col
        grep -q -E "^gmat: $f:[0-9]+:[0-9]+: " "$TMP/err" || fail "gmat list $f: no file:line:col: $(cat "$TMP/err")"
    elif [ -n "$prefix" ]; then
        grep -q -F "gmat: $prefix" "$TMP/err" || fail "gmat list $f: expected '$want', got: $(cat "$TMP/err")"
    fi
    case $f in # values whose conversion depends on the colour model: also in the bispectral one
    bfc_overflow.mat | scale_overflow.mat)
        run_fails "gmat list $f --colormodel bispectral" "$GMAT" list "$f" --colormodel bispectral
        grep -q -E "^gmat: [A-Za-z0-9_.-]+:[0-9]+:[0-9]+: " "$TMP/err" ||
            fail "gmat list $f --colormodel bispectral: no file:line:col: $(cat "$TMP/err")"
        ;;
    esac
}

check_probe() { # a broken probe: the message names the file, an existing lights file is kept
    f=$1
    known "$TMP/lights.txt"
    run_fails "gprobe approx $f" "$GPROBE" approx --probe "$f" --technique adaptive -n 4 -o "$TMP/lights.txt"
    grep -q -F "gprobe: $f" "$TMP/err" || fail "gprobe $f: the message does not name the file: $(cat "$TMP/err")"
    unchanged "gprobe approx $f" "$TMP/lights.txt"
}

check_scene() { # a broken scene (or a material file without a scene): file:line:col, an existing image is kept
    f=$1
    known "$TMP/render.png"
    run_fails "gtrace $f" "$GTRACE" "$f" -o "$TMP/render.png" -q
    case $f in
    *.scene) grep -q -E "^gtrace: $f(:[0-9]+:[0-9]+)?: " "$TMP/err" || fail "gtrace $f: no file:line:col: $(cat "$TMP/err")" ;;
    esac
    unchanged "gtrace $f" "$TMP/render.png"
}

cd "$SRC/tests/bad" || exit 1
if [ "$2" = "--each" ]; then # worker: BUILD --each KIND FILE...
    kind=$3
    shift 3
    for f in "$@"; do
        "check_$kind" "$f"
    done
    echo "checked $checked"
    exit 0
fi

# each KIND FILE...: the checks of every file, two workers at a time; their failures are reported here
each() {
    kind=$1
    shift
    printf '%s\n' "$@" | xargs -P 2 -n 8 sh "$SRC/tests/scripts/bad_inputs.sh" "$BUILD" --each "$kind" > "$TMP/each" 2>&1
    while IFS= read -r line; do
        case $line in
        "checked "*) checked=$((checked + ${line#checked })) ;;
        "FAIL: "*) echo "$line"; fails=$((fails + 1)) ;;
        *) echo "$line" ;;
        esac
    done < "$TMP/each"
}

# ---- text files: every tests/bad/*.mat (every second one in a sanitizer build) ----
# (Tool runs once cost 0.2 s each, 0.4 s under AddressSanitizer, to start OpenImageIO; it is now loaded only for
# images, and a run starts in a few milliseconds.)
# Under the sanitizers the library itself reads every file of the corpus in-process (test_reader), so the
# tools' own path - a failed load reported and the program ended - is checked on half the files there.
mats=$(ls *.mat)
if ldd "$GMAT" 2> /dev/null | grep -q -E "libasan|libubsan"; then # as prelude.sh's sanitized
    mats=$(ls *.mat | awk 'NR % 2 == 1')
fi
each mat $mats

# a plot of a broken file, and of a good file with a bad argument, keeps an existing image
known "$TMP/plot.png"
run_fails "gmat plot of a broken file" "$GMAT" plot scale_overflow.mat lamp --in 30 -o "$TMP/plot.png"
unchanged "gmat plot of a broken file" "$TMP/plot.png"
printf 'material m lambert { reflectance rgb 0.5 0.5 0.5 }\n' > "$TMP/good.mat"
run_fails "gmat plot into an unknown format" "$GMAT" plot "$TMP/good.mat" m --in 30 -o "$TMP/plot.unknownformat"
[ -e "$TMP/plot.unknownformat" ] && fail "gmat plot into an unknown format left a file"

# a file over the memory budget (sparse, 16 MiB + 1 byte under a budget of 16 MiB) is refused before it is read
: > "$TMP/big.mat"
truncate -s 16777217 "$TMP/big.mat" 2> /dev/null || dd if=/dev/zero of="$TMP/big.mat" bs=1 count=0 seek=16777217 2> /dev/null
run_fails "gmat list of a 16 MiB + 1 byte file under a 16 MiB budget" env GENERIC_MEMORY_LIMIT_MB=16 "$GMAT" list "$TMP/big.mat"
grep -q "(16777217 bytes) needs 16.0 MiB, over the memory budget" "$TMP/err" ||
    fail "a file over the memory budget: $(cat "$TMP/err")"

# ---- plug-ins: another interface version, no entry point, a failing init, not a shared object ----
ABI=$(sed -n 's/^#define GMODULE_ABI_VERSION \([0-9]*\).*/\1/p' "$SRC/include/generic/plugin.h")
for case in "bad_abi:was built for module interface version $((ABI + 41)), this library has version $ABI" \
            "no_init:has no entry point" "failing_init:failed to initialise: this module always fails"; do
    so=${case%%:*}
    msg=${case#*:}
    if [ ! -e "$PLUGINS/$so.so" ]; then
        fail "$PLUGINS/$so.so is not built"
        continue
    fi
    if [ "$so" = bad_abi ]; then
        run_fails "gmat --plugin $so.so" "$GMAT" list "$TMP/good.mat" --plugin "$PLUGINS/$so.so"
        grep -q -F "$msg" "$TMP/err" || fail "--plugin $so.so: expected '$msg', got: $(cat "$TMP/err")"
    fi
    printf 'plugin "%s"\nmaterial m lambert\n' "$PLUGINS/$so.so" > "$TMP/plugin_$so.mat"
    run_fails "plugin \"$so.so\" statement" "$GMAT" list "$TMP/plugin_$so.mat" --allow-plugins
    grep -q -F "plugin_$so.mat:1:8: " "$TMP/err" && grep -q -F "$msg" "$TMP/err" ||
        fail "plugin statement $so.so: expected 'plugin_$so.mat:1:8: ...$msg', got: $(cat "$TMP/err")"
done
run_fails "gmat --plugin of a text file" "$GMAT" list "$TMP/good.mat" --plugin tiny.BFC
grep -q "invalid ELF header" "$TMP/err" || fail "a text file as a module: $(cat "$TMP/err")"

# ---- light probes: broken files fail naming the file; approx and convert keep existing outputs ----
each probe $(ls probe_*.hdr probe_*.pfm | grep -v -E "probe_(nonfinite|black).pfm")
known "$TMP/lights.txt"
known "$TMP/probe.png"
run_fails "gprobe convert probe_truncated.hdr" "$GPROBE" convert --probe probe_truncated.hdr -o "$TMP/probe.png"
unchanged "gprobe convert probe_truncated.hdr" "$TMP/probe.png"
run_fails "gprobe approx with a bad light count" "$GPROBE" approx --probe probe_black.pfm --technique mediancut -n 3 \
    -o "$TMP/lights.txt"
unchanged "gprobe approx with a bad light count" "$TMP/lights.txt"
# NaN, +-infinity and negative pixels are set to 0 and counted; the lights are finite and the count is reported
checked=$((checked + 1))
if "$GPROBE" approx --probe probe_nonfinite.pfm --technique kmeans -n 4 -o "$TMP/nonfinite.txt" 2> "$TMP/err"; then
    grep -q "4 pixels had negative, NaN or infinite values (set to 0)" "$TMP/err" ||
        fail "probe_nonfinite.pfm: the clamped pixels are not reported: $(cat "$TMP/err")"
    grep "^light" "$TMP/nonfinite.txt" | grep -i -q -E "nan|inf" && fail "probe_nonfinite.pfm: a light is not finite: $(cat "$TMP/nonfinite.txt")"
    grep -q "^light directional" "$TMP/nonfinite.txt" || fail "probe_nonfinite.pfm: no lights written"
else
    fail "gprobe approx probe_nonfinite.pfm failed: $(cat "$TMP/err")"
fi
# a 1x1 probe is square: the message says what is wrong with it (too small), not that it is not square
printf 'PF\n1 1\n-1.0\n\000\000\200\077\000\000\200\077\000\000\200\077' > "$TMP/one.pfm"
run_fails "gprobe eval on a 1x1 probe" "$GPROBE" eval --probe "$TMP/one.pfm"
grep -q -F "one.pfm is 1x1: an angular map needs at least 2x2 pixels" "$TMP/err" ||
    fail "gprobe eval on a 1x1 probe: expected 'needs at least 2x2 pixels', got: $(cat "$TMP/err")"

# ---- files that are not regular files, as every kind of input: refused at once with the path and the kind ----
mkfifo "$TMP/fifo" 2> /dev/null || fail "mkfifo failed"
mkdir "$TMP/adir"
printf 'camera pinhole { from <0,0,5> at <0,0,0> }\nmaterial g lambert { }\n' > "$TMP/cam.part"
for spec in "$TMP/fifo:a FIFO" "/dev/zero:a character device" "/dev/urandom:a character device" "$TMP/adir:a directory"; do
    p=${spec%%:*}
    kind=${spec#*:}
    want="\"$p\": it is $kind"
    {
        cat "$TMP/cam.part"
        printf 'object mesh { file "%s" material g }\n' "$p"
    } > "$TMP/mesh_input.scene"
    printf 'include "%s"\n' "$p" > "$TMP/include_input.mat"
    printf 'node n image { child lambert file "%s" }\n' "$p" > "$TMP/image_input.mat"
    printf 'color c bfc "%s"\n' "$p" > "$TMP/bfc_input.mat"
    printf 'plugin "%s"\n' "$p" > "$TMP/plugin_input.mat"
    for c in "gmat list $p:$GMAT list $p" "include:$GMAT list $TMP/include_input.mat" \
             "image node:$GMAT list $TMP/image_input.mat" "bfc:$GMAT list $TMP/bfc_input.mat" \
             "plugin statement:$GMAT list $TMP/plugin_input.mat --allow-plugins" "--plugin:$GMAT list $TMP/good.mat --plugin $p" \
             "mesh:$GTRACE $TMP/mesh_input.scene -q -o $TMP/mesh.png" \
             "probe:$GPROBE approx --probe $p --technique adaptive -n 4 -o $TMP/lights.txt"; do
        what=${c%%:*}
        cmd=${c#*:}
        # the message names the kind: refused before any read. `timeout` turns a hang (a FIFO opened for reading
        # blocks until a writer comes) into a failure instead of a suite that never ends; a run takes milliseconds.
        # shellcheck disable=SC2086 # the command's words
        timeout 120 sh -c 'exec "$@"' sh $cmd > "$TMP/out" 2> "$TMP/err"
        st=$?
        checked=$((checked + 1))
        if [ $st -eq 124 ]; then
            fail "$what on $p: hangs"
        elif [ $st -eq 0 ] || [ $st -ge 128 ]; then
            fail "$what on $p: exit status $st: $(head -c 1000 "$TMP/err")"
        elif ! grep -q -F -- "$want" "$TMP/err"; then
            fail "$what on $p: expected '$want', got: $(cat "$TMP/err")"
        fi
    done
done

# ---- generated headers that claim more pixels than the file holds, or than the memory budget allows ----
# PFM (uncompressed: compared with the file's size) and Radiance HDR (run-length encoded: at least 2 bytes
# for 127 of a component), from small to the largest sizes; each is refused by gprobe and the image node
# within 300 MB: before the claimed pixels are allocated.
lie=0
for size in "1024 512" "4096 2048" "8192 4096" "16384 8192" "23000 11500" "32768 16384" "65535 32767"; do
    set -- $size
    lie=$((lie + 1))
    printf 'PF\n%s %s\n-1.0\n' "$1" "$2" > "$TMP/lie$lie.pfm"
    head -c 1000 /dev/zero >> "$TMP/lie$lie.pfm"
    printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %s +X %s\n' "$2" "$1" > "$TMP/lie$lie.hdr"
    for f in "$TMP/lie$lie.pfm" "$TMP/lie$lie.hdr"; do
        printf 'node n image { child lambert file "%s" }\n' "$f" > "$TMP/lie_node.mat"
        for c in "$GPROBE approx --probe $f --technique adaptive -n 4 -o $TMP/lights.txt" "$GMAT list $TMP/lie_node.mat"; do
            known "$TMP/lights.txt"
            # shellcheck disable=SC2086
            /usr/bin/time -f "%M" -o "$TMP/time" $c > "$TMP/out" 2> "$TMP/err"
            st=$?
            checked=$((checked + 1))
            read -r kb << EOF
$(tail -n 1 "$TMP/time")
EOF
            if [ $st -eq 0 ] || [ $st -ge 128 ]; then
                fail "$c: exit status $st: $(head -c 1000 "$TMP/err")"
            fi
            grep -q -F "$f" "$TMP/err" || fail "$c: the message does not name the file: $(cat "$TMP/err")"
            grep -q -E "claims|invalid image size|unsupported image size" "$TMP/err" ||
                fail "$c: expected the claim to be refused, got: $(cat "$TMP/err")"
            if ! ldd "$GMAT" 2> /dev/null | grep -q -E "libasan"; then
                [ "$kb" -lt 300000 ] || fail "$c: held $kb KB"
            fi
            unchanged "$c" "$TMP/lights.txt"
        done
    done
done

# ---- scenes: gtrace reports file:line:col (or the file) and keeps an existing image ----
each scene scene_*.scene image_missing.mat bfc_overflow.mat

echo "$checked failing runs checked, $fails failures"
[ $fails -eq 0 ]
