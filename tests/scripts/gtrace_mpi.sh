#!/bin/sh
# gtrace_mpi.sh BUILD - gtrace under mpirun (docs/distributed.md): 3 ranks render images bit-identical to a
# single process, Whitted and path, a crop too, with rank 0 rendering or only gathering, and sppm and light with 1,
# 2 and 3 ranks; a rank that cannot read the scene, or was started with other arguments, is named by rank 0 and the
# job exits 1 without an image; a
# worker stopped (SIGSTOP) is declared dead after --mpi-timeout, and one killed (SIGKILL) ends the job, both
# without an image and within a bounded time; a missing module is a clear error; --help and a render on one
# machine never map libmpi. Every mpirun runs under `timeout`.
# shellcheck disable=SC2086 # option lists ($ARGS, $MPIRUN, ...) are split into words on purpose
set -u
BUILD=${1:-build}
GT="$BUILD/bin/gtrace"
. "$(dirname "$0")/prelude.sh"
need_program "$GT"
if ! "$GT" --version | grep -q "MPI module"; then
    # Open MPI's development files are here, so the build must have used them (every object tree of gtrace)
    pkg-config --exists ompi-c 2> /dev/null && { echo "FAIL: Open MPI is installed but $GT says: $("$GT" --version | tail -1)"; exit 1; }
    echo "gtrace_mpi: gtrace was built without MPI ($("$GT" --version | tail -1)): nothing to test"
    exit 0
fi
need_command mpirun openmpi-bin
need_command oiiotool openimageio-tools
# Open MPI in a container, possibly as root, on 2 cores: more ranks than cores, no single-copy transfers (they
# need ptrace rights a container may not grant). Under the sanitizers, Open MPI's own leaks are suppressed
# (tests/lsan_openmpi.supp): that needs whole stacks (Open MPI has no frame pointers, so the fast unwinder stops
# inside it) and its plug-ins kept mapped at exit (else their frames have no name).
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_mca_base_component_disable_dlclose=1
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan_openmpi.supp:print_suppressions=0:fast_unwind_on_malloc=0"
MPIRUN="timeout 120 mpirun -x LSAN_OPTIONS --oversubscribe --allow-run-as-root"
# Under the sanitizers the whole stacks cost each rank seconds of CPU, so leaks are checked on one job of each kind
# (Whitted and sppm bit-identical, every failure); the other jobs run with AddressSanitizer and UBSan alone.
MPIRUN_NOLEAK="env ASAN_OPTIONS=detect_leaks=0 LSAN_OPTIONS= timeout 120 mpirun --oversubscribe --allow-run-as-root"
SCENE=examples/scenes/demo.scene
ARGS="--width 96 --spp 2 --threads 1 -q"

same() { # A B WHAT: the two images are equal pixel by pixel
    d=$(oiiotool "$1" "$2" --fail 0 --diff 2>&1)
    echo "$d" | grep -q '^PASS' || fail "$3: differs from the single-process render: $(echo "$d" | tail -3)"
}

# ---- bit-identical to a single process ----
for integ in whitted path; do
    "$GT" "$SCENE" $ARGS --integrator $integ -o "$TMP/one_$integ.exr" || fail "single-process $integ render failed"
    run=$MPIRUN; [ $integ = whitted ] || run=$MPIRUN_NOLEAK
    $run -n 3 "$GT" "$SCENE" $ARGS --integrator $integ --mpi-block 16 -o "$TMP/mpi_$integ.exr" > "$TMP/log" 2>&1 ||
        fail "mpirun -n 3 $integ: exit status $?: $(cat "$TMP/log")"
    same "$TMP/one_$integ.exr" "$TMP/mpi_$integ.exr" "mpirun -n 3 --integrator $integ"
done
# the comparison can fail: another sample count differs
"$GT" "$SCENE" $ARGS --spp 3 -o "$TMP/other.exr" || fail "the --spp 3 render failed"
oiiotool "$TMP/one_whitted.exr" "$TMP/other.exr" --fail 0 --diff 2>&1 | grep -q '^PASS' &&
    fail "renders with 2 and 3 samples compare equal (the check is blind)"
# rank 0 only gathering, blocks that do not divide the image, two threads a rank, a crop (written as its region)
$MPIRUN_NOLEAK -n 3 "$GT" "$SCENE" $ARGS --threads 2 --mpi-block 20 --mpi-dedicated -o "$TMP/dedicated.exr" \
    > "$TMP/log" 2>&1 || fail "mpirun -n 3 --mpi-dedicated: exit status $?: $(cat "$TMP/log")"
same "$TMP/one_whitted.exr" "$TMP/dedicated.exr" "mpirun -n 3 --mpi-dedicated --mpi-block 20 --threads 2"
"$GT" "$SCENE" $ARGS --integrator path --crop 10,5,77,50 -o "$TMP/crop1.exr" || fail "the single crop failed"
$MPIRUN_NOLEAK -n 2 "$GT" "$SCENE" $ARGS --integrator path --crop 10,5,77,50 --mpi-block 16 -o "$TMP/crop2.exr" \
    > "$TMP/log" 2>&1 || fail "mpirun -n 2 --crop: exit status $?: $(cat "$TMP/log")"
