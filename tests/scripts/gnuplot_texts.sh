#!/bin/sh
# gnuplot_texts.sh BUILD - the figures of gmat plot and gprobe eval --plot as the scripts they hand gnuplot: a
# stand-in gnuplot on PATH keeps each script and runs the real one. Texts are drawn as written (noenhanced: a
# name such as ggx_conductor keeps its underscore instead of starting a subscript) and carry the names
# literally; the rings of --log-radius are one per decade with short labels (not '3e-013e+00'); the legends sit
# outside the plots (gmat plot: above the plot's box; gprobe: in a strip under both panels).
BUILD=${1:-build}
. tests/scripts/prelude.sh
need_program "$BUILD/bin/gmat"
need_program "$BUILD/bin/gprobe"
need_command gnuplot gnuplot-nox
REAL=$(command -v gnuplot)
mkdir -p "$TMP/bin"
cat > "$TMP/bin/gnuplot" << EOF
#!/bin/sh
n=\$(ls "$TMP"/script*.gp 2> /dev/null | wc -l)
tee "$TMP/script\$n.gp" | "$REAL" "\$@"
EOF
chmod +x "$TMP/bin/gnuplot"
GMAT=$(cd "$BUILD/bin" && pwd)/gmat
GPROBE=$(cd "$BUILD/bin" && pwd)/gprobe
cat > "$TMP/m.mat" << 'EOF'
material ggx_conductor phong { diffuse rgb 0.1 0.1 0.1 specular rgb 0.5 0.5 0.5 exponent 200 mirror rgb 0.04 0.04 0.04 }
EOF
# the value of `set NAME at screen V` (a margin) in script $1
margin() { sed -n "s/^set $2 at screen \([0-9.]*\)$/\1/p" "$1"; }

# ---- gmat plot, logarithmic radius ----
PATH="$TMP/bin:$PATH" "$GMAT" plot "$TMP/m.mat" ggx_conductor --in 40 --log-radius -o "$TMP/p.png" > "$TMP/out" 2>&1 ||
    fail "gmat plot: $(cat "$TMP/out")"
s="$TMP/script0.gp"
[ -f "$s" ] || { echo "FAIL: gmat plot ran no gnuplot"; exit 1; }
grep -q "^set terminal pngcairo noenhanced " "$s" ||
    fail "gmat plot: the terminal is not noenhanced: $(grep terminal "$s")"
grep -q "'ggx_conductor (phong, rgb)" "$s" || fail "gmat plot: the title does not carry ggx_conductor as written"
[ -s "$TMP/p.png" ] || fail "gmat plot wrote no picture"
# the rings: at least 3 labelled, each a power of ten in at most 4 characters, a decade (1.0 in plot units) apart
sed -n "s/^set rtics (\(.*\))$/\1/p" "$s" | tr ',' '\n' | sed -n "s/^ *'\([^']*\)' \([0-9.]*\)$/\1 \2/p" > "$TMP/rings"
bad=$(awk 'NF == 2 { n++; e = log($1) / log(10); f = e - int(e + (e < 0 ? -0.5 : 0.5))
     if (length($1) > 4 || f * f > 1e-12) printf " %s is not a short power of ten;", $1
     if (n > 1 && ($2 - last < 0.999 || $2 - last > 1.001)) printf " rings %g apart;", $2 - last; last = $2 }
     END { if (n < 3) printf " %d labels;", n }' "$TMP/rings")
[ -z "$bad" ] || fail "gmat plot --log-radius rings:$bad
$(cat "$TMP/rings")"
# the legend's top is above the plot's box, whose top margin it leaves alone
key=$(sed -n 's/^set key at screen 0.5, screen \([0-9.]*\) center top.*/\1/p' "$s")
top=$(margin "$s" tmargin)
if [ -z "$key" ] || [ -z "$top" ]; then
    fail "gmat plot: no legend position ('$key') or top margin ('$top')"
elif ! awk -v k="$key" -v t="$top" 'BEGIN { exit !(k > t + 0.05) }'; then
    fail "gmat plot: the legend (top $key) is not above the plot (top $top)"
fi

# ---- gprobe eval --plot ----
"$GPROBE" sky -o "$TMP/sky_probe.hdr" --height 16 > "$TMP/out" 2>&1 || fail "gprobe sky: $(cat "$TMP/out")"
rm -f "$TMP"/script*.gp
PATH="$TMP/bin:$PATH" "$GPROBE" eval --probe "$TMP/sky_probe.hdr" --normals 200 --counts 2,4 \
    --techniques adaptive,sh,sh9 --plot "$TMP/f.png" --title 'sky_probe_v2' -q > "$TMP/out" 2>&1 ||
    fail "gprobe eval --plot: $(cat "$TMP/out")"
s="$TMP/script0.gp"
[ -f "$s" ] || { echo "FAIL: gprobe eval --plot ran no gnuplot"; exit 1; }
grep -q "^set terminal pngcairo noenhanced " "$s" ||
    fail "gprobe: the terminal is not noenhanced: $(grep terminal "$s")"
grep -q "^set multiplot title 'sky_probe_v2'" "$s" || fail "gprobe: the title does not carry sky_probe_v2 as written"
grep -q "title 'sh9 (9 coefficients)'" "$s" || fail "gprobe: the legend lacks the sh9 line"
# the legend's strip is under the panels: its top below their bottom margin
panel=$(margin "$s" bmargin | head -n 1)
strip=$(margin "$s" tmargin | tail -n 1)
if [ -z "$panel" ] || [ -z "$strip" ]; then
    fail "gprobe: no panel margin ('$panel') or legend strip ('$strip')"
elif ! awk -v p="$panel" -v k="$strip" 'BEGIN { exit !(k > 0 && k < p) }'; then
    fail "gprobe: the legend's strip (top $strip) is not under the panels (bottom $panel)"
fi
[ -s "$TMP/f.png" ] || fail "gprobe eval --plot wrote no picture"
[ $fails -eq 0 ] && echo "gnuplot_texts: names drawn as written, short log rings, legends beside the plots"
exit $fails
