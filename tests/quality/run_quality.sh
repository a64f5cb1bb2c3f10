#!/bin/sh
# One image-quality regression test (docs/quality.md): replay a bundled path
# with fixed settings, then compare summary.json with the checked-in
# expected metrics. With TRIMVR_UPDATE_EXPECTED=1 it rewrites the expected
# file instead (a deliberate, reviewed change).
#
#   run_quality.sh TRIMVR EXPECTED.json OUT_DIR NEEDS replay-options...
# NEEDS: a file the replay reads from ../shared (relative to $TRIMVR_SHARED),
# or - for none; when it is absent the test is skipped (exit 77).
set -u
trimvr=$1
expected=$2
out=$3
needs=$4
shift 4
if [ "$needs" != - ]; then
    shared=${TRIMVR_SHARED:-../shared}
    if [ ! -f "$shared/$needs" ]; then
        echo "skip: $shared/$needs absent (../shared not available)"
        exit 77
    fi
fi
rm -rf "$out"
"$trimvr" replay "$@" --no-plots --no-progress --out "$out" >"$out.log" 2>&1 || {
    cat "$out.log"
    echo "FAIL: trimvr replay $* exited non-zero"
    exit 1
}
here=$(dirname "$0")
if [ "${TRIMVR_UPDATE_EXPECTED:-0}" = 1 ]; then
    # the note names the run relative to the repository, so it is the same on every machine
    args=$(printf '%s' "$*" | sed "s|${TRIMVR_SOURCE_DIR:-/nonexistent}/||g")
    exec sh "$here/compare.sh" update "$expected" "$out/summary.json" \
        "trimvr replay $args (regenerate when tr, prediction or rendering change; docs/quality.md)"
fi
exec sh "$here/compare.sh" check "$expected" "$out/summary.json"
