#!/bin/sh
# conformance.sh BUILD - the conformance checks over every registered type, taken from the registry's own lists
# (gcolor list, gmat types): a new built-in is checked the moment it is registered.
#   - gcolor check over every colour model;
#   - gmat check over every material, node and generator type, in every registered colour model (under the
#     sanitizers each type in one model, the models in turn: the same code paths at a quarter of the cost). A violation
#     known and tracked would be listed in KNOWN below with its reason and must then still fail (so the list
#     cannot go stale); the list is empty. A fluorescent material folded into a model without re-radiation
#     matrices reflects more than 1 in a band under white light (blue light re-radiated as red); gmat check then
#     holds it to energy over all bands, the rule of material_params.h, which spectrum meets. rgb and spectrum9
#     hold the matrix's reduction to 3 x 3 and 9 x 9 (gcolormodel_reduce_reradiation), whose columns sum to at most 1.
#     The instance checked is a default one (`material m TYPE`, no parameters) when the type can be made so, else
#     the first named entry of that type in examples/materials/*.mat or examples/textures/*.txt; a generator
#     drives an interpolate node between two lamberts. A type with neither FAILS, asking for an example;
#     gmat check includes the sampling checks (chi2 of sample() against pdf(), the pdf's integral, the weights);
#   - the modules of tests/plugins/nonconforming.c must be reported as failing, naming the broken property
#     (misdrawn_lambert: chi2 alone; misflagged_lambert, whose glow a wrong GMAT_NO_EMISSION hides: no-emission
#     alone; misopaque_lambert, whose transparency a wrong GMAT_OPAQUE hides: opaque-flag alone; misnormal_lambert,
#     whose tilted normal a wrong GMAT_GEOMETRIC_NORMAL hides: geometric-normal alone; misdiffuse_lambert, whose
#     diffuse colour a wrong GMAT_LAMBERTIAN puts in place of its reflection: lambertian alone;
#     misuv_lambert, whose albedo follows u, which a wrong GMAT_NO_UV hides: no-uv alone; misdiag_lambert, whose
#     grey response to coloured light a wrong GMAT_DIAGONAL hides: diagonal alone; misideal_lambert, whose ideal ray
#     a wrong GMAT_NO_IDEAL hides: no-ideal alone; misrelindex_lambert, whose reflection follows the relative index
#     a wrong GMAT_NO_REL_INDEX hides: no-rel-index alone; misconstindex_lambert, whose refraction index follows u,
#     which a wrong GMAT_CONSTANT_INDEX hides: constant-index alone; misclear_lambert, whose medium absorbs, which
#     a wrong GMAT_CLEAR hides: clear alone),
#     and the example modules (examples/plugins/) must pass;
#   - lambert, phong and mirror with a re-radiation matrix for a colour (bispectral) pass, the sampling weights
#     included; light that moves between samples along the ideal ray alone is seen as re-radiation.
# Blends of materials with and without an ideal ray, generated in pairs and triples: blend_conformance.sh.
SRC=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=$(cd "${1:-build}" 2> /dev/null && pwd) || { echo "FAIL: no build directory ${1:-build}"; exit 1; }
GMAT="$BUILD/bin/gmat"
GCOLOR="$BUILD/bin/gcolor"
PLUGINS="$BUILD/plugins"
for t in "$GMAT" "$GCOLOR"; do
    [ -x "$t" ] || { echo "FAIL: $t is not built"; exit 1; }
done
. "$(dirname "$0")/prelude.sh"
checked=0
OPTS=$(check_opts "$GMAT") # gmat check's options (prelude.sh)

# ---- colour models ----
"$GCOLOR" list > "$TMP/models" || fail "gcolor list failed"
[ -s "$TMP/models" ] || fail "gcolor list printed no model"
while read -r model; do
    checked=$((checked + 1))
    "$GCOLOR" check "$model" > "$TMP/log" 2>&1 || fail "gcolor check $model:
$(cat "$TMP/log")"
    grep -q "^$model: PASS" "$TMP/log" || fail "gcolor check $model printed no verdict: $(cat "$TMP/log")"
done < "$TMP/models"

