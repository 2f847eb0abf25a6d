#!/bin/sh
# gcolor_convert.sh BUILD - `gcolor convert`: one machine-readable line per colour literal, with the figures the
# colorimetry gives (sRGB red's XYZ is the matrix column, D65 and E lights have their white points, a grey keeps its
# value in every sample), --samples in the model's own grid (a re-radiation matrix by its diagonal), the named
# illuminants' chromaticities within 2e-4 of the CIE's, and bad literals or options refused with the right status.
BUILD=${1:-build}
GC="$BUILD/bin/gcolor"
. "$(dirname "$0")/prelude.sh"
need_program "$GC"

# field LINE NAME K: the K-th number after the word NAME in LINE
field() {
    echo "$1" | awk -v name="$2" -v k="$3" '{ for (i = 1; i <= NF; i++) if ($i == name) { print $(i + k); exit } }'
}
# near WHAT GOT WANT TOL
near() {
    awk -v g="$2" -v w="$3" -v t="$4" 'BEGIN { d = g - w; if (d < 0) d = -d; exit !(g != "" && d <= t) }' ||
        fail "$1: $2, expected $3 within $4"
}

line=$("$GC" convert --colormodel rgb 'rgb 1 0 0') || fail "rgb 1 0 0 failed"
case "$line" in "rgb 1 0 0: XYZ "*" xy "*" sRGB "*" brightness "*) ;; *) fail "not the documented line: $line" ;; esac
near "rgb red X" "$(field "$line" XYZ 1)" 0.4124564 1e-6
near "rgb red Y" "$(field "$line" XYZ 2)" 0.2126729 1e-6
near "rgb red Z" "$(field "$line" XYZ 3)" 0.0193339 1e-6
near "rgb red x" "$(field "$line" xy 1)" 0.64 1e-6
near "rgb red r" "$(field "$line" sRGB 1)" 1 1e-6

# one line per literal, in order, white space made single spaces
out=$("$GC" convert --role light 'illuminant D65' 'illuminant
    E' 'blackbody 6504') || fail "three lights failed"
[ "$(echo "$out" | wc -l)" = 3 ] || fail "not one line per literal: $out"
d65=$(echo "$out" | sed -n 1p) e=$(echo "$out" | sed -n 2p)
case "$e" in "illuminant E: "*) ;; *) fail "the second line is not the literal on one line: $e" ;; esac
near "D65 x" "$(field "$d65" xy 1)" 0.31272 2e-4
near "D65 y" "$(field "$d65" xy 2)" 0.32903 2e-4
near "D65 Y" "$(field "$d65" XYZ 2)" 1 1e-3
near "E x" "$(field "$e" xy 1)" 0.333333 1e-4
near "E y" "$(field "$e" xy 2)" 0.333333 1e-4

# a reflectance grey under D65 is D65's chromaticity and its sRGB value
grey=$("$GC" convert --colormodel spectrum 'rgb 0.5 0.5 0.5')
near "grey r" "$(field "$grey" sRGB 1)" 0.5 1e-4
near "grey Y" "$(field "$grey" XYZ 2)" 0.5 1e-4

# --samples: the model's grid, NM:VALUE pairs
s9=$("$GC" convert --colormodel spectrum9 --samples 'rgb 0.5 0.5 0.5')
n=$(echo "$s9" | sed 's/.* samples //' | tr ' ' '\n' | grep -c ':')
[ "$n" = 9 ] || fail "spectrum9 --samples: $n samples, expected 9: $s9"
echo "$s9" | sed 's/.* samples //' | tr ' ' '\n' | awk -F: '{ d = $2 - 0.5; if (d < 0) d = -d; if (d > 1e-3) bad = 1 }
    END { exit bad }' || fail "spectrum9 --samples: a grey's samples are not 0.5: $s9"
