#!/bin/sh
# run_generated.sh - the generated inputs of one fuzz target (`make fuzz`, `make fuzz-gen`):
#
#   tests/fuzz/run_generated.sh TARGET SEED COUNT BUDGET TIMEOUT MEMORY_MB [FUZZ_BUILD]
#
# fuzz_gen writes COUNT structured inputs of up to BUDGET bytes for TARGET (a target of tests/fuzz/) into
# FUZZ_BUILD/gen/TARGET/, and the target's libFuzzer binary runs them as files (each once, through the same
# entry point as fuzzing, in large mode: GFUZZ_LARGE=1, see tests/fuzz/fuzz_entry.h), with TIMEOUT seconds and
# MEMORY_MB megabytes (resident, and per allocation) per input. An input that crashes, times out, runs out of
# memory or breaks a promise of the entry point is reported with what happened, kept in
# FUZZ_BUILD/crashes/TARGET/ under its generated name, and the run goes on with the inputs after it; the exit
# status is 1 when any failed. SEED 0 draws a seed (printed, so the run can be repeated).
set -u
target=$1 seed=$2 count=$3 budget=$4 timeout=$5 mem=$6 build=${7:-build/fuzz}
bin=$build/fuzz_$target
dir=$build/gen/$target
crashes=$build/crashes/$target
log=$build/gen_$target.log
if [ "$seed" = 0 ]; then
    seed=$(od -An -N4 -tu4 /dev/urandom | tr -d ' ')
fi
rm -rf "$dir"
mkdir -p "$dir" "$crashes" "$build/gen/artifacts"
if ! "$build/fuzz_gen" "$target" "$seed" "$count" "$dir" "$budget" > "$dir.list"; then
    echo "fuzz-gen $target: the generator failed"
    exit 1
fi
case $target in
image | probe) leaks=0 ;; # OpenImageIO's file cache grows between inputs (as in the libFuzzer runs)
*) leaks=1 ;;
esac
total=$(wc -l < "$dir.list")
echo "fuzz-gen $target: $total inputs (seed $seed, up to $budget bytes, $timeout s and $mem MB each)"

# The inputs not yet run, in order; after a failure, the ones after the failing input.
set -- $(cut -f1 "$dir.list")
failed=0 slowest=0 slowest_name=
start=$(date +%s)
while [ $# -gt 0 ]; do
    GFUZZ_LARGE=1 OPENIMAGEIO_OPTIONS=try_all_readers=0 "$bin" -timeout="$timeout" -rss_limit_mb="$mem" \
        -malloc_limit_mb="$mem" -detect_leaks=$leaks -artifact_prefix="$build/gen/artifacts/" "$@" > "$log" 2>&1
    rc=$?
    # the slowest input that finished
    slow=$(sed -n 's/^Executed \(.*\) in \([0-9]*\) ms$/\2 \1/p' "$log" | sort -n | tail -n 1)
    if [ -n "$slow" ] && [ "${slow%% *}" -gt "$slowest" ]; then
        slowest=${slow%% *} slowest_name=$(basename "${slow#* }")
    fi
    [ $rc -eq 0 ] && break
    input=$(sed -n 's/^Running: //p' "$log" | tail -n 1)
    if [ -z "$input" ]; then
        echo "fuzz-gen $target: FAILED before the first input (status $rc):"
        tail -n 20 "$log"
        failed=$((failed + 1))
        break
    fi
    if grep -q "^Executed $input in" "$log"; then
        # every input ran; the failure came at exit (a leak)
        what="at exit, after the last input ran (one of the batch leaked?)"
    elif grep -q 'ERROR: libFuzzer: timeout' "$log"; then
        what="TIMEOUT (more than $timeout s)"
    elif grep -q 'out-of-memory (malloc' "$log"; then
        what="OUT OF MEMORY: $(grep -o 'out-of-memory (malloc([0-9]*))' "$log" | head -n 1) over $mem MB"
    elif grep -q 'out-of-memory' "$log"; then
        what="OUT OF MEMORY (resident over $mem MB)"
    elif grep -q 'AddressSanitizer: stack-overflow' "$log"; then
        # the innermost frame in the project's sources (not the sanitizer's own)
        frame=$(sed -n '/stack-overflow/,$p' "$log" | grep -m1 -E ' #[0-9]+ .* in [^ ]+ [^ ]*\.(c|cpp):[0-9]+' |
            sed 's/^.* in //; s|[^ ]*/\([a-z]*/[^/ ]*:[0-9]*\)|\1|')
        what="STACK OVERFLOW in $frame"
    elif grep -q 'runtime error:' "$log"; then
        what="UNDEFINED BEHAVIOUR: $(grep -m1 'runtime error:' "$log")"
    elif grep -q 'ERROR: AddressSanitizer\|ERROR: LeakSanitizer' "$log"; then
        what="MEMORY ERROR: $(grep -m1 'ERROR: [A-Za-z]*Sanitizer' "$log")"
    elif grep -q "^fuzz_$target: " "$log"; then
        what="BROKEN PROMISE: $(grep -m1 "^fuzz_$target: " "$log" | cut -c1-300)"
    elif grep -q 'terminate called\|uncaught exception' "$log"; then
        what="C++ EXCEPTION: $(grep -m1 -A1 'terminate called\|uncaught exception' "$log" | tr '\n' ' ' | cut -c1-300)"
    else
        what="CRASH: $(grep -m1 'ERROR: libFuzzer\|deadly signal\|Segmentation\|Aborted' "$log" || echo "status $rc")"
    fi
    name=$(basename "$input")
    size=$(wc -c < "$input" | tr -d ' ')
    cp "$input" "$crashes/$name"
    cp "$log" "$crashes/$name.log"
    failed=$((failed + 1))
    echo "fuzz-gen $target: $name ($size bytes): $what"
    echo "    kept in $crashes/$name (log $crashes/$name.log); repeat with:"
    echo "    GFUZZ_LARGE=1 $bin -timeout=$timeout -rss_limit_mb=$mem -malloc_limit_mb=$mem $crashes/$name"
    # go on after the failing input
    while [ $# -gt 0 ] && [ "$1" != "$input" ]; do shift; done
    [ $# -gt 0 ] && shift
done
echo "fuzz-gen $target: $((total - failed)) of $total passed in $(($(date +%s) - start)) s; slowest that passed:" \
    "${slowest_name:-none} ${slowest} ms"
[ $failed -eq 0 ]