same "$TMP/crop1.exr" "$TMP/crop2.exr" "mpirun -n 2 --crop 10,5,77,50 --integrator path"
oiiotool --info -v "$TMP/crop2.exr" | grep -q "pixel data origin: x=10, y=5" || fail "the MPI crop has no data window"
# the values at the model's wavelengths (--spectral) travel with the pixels
"$GT" "$SCENE" $ARGS --colormodel spectrum --spectral -o "$TMP/spec1.exr" || fail "the single --spectral render failed"
$MPIRUN_NOLEAK -n 3 "$GT" "$SCENE" $ARGS --colormodel spectrum --spectral --mpi-block 16 -o "$TMP/spec3.exr" \
    > "$TMP/log" 2>&1 || fail "mpirun -n 3 --spectral: exit status $?: $(cat "$TMP/log")"
same "$TMP/spec1.exr" "$TMP/spec3.exr" "mpirun -n 3 --spectral"
[ "$(oiiotool --info -v "$TMP/spec3.exr" | grep -o 'S0\.[0-9]*,[0-9]*nm' | wc -l)" -ge 81 ] ||
    fail "the MPI --spectral image lacks its spectral channels"
# the particle integrators: each rank traces a range of every photon batch, the sums keep a single process's order
# (bit-identical for 1, 2 and 3 ranks); the glass ball's caustic, one batch a pass, then several (110000 photons)
BALL=examples/scenes/glass_ball_caustic.scene
PARGS="--width 48 --passes 3 --photons 20000 --threads 1 -q"
# (under the sanitizers 2 ranks only: each MPI start-up there costs seconds of CPU)
RANKS="1 2 3"
! sanitized "$GT" || RANKS=2
for integ in sppm light; do
    "$GT" "$BALL" $PARGS --integrator $integ -o "$TMP/one_$integ.exr" || fail "single-process $integ render failed"
    for n in $RANKS; do
        run=$MPIRUN; [ $integ = sppm ] || run=$MPIRUN_NOLEAK
        $run -n $n "$GT" "$BALL" $PARGS --integrator $integ -o "$TMP/mpi_$integ$n.exr" > "$TMP/log" 2>&1 ||
            fail "mpirun -n $n --integrator $integ: exit status $?: $(cat "$TMP/log")"
        same "$TMP/one_$integ.exr" "$TMP/mpi_$integ$n.exr" "mpirun -n $n --integrator $integ"
    done
done
# (not blind: the focus is bright, and one pass more changes the image)
oiiotool --stats "$TMP/one_sppm.exr" | awk '/Stats Max/ { exit !($3 > 1.0) }' || fail "sppm: no bright caustic"
"$GT" "$BALL" $PARGS --passes 4 --integrator sppm -o "$TMP/other.exr" || fail "the --passes 4 render failed"
oiiotool "$TMP/one_sppm.exr" "$TMP/other.exr" --fail 0 --diff 2>&1 | grep -q '^PASS' &&
    fail "sppm renders with 3 and 4 passes compare equal (the check is blind)"
PARGS="--width 40 --passes 1 --photons 110000 -q --crop 4,3,36,27"
"$GT" "$BALL" $PARGS --threads 1 --integrator sppm -o "$TMP/one_batches.exr" || fail "the sppm crop failed"
$MPIRUN_NOLEAK -n 2 "$GT" "$BALL" $PARGS --threads 2 --integrator sppm -o "$TMP/mpi_batches.exr" > "$TMP/log" 2>&1 ||
    fail "mpirun -n 2 sppm, several batches: exit status $?: $(cat "$TMP/log")"
same "$TMP/one_batches.exr" "$TMP/mpi_batches.exr" "mpirun -n 2 sppm, several batches a pass, a crop, 2 threads"
# the summary line names the ranks
$MPIRUN_NOLEAK -n 2 "$GT" "$SCENE" --width 32 --spp 1 --threads 1 -o "$TMP/s.png" > "$TMP/log" 2>&1
grep -q "1 threads x 2 ranks" "$TMP/log" || fail "the summary does not name the ranks: $(cat "$TMP/log")"

# ---- failures: a message from rank 0, exit status 1, no image ----
failed_run() { # WHAT EXPECTED-MESSAGE OUT: the last mpirun failed, printed the message, wrote no OUT
    [ "$st" -ne 0 ] || fail "$1: exit status 0"
    [ "$st" -eq 124 ] && fail "$1: did not end within the test's timeout"
    grep -q -- "$2" "$TMP/log" || fail "$1: no message '$2': $(cat "$TMP/log")"
    ls "$3"* > /dev/null 2>&1 && fail "$1: an image (or a temporary file) was left: $(ls "$3"*)"
    ls "$TMP"/.*.tmp* > /dev/null 2>&1 && fail "$1: a temporary file was left"
}
# a rank that cannot read its scene (another node without the file, here another command line)
$MPIRUN -n 2 "$GT" "$SCENE" $ARGS -o "$TMP/f1.exr" : -n 1 "$GT" "$TMP/absent.scene" $ARGS -o "$TMP/f1.exr" \
    > "$TMP/log" 2>&1
