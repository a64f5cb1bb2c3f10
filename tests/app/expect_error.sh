#!/bin/sh
# Runs a command that must fail on bad input and checks the failure is the
# one the brief asks for: non-zero exit (not a crash), exactly one line on
# stderr, and that line names the offending file.
# usage: expect_error.sh NEEDLE command args...
needle=$1
shift
err=$(mktemp)
"$@" >/dev/null 2>"$err"
code=$?
lines=$(wc -l <"$err")
msg=$(cat "$err")
rm -f "$err"
if [ "$code" -eq 0 ]; then
    echo "FAIL: exit status 0 for bad input: $*"
    exit 1
fi
if [ "$code" -ge 128 ]; then
    echo "FAIL: crashed with signal $((code - 128)): $*"
    exit 1
fi
if [ "$lines" -ne 1 ]; then
    echo "FAIL: expected one line on stderr, got $lines:"
    echo "$msg"
    exit 1
fi
case "$msg" in
*"$needle"*) echo "ok: exit $code: $msg" ;;
*)
    echo "FAIL: message does not name '$needle': $msg"
    exit 1
    ;;
esac
