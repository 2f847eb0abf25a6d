#!/bin/sh
# gtrace_progress.sh BUILD - gtrace's progress when stderr is not a terminal: plain lines (no carriage returns)
# "gtrace: P% rendered, E s elapsed, about L s left", P rising to a last line at 100%, at least a tenth of the work
# apart; nothing with -q. GTRACE_PROGRESS_INTERVAL=0 drops the time between lines, so that the lines depend on the
# work alone (no clock in the assertions).
BUILD=${1:-build}
GT="$BUILD/bin/gtrace"
. "$(dirname "$0")/prelude.sh"
need_program "$GT"

cat > "$TMP/p.scene" << 'EOF'
material grey lambert { reflectance rgb 0.5 0.5 0.5 }
camera pinhole { from <0, 1, 4> at <0, 0.5, 0> fov 40 width 64 height 48 spp 1 depth 2 }
object plane { point <0, 0, 0> normal <0, 1, 0> material grey }
object sphere { center <0, 0.5, 0> radius 0.5 material grey }
light point { position <2, 4, 3> intensity rgb 20 20 20 }
EOF

# check_lines FILE WHAT MIN MAX: every line of FILE is a progress line, the percentages rise by at least 10 to 100,
# MIN..MAX lines
check_lines() {
    tr -d '\n' < "$1" | grep -q "$(printf '\r')" && fail "$2: a carriage return in: $(cat -A "$1")"
    awk -v what="$2" -v min="$3" -v max="$4" '
        /^gtrace: [0-9]+% rendered, [0-9]+\.[0-9] s elapsed, about [0-9]+\.[0-9] s left$/ ||
        /^gtrace: 100% rendered, [0-9]+\.[0-9] s elapsed$/ {
            p = $2 + 0
            if (n > 0 && p < last + 10) { print "FAIL: " what ": " p "% follows " last "%"; bad = 1 }
            if ((p == 100) != ($0 !~ /left$/)) { print "FAIL: " what ": the time left at " p "%"; bad = 1 }
            last = p; n++; next
        }
        { print "FAIL: " what ": not a progress line: " $0; bad = 1 }
        END {
            if (n < min || n > max) { print "FAIL: " what ": " n " lines, expected " min ".." max; bad = 1 }
            if (last != 100) { print "FAIL: " what ": the last line is at " last "%, not 100%"; bad = 1 }
            exit bad
        }' "$1" || fails=$((fails + 1))
}

# 12 tiles of 16x16 pixels, each a twelfth: a line every second tile (at least a tenth), 6 in all
for threads in 1 2; do
    GTRACE_PROGRESS_INTERVAL=0 "$GT" "$TMP/p.scene" -o "$TMP/p.png" --threads $threads > "$TMP/out" 2> "$TMP/err" ||
        fail "render with $threads threads: $(cat "$TMP/err")"
    check_lines "$TMP/err" "64x48, $threads threads" 6 6
    grep -q "^gtrace: .*p.png 64x48" "$TMP/out" || fail "no summary line on stdout: $(cat "$TMP/out")"
done
# 300 tiles: one line per tenth (10 lines), whatever the tiles' order
GTRACE_PROGRESS_INTERVAL=0 "$GT" "$TMP/p.scene" -o "$TMP/p.png" --width 320 --height 240 --threads 2 > /dev/null \
    2> "$TMP/err" || fail "320x240 render: $(cat "$TMP/err")"
check_lines "$TMP/err" "320x240" 10 10
# a crop counts its own pixels
GTRACE_PROGRESS_INTERVAL=0 "$GT" "$TMP/p.scene" -o "$TMP/c.exr" --crop 0,0,32,48 > /dev/null 2> "$TMP/err" ||
    fail "crop: $(cat "$TMP/err")"
check_lines "$TMP/err" "crop 32x48 (6 tiles)" 6 6
# -q: nothing at all
GTRACE_PROGRESS_INTERVAL=0 "$GT" "$TMP/p.scene" -o "$TMP/q.png" -q > "$TMP/out" 2> "$TMP/err" || fail "-q render failed"
[ -s "$TMP/err" ] && fail "-q printed progress: $(cat "$TMP/err")"
[ -s "$TMP/out" ] && fail "-q printed: $(cat "$TMP/out")"

[ $fails -eq 0 ] && echo "gtrace progress lines: all checks passed"
[ $fails -eq 0 ]
