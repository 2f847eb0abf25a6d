#!/bin/sh
# run_tests.sh [BUILD] - runs every test program in BUILD/tests (default build) and the script tests in
# tests/scripts/, TEST_JOBS at a time (default: the number of processors), prints PASS or FAIL for each as it
# ends, then the log of each failure and one summary line "N passed, N failed".
# The tests that assert time bounds or wait on timeouts, and those that run `make install` in this tree (SERIAL
# below), run afterwards, one at a time, with no other test loading the machine under them; in the parallel batch
# GENERIC_TEST_BATCH is set, and a time bound read there fails (tu_seconds in tests/test_util.h, serial_only in
# tests/scripts/prelude.sh). Test programs find the shared data and the source tree through GENERIC_SOURCE_DIR.
# Each test's output goes to its log: BUILD/tests/NAME.log, and its time to its PASS or FAIL line. A run that fails
# only because LeakSanitizer's thread tracer crashed ("Tracer caught signal") is repeated once (see --one below).
# (run_tests.sh --one BUILD PROGRAM runs one test: the form the parallel phase calls.)
SERIAL="test_image_limits test_reader_constants test_structures test_gtrace_instances large_scene.sh
limits.sh reuse_limits.sh structure_limits.sh gtrace_mpi.sh load_linear.sh install_test.sh lazy_oiio.sh"
# The parallel batch starts with the tests that take longest (20 to 90 s of CPU each, with or without the
# sanitizers), so that it does not end with one of them running alone on an otherwise idle machine; a test not
# named here runs after them, in the order of its name. The order changes nothing but the batch's length.
LONG_FIRST="readme_examples.sh texparam_conformance.sh coated_conformance.sh conformance.sh test_rough_dielectric
albedo_narrow.sh test_gtrace_caustics test_gtrace_sppm test_gtrace_path test_gtrace_media_grid outputs.sh
gtrace_merge.sh blend_conformance.sh scenes_all_models.sh check_gaps.sh bump_ideal_conformance.sh"

if [ "${1:-}" = "--one" ]; then
    BUILD=$2
    prog=$3
    name=$(basename "$prog")
    log="$BUILD/tests/$name.log"
    t0=$(date +%s.%N)
    note=""
    for attempt in 1 2; do
        case "$prog" in
        *.sh) "$prog" "$BUILD" > "$log" 2>&1 ;;
        *) "$prog" > "$log" 2>&1 ;;
        esac
        status=$?
        # LeakSanitizer's thread tracer itself can crash at exit while a library's threads (OpenImageIO's logging
        # pool) start or stop: a fault of the tool, not a leak and not the test's. Such a run is repeated once;
        # a leak, a second tracer crash or any other failure stands.
        [ "$status" -ne 0 ] && grep -q "^Tracer caught signal" "$log" && [ "$attempt" -eq 1 ] || break
        cp "$log" "$log.tracer-crash"
        note=", repeated once after LeakSanitizer's tracer crashed"
    done
    secs=$(echo "$(date +%s.%N) $t0" | awk '{printf "%.1f", $1 - $2}')
    # the processor time of the test and its children (the second line of `times`: user and system, "XmY.Zs")
    times > "$log.times"
    secs="$secs s, $(awk 'NR == 2 { split($1 "m" $2, t, "[ms]"); printf "%.1f", t[1] * 60 + t[2] + t[4] * 60 + t[5] }' \
        "$log.times") s CPU"
    rm -f "$log.times"
    echo "$status" > "$log.status"
    if [ "$status" -eq 0 ]; then
        cases=$(grep -c '^\[       OK \]' "$log")
        [ "$cases" -gt 0 ] && secs="$cases cases, $secs"
        echo "PASS $name ($secs$note)"
    else
        echo "FAIL $name ($secs$note)"
    fi
    exit 0
fi

BUILD=${1:-build}
# LeakSanitizer (GCC 12's) follows __tls_get_addr to find the dynamic TLS of shared objects, and guesses where a
# block starts by a test on its offset within its page that glibc's later allocations can pass by chance: a known
# upstream defect (google/sanitizers issue 1322, "Detecting GLIBC version (DTLS SIGSEGV)"), whose workaround is
# this one. With the 260 or so objects OpenImageIO brings in, it recorded a block at a bogus address (its log: "DTLS
# 9 at 0x1dbb-0x2c00002ebd") and its leak scan then faulted at exit ("Tracer caught signal 11"), every time for some
# builds of a test whose render reads an image texture (examples/scenes/demo.scene, one thread), while ASan and
# UBSan reported nothing and the pictures were those of the unsanitized build. The interception is turned off: leaks
# are still found from every other root (stacks, static TLS, globals, registers); only blocks reachable from a
# shared object's dynamic TLS alone are not roots, and none of ours is.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}intercept_tls_get_addr=0"
GENERIC_SOURCE_DIR=$(pwd)
GENERIC_BUILD_DIR=$(cd "$BUILD" && pwd)
export GENERIC_SOURCE_DIR GENERIC_BUILD_DIR
JOBS=${TEST_JOBS:-$(nproc 2> /dev/null || echo 1)}
# OpenMP's threads sleep at a barrier instead of spinning: with JOBS tests at a time, each with its own thread team,
# spinning threads take the processors the other tests need (a probe fit's test spent 75% of its CPU time so).
OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
export OMP_WAIT_POLICY
SELF="$0"

list=$(mktemp)
serial=$(mktemp)
trap 'rm -f "$list" "$serial"' EXIT
for t in "$BUILD"/tests/test_* tests/scripts/*.sh; do
    case "$t" in *.log | *.d | *.o | *.status) continue ;; esac
    [ -x "$t" ] || continue
    case " $(echo $SERIAL) " in
    *" $(basename "$t") "*) echo "$t" >> "$serial" ;;
    *) echo "$t" >> "$list" ;;
    esac
done
cat "$list" "$serial" | while read -r p; do rm -f "$BUILD/tests/$(basename "$p").log.status"; done
ordered=$(mktemp)
for name in $LONG_FIRST; do grep "/$name\$" "$list" >> "$ordered"; done
grep -v -x -F -f "$ordered" "$list" >> "$ordered"
mv "$ordered" "$list"

GENERIC_TEST_BATCH=parallel xargs -P "$JOBS" -I{} "$SELF" --one "$BUILD" {} < "$list"
while read -r p; do "$SELF" --one "$BUILD" "$p" < /dev/null; done < "$serial"

pass=0
fail=0
while read -r p; do
    log="$BUILD/tests/$(basename "$p").log"
    if [ "$(cat "$log.status" 2> /dev/null)" = "0" ]; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "==== FAIL $(basename "$p"): $log"
        cat "$log"
    fi
done << LIST
$(cat "$list" "$serial")
LIST
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
