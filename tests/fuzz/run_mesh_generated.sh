#!/bin/sh
# run_mesh_generated.sh - gtrace's mesh readers on generated hostile meshes (tests/fuzz/gen/gen_mesh.c):
#
#   tests/fuzz/run_mesh_generated.sh FUZZ_GEN GTRACE SEED COUNT BUDGET TIMEOUT MEMORY_MB
#
# FUZZ_GEN (the generator, fuzz_gen) writes COUNT mesh inputs of up to BUDGET bytes; each is placed in a one-mesh
# scene and rendered small by GTRACE (one thread) under TIMEOUT seconds and an address-space limit of MEMORY_MB
# megabytes. An input must load (exit 0) or be refused with a message at the scene's FILE:LINE:COL (exit 1); a
# signal, a time-out or a message without a position is a failure, its input kept in the printed directory. Prints
# one line per input (family, bytes, outcome, seconds, peak resident KiB from /usr/bin/time) and, per family, the
# largest input; the exit status is 1 when any failed.
set -u
gen=$1 gtrace=$2 seed=$3 count=$4 budget=$5 timeout=$6 mem=$7
dir=$(mktemp -d)
export GENERIC_DECODE_FAULT=by-name # the fault-* families make gtrace's mesh reader process fail
if ! "$gen" mesh "$seed" "$count" "$dir" "$budget" > "$dir/list"; then
    echo "run_mesh_generated: the generator failed"
    exit 1
fi
TIME=/usr/bin/time
[ -x "$TIME" ] || TIME=
failed=0
while IFS="$(printf '\t')" read -r input family bytes; do
    name=$(basename "$input")
    cat > "$dir/s.scene" << E
material m lambert { reflectance rgb 0.5 0.5 0.5 }
camera pinhole { from <0.3, 0.3, 3> at <0.3, 0.3, 0> width 8 height 6 spp 1 }
light ambient { color rgb 1 1 1 }
object mesh { file "$name" material m }
E
    start=$(date +%s.%N)
    (
        ulimit -v $((mem * 1024))
        if [ -n "$TIME" ]; then
            exec "$TIME" -f "peak %M" -o "$dir/time" timeout "$timeout" "$gtrace" "$dir/s.scene" -q --threads 1 \
                -o "$dir/out.png"
        fi
        exec timeout "$timeout" "$gtrace" "$dir/s.scene" -q --threads 1 -o "$dir/out.png"
    ) > "$dir/out" 2>&1
    st=$?
    took=$(echo "$(date +%s.%N) - $start" | bc)
    peak=$(sed -n 's/^peak //p' "$dir/time" 2> /dev/null)
    case $st in
    0) outcome=loaded ;;
    1) outcome=refused
       grep -q "s.scene:4:[0-9]*: " "$dir/out" || outcome="refused without a position" ;;
    124) outcome="TIME-OUT" ;;
    *) outcome="status $st" ;;
    esac
    case $outcome in loaded | refused) ;; *) failed=$((failed + 1)); cp "$dir/out" "$dir/$name.log" ;; esac
    printf '%s\t%s\t%s\t%s s\t%s KiB\t%s\n' "$family" "$bytes" "$outcome" "$took" "${peak:-?}" \
        "$(head -c 160 "$dir/out" | tr '\n' ' ')"
done < "$dir/list" | tee "$dir/report"
failed=$(grep -c -v -P '\t(loaded|refused)\t' "$dir/report")
echo "largest input of each family:"
sort -t "$(printf '\t')" -k1,1 -k2,2n "$dir/report" |
    awk -F '\t' '{ last[$1] = $0 } END { for (f in last) print "  " last[f] }'
if [ "$failed" -gt 0 ]; then
    echo "run_mesh_generated: $failed input(s) failed; kept in $dir"
    exit 1
fi
rm -rf "$dir"
echo "run_mesh_generated: every input loaded or was refused at its entry"
