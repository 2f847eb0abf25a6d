#!/bin/sh
# reference_docs.sh BUILD - the committed reference pages are what the tools print from the registry:
# docs/reference/types.md is `gmat types --markdown` and docs/reference/scene-types.md is `gtrace types --markdown`
# (scripts/gen_reference.sh writes both), so a parameter table changed without its page fails here.
BUILD=${1:-build}
SRC=${GENERIC_SOURCE_DIR:-$(pwd)}
. "$SRC/tests/scripts/prelude.sh"
need_program "$BUILD/bin/gmat"
need_program "$BUILD/bin/gtrace"
unset GENERIC_PLUGIN_PATH
# page TOOL FILE: the page TOOL prints must equal FILE
page() {
    if ! "$BUILD/bin/$1" types --markdown > "$TMP/page" 2> "$TMP/err"; then
        fail "$1 types --markdown: $(cat "$TMP/err")"
        return
    fi
    if [ ! -f "$SRC/$2" ]; then
        fail "$2 is missing: run scripts/gen_reference.sh"
    elif ! cmp -s "$TMP/page" "$SRC/$2"; then
        fail "$2 is not what \`$1 types --markdown\` prints (run scripts/gen_reference.sh):
$(diff "$SRC/$2" "$TMP/page" | head -n 20)"
    else
        echo "$2: $(grep -c '^### ' "$TMP/page") types, as \`$1 types --markdown\` prints it"
    fi
}
page gmat docs/reference/types.md
page gtrace docs/reference/scene-types.md
exit $fails