first=$(echo "$s9" | sed 's/.* samples \([^ ]*\).*/\1/')
[ "${first%%:*}" = 380 ] || fail "spectrum9 --samples: the first wavelength is not 380: $first"
# a re-radiation matrix gives its diagonal: the not-absorbed reflectance far from the absorption band (0.92 *
# (1 - 0.97 * shape)), much less than its folded response
mat=$("$GC" convert --colormodel bispectral --samples 'reradiation { absorb_max 0.5 }')
v470=$(echo "$mat" | tr ' ' '\n' | sed -n 's/^470://p')
near "matrix diagonal at the absorption peak" "$v470" 0.46 1e-3

# the named illuminants: xy (CIE 1931 2 degree, 380..780 nm) within 2e-4 of the CIE's published values (CIE 15:2004)
# in the spectrum model at 1 nm; at its default 5 nm the model's hat-weighted sampling spreads the mercury lines of
# the F series over 10 nm, which moves y by up to 4.5e-4 (D50 and A, smooth, stay within 2e-4)
while read -r name x y tol5; do
    for step in 1 5; do
        l=$("$GC" convert --colormodel spectrum --step $step --role light "illuminant $name") ||
            { fail "illuminant $name"; continue; }
        tol=2e-4
        [ $step = 5 ] && tol=$tol5
        near "$name x at $step nm" "$(field "$l" xy 1)" "$x" $tol
        near "$name y at $step nm" "$(field "$l" xy 2)" "$y" $tol
        near "$name Y at $step nm" "$(field "$l" XYZ 2)" 1 1e-3
    done
done <<'LIST'
F2 0.37210 0.37510 5e-4
F11 0.38050 0.37690 5e-4
D50 0.34570 0.35850 2e-4
A 0.44757 0.40745 2e-4
D75 0.29902 0.31485 2e-4
LED-B1 0.4560 0.4078 3e-4
LIST
# a reflectance seen under a named illuminant: under D65 as by default, white under F11 is F11's white point
d=$("$GC" convert --illuminant D65 'rgb 0.5 0.2 0.1') plain=$("$GC" convert 'rgb 0.5 0.2 0.1')
near "under D65: X" "$(field "$d" XYZ 1)" "$(field "$plain" XYZ 1)" 1e-6
near "under D65: Z" "$(field "$d" XYZ 3)" "$(field "$plain" XYZ 3)" 1e-6
w=$("$GC" convert --illuminant F11 --step 1 'rgb 1 1 1')
near "white under F11: x" "$(field "$w" xy 1)" 0.38050 2e-4
near "white under F11: y" "$(field "$w" xy 2)" 0.37690 2e-4
near "white under F11: Y" "$(field "$w" XYZ 2)" 1 1e-4
# every listed name reads as a literal, and a name not listed does not
count=0
for name in $("$GC" list --illuminants); do
    count=$((count + 1))
    "$GC" convert --role light "illuminant $name" > /dev/null || fail "listed illuminant $name does not convert"
done
[ $count = 29 ] || fail "gcolor list --illuminants lists $count names, expected 29"

# refusals: a bad literal is status 1 with the reader's message; bad options are status 2
"$GC" convert 'rgb 1 0' > "$TMP/out" 2> "$TMP/err"
[ $? = 1 ] || fail "a short rgb literal is not status 1"
grep -q "expected a number" "$TMP/err" || fail "a short rgb literal: no reader message: $(cat "$TMP/err")"
[ -s "$TMP/out" ] && fail "a failed literal printed a line"
"$GC" convert 'rgb 1 0 0 color d rgb 1 1 1' > /dev/null 2> "$TMP/err"
[ $? = 1 ] || fail "two entries in one literal are not status 1"
"$GC" convert 'illuminant Q9' > /dev/null 2> "$TMP/err"
[ $? = 1 ] || fail "an unknown illuminant is not status 1"
for args in "--colormodel nosuch rgb_1" "--role nosuch x" "" "--colormodel rgb --samples x" "--step 7 x" "--step -1 x" \
    "--illuminant D93 x" "--illuminant A --role light x"; do
    # shellcheck disable=SC2086
    "$GC" convert $args > /dev/null 2>&1
    [ $? = 2 ] || fail "gcolor convert $args: not status 2"
done
exit $fails
