#!/bin/sh
# type_params.sh BUILD - every registered type has its parameter table (GTypeInfo.params), and the table names
# what its parse routine reads. The library's kinds are asked of gmat (with the example plug-ins loaded, so their
# types count too), gtrace's object, light and camera kinds of gtrace.
#   a) `TOOL types --markdown` prints a table for every type that `TOOL types KIND` lists; a type without a table,
#      an empty table (except the types of EMPTY), a parameter named twice, a value type outside the vocabulary of
#      generic/registry.h or a row without its text fails.
#   c) drift: an entry of each type with an unknown parameter (`material x lambert { nosuchparam 1 }`) is loaded;
#      the names that the parse routine's message expects ("unknown parameter 'nosuchparam' (expected one of: ...)")
#      must be the names of the table's named rows. The types of SKIP read no block of named parameters; they are
#      not asked, for the reason given there (and an entry of SKIP must still name a registered type).
BUILD=${1:-build}
SRC=${GENERIC_SOURCE_DIR:-$(pwd)}
. "$SRC/tests/scripts/prelude.sh"
GMAT="$BUILD/bin/gmat"
GTRACE="$BUILD/bin/gtrace"
need_program "$GMAT"
need_program "$GTRACE"
unset GENERIC_PLUGIN_PATH
PLUGINS=""
for p in grey oren_nayar bands; do
    [ -f "$BUILD/plugins/$p.so" ] || { echo "FAIL: $BUILD/plugins/$p.so is not built"; exit 1; }
    PLUGINS="$PLUGINS --plugin $BUILD/plugins/$p.so"
done
VOCABULARY=" number numbers integer bool string path vector color material generator choice formula block shape object medium phase "
VOCABULARY="$VOCABULARY texnumber texcolor " # textured parameters (kit/texparam.h)
EMPTY="phase:isotropic generator:surface"
SKIP="color:rgb:reads R G B (or <R, G, B>) after the keyword, no block of named parameters
color:spectrum:reads a positional block of wavelength/value pairs
color:blackbody:reads its temperature after the keyword
color:illuminant:reads the illuminant's name after the keyword
color:line:reads a wavelength and an optional power after the keyword
color:bfc:reads a file name after the keyword
color:scale:reads a factor and a colour after the keyword
color:rgbspace:reads a colour space's name and R G B after the keyword
object:group:reads its member objects (and a transform) in a positional block"

# rows TOOL-ARGS...: the page's types and rows as lines "type KIND NAME STATE" (STATE: table, empty or none) and
# "row KIND NAME PARAM FORM TYPE DOC-LENGTH".
rows() {
    "$@" types --markdown | awk '
        /^### / { kind = $2; name = $3; gsub(/`/, "", name); state = "none"; print "type", kind, name, "pending"; next }
        /^No parameters\.$/ { print "type", kind, name, "empty"; next }
        /^\| `/ {
            line = $0
            gsub(/\\\|/, "\001", line)
            n = split(line, c, "|")
            for (i = 2; i < n; i++) { gsub(/^ +| +$/, "", c[i]) }
            param = c[2]; gsub(/`/, "", param)
            print "type", kind, name, "table"
            print "row", kind, name, param, c[3], c[4], length(c[7])
        }'
}

