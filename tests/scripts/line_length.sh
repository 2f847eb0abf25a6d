#!/bin/sh
# Every line of the C and C++ sources git tracks is at most 120 columns,
# the project's limit: long lines are named FILE:LINE with their length. (BUILD, the usual argument, is not used.)
set -u
cd "$(dirname "$0")/../.." || exit 1
if ! git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    echo "line_length: SKIPPED outside a git checkout"
    exit 0
fi
long=$(git ls-files '*.c' '*.h' '*.cpp' '*.hpp' | xargs awk 'length > 120 { print FILENAME ":" FNR ": " length }')
if [ -n "$long" ]; then
    echo "$long"
    echo "line_length: FAIL: $(echo "$long" | wc -l) lines over 120 columns"
    exit 1
fi
echo "line_length: $(git ls-files '*.c' '*.h' '*.cpp' '*.hpp' | wc -l) files, no line over 120 columns"