st=$?
failed_run "a rank without the scene" "rank 2: cannot open \"$TMP/absent.scene\"" "$TMP/f1.exr"
# rank 0 itself cannot read it: its own message, the workers are released
$MPIRUN -n 1 "$GT" "$TMP/absent.scene" $ARGS -o "$TMP/f2.exr" : -n 2 "$GT" "$SCENE" $ARGS -o "$TMP/f2.exr" \
    > "$TMP/log" 2>&1
st=$?
failed_run "rank 0 without the scene" "^gtrace: cannot open \"$TMP/absent.scene\"" "$TMP/f2.exr"
# a rank started with other arguments would render another image
$MPIRUN -n 2 "$GT" "$SCENE" $ARGS -o "$TMP/f3.exr" : -n 1 "$GT" "$SCENE" $ARGS --spp 5 -o "$TMP/f3.exr" \
    > "$TMP/log" 2>&1
st=$?
failed_run "a rank with other arguments" "rank 2: it was started with other arguments" "$TMP/f3.exr"
# the module cannot be loaded
GTRACE_MPI_MODULE="$TMP/none.so" $MPIRUN -x GTRACE_MPI_MODULE -n 1 "$GT" "$SCENE" $ARGS -o "$TMP/f4.exr" > "$TMP/log" 2>&1
st=$?
failed_run "a missing module" "needs gtrace's MPI module gtrace_mpi.so" "$TMP/f4.exr"

# the PID of rank R of the job writing OUT, once it runs (empty after 20 s)
rank_pid() {
    i=0
    while [ $i -lt 200 ]; do
        for p in $(pgrep -f "gtrace.*$2"); do
            tr '\0' '\n' < "/proc/$p/environ" 2> /dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$1" && { echo "$p"; return; }
        done
        sleep 0.1
        i=$((i + 1))
    done
}
# waits until process PID has used 1 s of CPU (it is rendering; 60 s at most)
busy() {
    i=0
    while [ $i -lt 600 ]; do
        t=$(awk '{ print $14 + $15 }' "/proc/$1/stat" 2> /dev/null) || return
        [ "${t:-0}" -ge "$(getconf CLK_TCK)" ] && return
        sleep 0.1
        i=$((i + 1))
    done
}
# interrupt SIGNAL RANK NAME: a job writing TMP/NAME.exr, whose rank RANK gets SIGNAL once it renders; sets st
interrupt() {
    $MPIRUN -n 3 "$GT" "$SCENE" $BIG -o "$TMP/$3.exr" > "$TMP/log" 2>&1 &
    job=$!
    pid=$(rank_pid "$2" "$3.exr")
    [ -n "$pid" ] && busy "$pid" && kill "-$1" "$pid"
    wait $job
    st=$?
    [ -n "$pid" ] || fail "rank $2 of the $3 job was not found"
}
# a worker that stops answering (SIGSTOP: alive to the launcher) is declared dead after --mpi-timeout
# (many cheap blocks: no dispersion, depth 3, so that no block of a live rank takes near the timeout on a busy machine;
# about 3.5 s of CPU per rank in all, so that the signal, sent once the rank has used 1 s, comes while it renders)
BIG="--width 480 --spp 64 --depth 3 --bands 1 --threads 1 -q --mpi-block 16 --mpi-timeout 5"
t0=$(date +%s)
interrupt STOP 2 stopped
# (stopped while rendering, or, on a slow machine, before it reported its scene)
failed_run "a stopped worker" "rank 2 sent nothing for 5 s\|rank (2) did not report within 5 s" "$TMP/stopped.exr"
[ $(($(date +%s) - t0)) -le 60 ] || fail "a stopped worker: the job took $(($(date +%s) - t0)) s to end"
# a worker that dies: the launcher ends the job, rank 0 says what happened
interrupt KILL 1 killed
failed_run "a killed worker" "ended by its launcher" "$TMP/killed.exr"

# ---- one machine: no MPI library mapped ----
for c in "--help" "$SCENE -o $TMP/o.png --width 8 -q"; do
    LD_DEBUG=files LD_DEBUG_OUTPUT="$TMP/ld" "$GT" $c > /dev/null 2>&1 || fail "gtrace $c failed"
    cat "$TMP/ld".* > "$TMP/objects" 2> /dev/null
    rm -f "$TMP/ld".*
    grep -q 'generating link map' "$TMP/objects" || fail "gtrace $c: LD_DEBUG recorded nothing (the check is blind)"
    grep -q 'libmpi\|gtrace_mpi' "$TMP/objects" && fail "gtrace $c maps MPI: $(grep -m1 'libmpi\|gtrace_mpi' "$TMP/objects")"
done

[ $fails -eq 0 ] && echo "gtrace_mpi: 3 ranks bit-identical to one process (Whitted, path, gathering-only rank 0, a crop;" \
    "sppm and light with 1, 2, 3 ranks);" \
    "missing scene, other arguments, missing module, stopped and killed workers end the job with a message and no image;" \
    "no libmpi without mpirun"
exit $fails
