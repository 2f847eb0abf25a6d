#!/bin/sh
# gen_reference.sh [BUILD] - writes the reference pages of the registered types from the built tools:
# docs/reference/types.md (`gmat types --markdown`: the library's colour models, colours, materials, nodes and
# generators) and docs/reference/scene-types.md (`gtrace types --markdown`: gtrace's objects, lights and cameras).
# Run it after changing a type's parameter table; tests/scripts/reference_docs.sh checks that the pages are current.
set -eu
BUILD=${1:-build}
for t in gmat gtrace; do
    [ -x "$BUILD/bin/$t" ] || { echo "gen_reference.sh: $BUILD/bin/$t is not built (make tools)" >&2; exit 1; }
done
mkdir -p docs/reference
unset GENERIC_PLUGIN_PATH
"$BUILD/bin/gmat" types --markdown > docs/reference/types.md.tmp
"$BUILD/bin/gtrace" types --markdown > docs/reference/scene-types.md.tmp
mv docs/reference/types.md.tmp docs/reference/types.md
mv docs/reference/scene-types.md.tmp docs/reference/scene-types.md
echo "gen_reference.sh: wrote docs/reference/types.md and docs/reference/scene-types.md"
