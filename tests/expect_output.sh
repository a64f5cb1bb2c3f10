#!/bin/sh
# Runs a command and checks both its exit status and its output, which a
# ctest PASS_REGULAR_EXPRESSION cannot: with one, ctest ignores the exit
# status, so a validation error reported at exit (non-zero status) or a crash
# after the expected line would pass.
#   expect_output.sh STATUS REGEX command args...
# STATUS: 0, or "fail" for any non-zero status that is not a signal. REGEX: an
# extended regular expression matched against stdout and stderr together as
# one text ('.' also matches newlines, as in ctest's expressions).
want=$1
re=$2
shift 2
out=$(mktemp)
"$@" >"$out" 2>&1
code=$?
cat "$out"
RE=$re awk 'BEGIN { RS = "\001" } $0 ~ ENVIRON["RE"] { found = 1 } END { exit !found }' "$out"
matched=$?
rm -f "$out"
if [ "$code" -ge 128 ]; then
    echo "FAIL: killed by signal $((code - 128)): $*"
    exit 1
fi
if [ "$want" = 0 ] && [ "$code" -ne 0 ]; then
    echo "FAIL: exit status $code, expected 0: $*"
    exit 1
fi
if [ "$want" = fail ] && [ "$code" -eq 0 ]; then
    echo "FAIL: exit status 0, expected a failure: $*"
    exit 1
fi
if [ "$matched" -ne 0 ]; then
    echo "FAIL: the output does not match: $re"
    exit 1
fi
echo "ok: exit status $code, output matches"