# ---- materials, nodes, generators ----
# KNOWN: "TYPE MODEL PROPERTY" for each violation known and tracked; a line must keep failing exactly so.
KNOWN=""
known_failure() { # TYPE MODEL: the known failing property, or nothing
    echo "$KNOWN" | awk -v t="$1" -v m="$2" '$1 == t && $2 == m { print $3; exit }'
}
# The named entries of the example files, listed once: "FILE KIND NAME TYPE" per line.
for f in "$SRC"/examples/materials/*.mat "$SRC"/examples/textures/*.txt; do
    "$GMAT" list "$f" 2> /dev/null | awk -v f="$f" '$2 != "(anonymous)" && NF >= 3 { print f, $1, $2, $3 }'
done > "$TMP/examples"
# first_entry KIND TYPE: "FILE NAME" of the first named entry of TYPE in the example files, or nothing.
first_entry() {
    awk -v k="$1" -v t="$2" '$2 == k && $4 == t { print $1, $3; exit }' "$TMP/examples"
}
# a generator's instance: an interpolate node between two lamberts, driven by it
driven() { # FILE-TO-WRITE GENERATOR [INCLUDE]
    {
        [ -n "$3" ] && echo "include \"$3\""
        echo "node conformance_node interpolate { a lambert { reflectance rgb 0.9 0.2 0.1 }"
        echo "    b lambert { reflectance rgb 0.1 0.3 0.8 }  t $2 }"
    } >> "$1"
}
"$GMAT" types > "$TMP/types" || fail "gmat types failed"
[ -s "$TMP/types" ] || fail "gmat types printed nothing"
while read -r kind type; do
    checked=$((checked + 1))
    file="$TMP/default_$type.txt"
    if [ "$kind" = generator ]; then
        echo "generator conformance_gen $type" > "$file"
        driven "$file" conformance_gen
        name=conformance_node
    else
        echo "$kind conformance_default $type" > "$file"
        name=conformance_default
    fi
    how="a default instance"
    if ! "$GMAT" list "$file" > /dev/null 2>&1; then
        entry=$(first_entry "$kind" "$type")
        if [ -z "$entry" ]; then
            fail "$kind $type: cannot be made with default parameters and no example file has a named entry of it:" \
                "add one to examples/materials/ or examples/textures/"
            continue
        fi
        efile=${entry% *}
        ename=${entry##* }
        how="$ename from ${efile#"$SRC"/}"
        if [ "$kind" = generator ]; then
            : > "$file"
            driven "$file" "$ename" "$efile"
            name=conformance_node
        else
            file=$efile
            name=$ename
        fi
    fi
    models=$(cat "$TMP/models")
    if sanitized "$GMAT"; then # the same code paths: each type in one model, the models in turn
        models=$(awk -v n="$checked" 'NR == 1 { c = 0 } { m[c++] = $0 } END { print m[n % c] }' "$TMP/models")
    fi
    for model in $models; do
        "$GMAT" check "$file" "$name" --colormodel "$model" $OPTS > "$TMP/log" 2>&1
        st=$?
        known=$(known_failure "$type" "$model")
        if [ -n "$known" ]; then
            # a known violation must still be exactly that one, else the list is stale
            if [ $st -eq 0 ]; then
                fail "$kind $type in $model passes now: remove it from KNOWN ($known)"
            elif ! grep -q "^$known .*FAIL" "$TMP/log" || [ "$(grep -Ec 'worst .* FAIL( |$)' "$TMP/log")" -ne 1 ]; then
                fail "$kind $type in $model ($how) fails otherwise than the known '$known':
$(cat "$TMP/log")"
            else
                echo "known: $kind $type in $model fails '$known' (listed in KNOWN)"
            fi
        elif [ $st -ne 0 ]; then
            fail "$kind $type in $model ($how):
$(cat "$TMP/log")"
        fi
    done
done < "$TMP/types"

# ---- modules that break a property on purpose must be reported, naming it ----
# expect_fail WHAT PROPERTY COMMAND...: the command fails and its FAIL line names PROPERTY.
expect_fail() {
    what=$1
    prop=$2
    shift 2
    checked=$((checked + 1))
    "$@" > "$TMP/log" 2>&1
    st=$?
    [ $st -eq 1 ] || fail "$what: exit status $st, expected 1: $(cat "$TMP/log")"
    grep -q "^$prop .*FAIL" "$TMP/log" || fail "$what: no FAIL line for '$prop': $(cat "$TMP/log")"
    [ "$(grep -Ec 'worst .* FAIL( |$)' "$TMP/log")" -eq 1 ] || fail "$what: more than '$prop' failed: $(cat "$TMP/log")"
}
echo "material m gain_lambert" > "$TMP/gain.mat"
echo "material m skewed_lambert" > "$TMP/skewed.mat"
echo "material m misdrawn_lambert" > "$TMP/misdrawn.mat"
echo "material m misflagged_lambert" > "$TMP/misflagged.mat"
echo "material m misopaque_lambert" > "$TMP/misopaque.mat"
echo "material m misnormal_lambert" > "$TMP/misnormal.mat"
echo "material m misdiffuse_lambert" > "$TMP/misdiffuse.mat"
echo "material m misuv_lambert" > "$TMP/misuv.mat"
echo "material m misdiag_lambert" > "$TMP/misdiag.mat"
echo "material m misideal_lambert" > "$TMP/misideal.mat"
echo "material m misrelindex_lambert" > "$TMP/misrelindex.mat"
echo "material m misconstindex_lambert" > "$TMP/misconstindex.mat"
echo "material m misclear_lambert" > "$TMP/misclear.mat"
expect_fail "gain_lambert (albedo 1.5)" albedo "$GMAT" check "$TMP/gain.mat" m --plugin "$PLUGINS/gain.so"
expect_fail "skewed_lambert (not reciprocal)" reciprocity "$GMAT" check "$TMP/skewed.mat" m --plugin "$PLUGINS/skewed.so"
expect_fail "misdrawn_lambert (samples uniformly, pdf cos/pi)" chi2 "$GMAT" check "$TMP/misdrawn.mat" m --plugin "$PLUGINS/misdrawn.so"
expect_fail "misflagged_lambert (GMAT_NO_EMISSION on a glow)" no-emission "$GMAT" check "$TMP/misflagged.mat" m \
    --plugin "$PLUGINS/misflagged.so"
expect_fail "misopaque_lambert (GMAT_OPAQUE on a transparent slot)" opaque-flag "$GMAT" check "$TMP/misopaque.mat" m \
    --plugin "$PLUGINS/misopaque.so"
expect_fail "misnormal_lambert (GMAT_GEOMETRIC_NORMAL on a tilted normal)" geometric-normal "$GMAT" check \
    "$TMP/misnormal.mat" m --plugin "$PLUGINS/misnormal.so"
expect_fail "misdiffuse_lambert (GMAT_LAMBERTIAN on a diffuse colour that is not the reflection's)" lambertian \
    "$GMAT" check "$TMP/misdiffuse.mat" m --plugin "$PLUGINS/misdiffuse.so"
expect_fail "misuv_lambert (GMAT_NO_UV on a reflection that reads u)" no-uv "$GMAT" check "$TMP/misuv.mat" m \
    --plugin "$PLUGINS/misuv.so"
expect_fail "misdiag_lambert (GMAT_DIAGONAL on a reflection that mixes the light's samples)" diagonal "$GMAT" check \
    "$TMP/misdiag.mat" m --plugin "$PLUGINS/misdiag.so"
expect_fail "misideal_lambert (GMAT_NO_IDEAL on a reflection_dir that gives a ray)" no-ideal "$GMAT" check \
    "$TMP/misideal.mat" m --plugin "$PLUGINS/misideal.so"
expect_fail "misrelindex_lambert (GMAT_NO_REL_INDEX on a reflection that reads the index)" no-rel-index "$GMAT" \
    check "$TMP/misrelindex.mat" m --plugin "$PLUGINS/misrelindex.so"
expect_fail "misconstindex_lambert (GMAT_CONSTANT_INDEX on a refraction index that follows u)" constant-index \
    "$GMAT" check "$TMP/misconstindex.mat" m --plugin "$PLUGINS/misconstindex.so"
expect_fail "misclear_lambert (GMAT_CLEAR on a medium that absorbs exp(-0.1 length))" clear "$GMAT" check \
    "$TMP/misclear.mat" m --plugin "$PLUGINS/misclear.so"
expect_fail "bad_add (wrong add)" "a + black = a" "$GCOLOR" check bad_add --plugin "$PLUGINS/bad_add.so"
expect_fail "bad_bands (overlapping bands)" "bands partition a" "$GCOLOR" check bad_bands --plugin "$PLUGINS/bad_bands.so"

# ---- plain materials whose colours are re-radiation matrices (bispectral) pass, sampling included: a sampled
# direction's weight is what the matrix makes of white light, a vector, as material.h defines it ----
checked=$((checked + 1))
cat > "$TMP/matrix.mat" << 'EOM'
colormodel bispectral
color dayglo reradiation { absorb_peak 470 absorb_width 115 absorb_shape 8 absorb_max 0.97
    emit_width 20 stokes_shift 135 quantum_yield 0.65 reflectance 0.92 }
material matte lambert { reflectance dayglo }
material glossy phong { diffuse dayglo specular rgb 0.04 0.04 0.04 exponent 30 }
material mirrored phong { diffuse dayglo specular rgb 0.02 0.02 0.02 exponent 30 mirror rgb 0.03 0.03 0.03 }
material shiny mirror { reflectance dayglo }
material tinted phong { diffuse rgb 0.05 0.05 0.05 mirror dayglo }
EOM
for m in matte glossy mirrored shiny tinted; do
    "$GMAT" check "$TMP/matrix.mat" $m > "$TMP/log" 2>&1 || fail "$m with a re-radiation matrix: $(cat "$TMP/log")"
done

# ---- the example modules pass ----
checked=$((checked + 1))
cat > "$TMP/oren.mat" << 'EOM'
material rough oren_nayar { reflectance rgb 0.8 0.6 0.4  sigma 30 }
material smooth oren_nayar { sigma 0 }
EOM
for m in rough smooth; do
    for model in rgb bispectral; do
        "$GMAT" check "$TMP/oren.mat" $m --colormodel $model --plugin "$PLUGINS/oren_nayar.so" > "$TMP/log" 2>&1 ||
            fail "oren_nayar $m in $model: $(cat "$TMP/log")"
    done
done
"$GCOLOR" check grey --plugin "$PLUGINS/grey.so" > "$TMP/log" 2>&1 || fail "gcolor check grey: $(cat "$TMP/log")"
# the bands generator from its module, driven inside a node like the built-in generators
echo "generator g bands" > "$TMP/bands.txt"
driven "$TMP/bands.txt" g
"$GMAT" check "$TMP/bands.txt" conformance_node --plugin "$PLUGINS/bands.so" > "$TMP/log" 2>&1 ||
    fail "bands generator: $(cat "$TMP/log")"

if [ $fails -gt 0 ]; then
    echo "$fails failure(s) in $checked checks"
    exit 1
fi
echo "conformance: $checked checks passed"
