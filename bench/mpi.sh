#!/bin/sh
# mpi.sh [BUILD] - what distributed rendering costs on this machine (docs/distributed.md):
#   1. parallel efficiency on examples/scenes/demo.scene (480 wide, 4 spp): one process with 1 and 2 threads,
#      and mpirun with 2 ranks x 1 thread, rank 0 rendering too and rank 0 only gathering (--mpi-dedicated);
#   2. the per-block overhead of the MPI path: 2 ranks, rank 0 only gathering, so rank 1 renders every 16x16
#      block and sends it, against one process with 1 thread, on a cheap render (1 spp);
#   3. gathering and writing a 3840x2160 float EXR: a background-only scene, so that the time is the transfer
#      (99.5 MB of pixels from rank 1 to rank 0) and the write.
# Runs are interleaved (the machine is shared) and the medians of MPI_BENCH_REPS runs (default 3) reported:
# render = the seconds of gtrace's summary line (rank 0's loop, gathering included; no start-up, no load, no
# write), wall = the whole command (mpirun's start-up included). Prints figures; never fails on time.
# shellcheck disable=SC2086 # option lists ($ARGS, $MPIRUN, ...) are split into words on purpose
BUILD=${1:-build}
GT="$BUILD/bin/gtrace"
SCENE=$(dirname "$0")/../examples/scenes/demo.scene
REPS=${MPI_BENCH_REPS:-3}
[ -x "$GT" ] || { echo "bench-mpi: $GT is not built"; exit 1; }
"$GT" --version | grep -q "MPI module" || { echo "bench-mpi: gtrace was built without MPI"; exit 0; }
command -v mpirun > /dev/null || { echo "bench-mpi: mpirun (openmpi-bin) is missing"; exit 1; }
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
MPIRUN="mpirun --oversubscribe --allow-run-as-root --bind-to none"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

# run NAME CMD...: appends "render wall" of one run to TMP/NAME
run() {
    name=$1
    shift
    t0=$(date +%s.%N)
    "$@" > "$TMP/log" 2>&1 || { echo "bench-mpi: $name failed: $(tail -3 "$TMP/log")"; return 1; }
    t1=$(date +%s.%N)
    awk -v w="$(echo "$t1 - $t0" | bc)" '/^gtrace: .* rays/ { for (i = 1; i <= NF; i++) if ($i == "s,") t = $(i - 1) }
        END { if (t == "") t = "nan"; print t, w }' "$TMP/log" >> "$TMP/$name"
}
median() { # FILE COLUMN
    sort -n -k"$2" "$1" | awk -v c="$2" '{ v[NR] = $c } END { print v[int((NR + 1) / 2)] }'
}

# ---- 1. parallel efficiency ----
DEMO="$SCENE --width 480 --spp 4 -o $TMP/demo.exr"
for _ in $(seq "$REPS"); do
    run t1 "$GT" $DEMO --threads 1
    run t2 "$GT" $DEMO --threads 2
    run r2 $MPIRUN -n 2 "$GT" $DEMO --threads 1
    run r2d $MPIRUN -n 2 "$GT" $DEMO --threads 1 --mpi-dedicated
done
T1=$(median "$TMP/t1" 1)
echo "1. demo.scene 480x270, 4 spp: medians of $REPS interleaved runs (speed-up = T(1 thread) / T; efficiency ="
echo "   speed-up / 2 for the 2-worker runs)"
printf '%-34s %9s %9s %9s %11s\n' "" "render s" "wall s" "speed-up" "efficiency"
for c in "t1:1 process x 1 thread" "t2:1 process x 2 threads" "r2:2 ranks x 1 thread" \
         "r2d:2 ranks x 1 thread, rank 0 gathers"; do
    f=${c%%:*}
    [ -s "$TMP/$f" ] || continue
    t=$(median "$TMP/$f" 1)
    s=$(echo "$T1 / $t" | bc -l)
    e=$([ "$f" = t1 ] && echo "-" || printf '%.0f%%' "$(echo "50 * $s" | bc -l)")
    printf '%-34s %9.2f %9.2f %8.2fx %11s\n' "${c#*:}" "$t" "$(median "$TMP/$f" 2)" "$s" "$e"
done

# ---- 2. per-block overhead ----
CHEAP="$SCENE --width 480 --spp 1 --depth 2 -o $TMP/cheap.exr --threads 1"
for _ in $(seq "$REPS"); do
    run c1 "$GT" $CHEAP
    run c16 $MPIRUN -n 2 "$GT" $CHEAP --mpi-dedicated --mpi-block 16
done
C1=$(median "$TMP/c1" 1)
C16=$(median "$TMP/c16" 1)
H=$(oiiotool --info "$TMP/cheap.exr" 2>/dev/null | sed -n 's/.*: *[0-9]* x *\([0-9]*\),.*/\1/p')
H=${H:-270}
N=$(( ((480 + 15) / 16) * ((H + 15) / 16) ))
echo "2. per-block overhead: 480x$H, 1 spp, depth 2, 16x16 blocks ($N), 1 thread rendering"
echo "$C1 $C16 $N" | awk '{ printf "   one process %.3f s, rank 1 of 2 (rank 0 gathering) %.3f s: %.0f us a block (%.1f%% of a block'"'"'s %.0f us)\n", $1, $2, 1e6 * ($2 - $1) / $3, 100 * ($2 - $1) / $1, 1e6 * $1 / $3 }'

# ---- 3. gathering and writing a 4K image ----
cat > "$TMP/empty.scene" << 'EOF2'
camera pinhole { from <0, 0, 4> at <0, 0, 0> fov 40 width 3840 height 2160 spp 1 }
light background { color rgb 0.2 0.3 0.4 }
EOF2
for _ in $(seq "$REPS"); do
    run k1 "$GT" "$TMP/empty.scene" -o "$TMP/4k.exr" --threads 1
    run k2 $MPIRUN -n 2 "$GT" "$TMP/empty.scene" -o "$TMP/4k.exr" --threads 1 --mpi-dedicated
    run kb $MPIRUN -n 2 "$GT" "$TMP/empty.scene" -o "$TMP/4k.exr" --threads 1 --mpi-dedicated --mpi-block 256
done
echo "3. 3840x2160 float EXR (99.5 MB of pixels), background only, 1 thread a rank, rank 0 gathering:"
echo "   one process: render $(median "$TMP/k1" 1) s, whole command $(median "$TMP/k1" 2) s (the write is most of the rest)"
echo "   2 ranks, 64-pixel blocks (2040): render + gather $(median "$TMP/k2" 1) s, whole command $(median "$TMP/k2" 2) s"
echo "   2 ranks, 256-pixel blocks (135): render + gather $(median "$TMP/kb" 1) s, whole command $(median "$TMP/kb" 2) s"