# ---- a) a table for every registered type ----
check_page() { # LABEL KINDS TOOL-ARGS...
    label=$1 kinds=$2
    shift 2
    rows "$@" > "$TMP/rows"
    # the state of each type: "table" or "empty" replace "pending"; "pending" alone is a missing table
    awk '$1 == "type" { k = $2 " " $3; if (s[k] == "" || s[k] == "pending") s[k] = $4 }
         END { for (k in s) print k, s[k] }' "$TMP/rows" | sort > "$TMP/states"
    for kind in $kinds; do
        "$@" types "$kind" | sort > "$TMP/listed.$kind"
        awk -v k="$kind" '$1 == k { print $1, $2 }' "$TMP/states" | sort > "$TMP/paged.$kind"
        [ -s "$TMP/listed.$kind" ] || fail "$label types $kind lists nothing"
        cmp -s "$TMP/listed.$kind" "$TMP/paged.$kind" ||
            fail "$label: the types of kind $kind and the page's differ: $(diff "$TMP/listed.$kind" "$TMP/paged.$kind")"
    done
    while read -r kind name state; do
        case "$state" in
        table) ;;
        empty) case " $EMPTY " in *" $kind:$name "*) ;; *) fail "$kind $name: its parameter table is empty" ;; esac ;;
        *) fail "$kind $name: no parameter table (GENERIC_TYPE_PARAMS, generic/plugin.h)" ;;
        esac
    done < "$TMP/states"
    awk '$1 == "row" { print $2, $3, $4 }' "$TMP/rows" | sort | uniq -d | while read -r kind name param; do
        echo "FAIL: $kind $name: parameter $param is in its table twice"
    done > "$TMP/dups"
    [ -s "$TMP/dups" ] && fail "$(cat "$TMP/dups")"
    while read -r what kind name param form type doclen; do
        [ "$what" = row ] || continue
        case "$VOCABULARY" in *" $type "*) ;; *) fail "$kind $name: parameter $param has the type '$type'" ;; esac
        case "$form" in named | positional) ;; *) fail "$kind $name: parameter $param has the form '$form'" ;; esac
        [ "$doclen" -gt 0 ] || fail "$kind $name: parameter $param says nothing of what it does"
    done < "$TMP/rows"
    cat "$TMP/rows" >> "$TMP/all_rows"
    echo "a) $label: $(wc -l < "$TMP/states") types with $(grep -c '^row' "$TMP/rows") parameters in their tables"
}
: > "$TMP/all_rows"
# shellcheck disable=SC2086
check_page gmat "colormodel color material node generator" "$GMAT" $PLUGINS
check_page gtrace "object light camera medium phase" "$GTRACE"

# ---- c) the tables against the parse routines' lists ----
asked=0
skipped=0
awk '$1 == "type" && $4 != "pending" { print $2, $3 }' "$TMP/all_rows" | sort -u > "$TMP/types"
echo "$SKIP" | while IFS=: read -r kind name reason; do
    grep -qx "$kind $name" "$TMP/types" || echo "FAIL: SKIP names $kind $name, which is not registered"
done > "$TMP/stale"
[ -s "$TMP/stale" ] && fail "$(cat "$TMP/stale")"
while read -r kind name; do
    reason=$(echo "$SKIP" | awk -F: -v k="$kind" -v n="$name" '$1 == k && $2 == n { sub(/^[^:]*:[^:]*:/, ""); print }')
    if [ -n "$reason" ]; then
        echo "c) $kind $name: not asked, it $reason"
        skipped=$((skipped + 1))
        continue
    fi
    case $kind in
    colormodel) entry="colormodel $name { nosuchparam 1 }" ;;
    object | light | camera) entry="$kind $name { nosuchparam 1 }" ;;
    *) entry="$kind x $name { nosuchparam 1 }" ;;
    esac
    echo "$entry" > "$TMP/entry.txt"
    case $kind in
    object | light | camera | medium | phase) "$GTRACE" "$TMP/entry.txt" -o "$TMP/out.png" --width 1 --height 1 > "$TMP/log" 2>&1 ;;
    # shellcheck disable=SC2086
    *) "$GMAT" list "$TMP/entry.txt" $PLUGINS > "$TMP/log" 2>&1 ;;
    esac
    expected=$(sed -n "s/.*$kind $name: unknown parameter 'nosuchparam' (expected one of: \(.*\))\$/\1/p" "$TMP/log")
    if [ -z "$expected" ]; then
        fail "$kind $name: \`$entry\` did not fail with the parse routine's list of parameters: $(cat "$TMP/log")"
        continue
    fi
    asked=$((asked + 1))
    [ "$expected" = "(none)" ] && expected=""
    echo "$expected" | tr ',' '\n' | sed 's/^ *//; s/ *$//; /^$/d' | sort > "$TMP/routine"
    awk -v k="$kind" -v n="$name" '$1 == "row" && $2 == k && $3 == n && $5 == "named" { print $4 }' "$TMP/all_rows" |
        sort > "$TMP/table"
    cmp -s "$TMP/routine" "$TMP/table" ||
        fail "$kind $name: the parse routine expects [$(paste -sd' ' "$TMP/routine")], the table names" \
             "[$(paste -sd' ' "$TMP/table")]"
done < "$TMP/types"
echo "c) $asked types asked with an unknown parameter, each routine's list the table's names; $skipped not asked"
exit $fails
