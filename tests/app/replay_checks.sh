#!/bin/sh
# Assertions on `trimvr replay` outputs, in POSIX sh + awk (no Python on a
# fresh Debian). Usage:
#   replay_checks.sh summary DIR 'key op value'...   e.g. 'viewcell_miss_frames == 0'
#       ("inf", written for the PSNR of identical images, compares as +inf;
#       null, a metric that is not a number, fails every comparison;
#       'psnr_min_db == inf' asserts identical images)
#   replay_checks.sh csv DIR MIN_ROWS                frames.csv well formed, >= MIN_ROWS rows
#   replay_checks.sh same DIR1 DIR2                  frames.csv equal except wall-clock columns
#   replay_checks.sh interrupt DIR SECONDS command...  kill -9 the command mid-run, then check csv
set -u
mode=$1
shift

fail() {
    echo "FAIL: $*"
    exit 1
}

check_csv() {
    f=$1/frames.csv
    [ -f "$f" ] || fail "$f missing"
    [ -z "$(tail -c 1 "$f")" ] || fail "$f: last row is not complete (no final newline)"
    awk -F, -v min="$2" 'NR == 1 { n = NF; next }
        NF != n { printf "FAIL: %s line %d has %d fields, header has %d\n", FILENAME, NR, NF, n; bad = 1; exit 1 }
        END { if (bad) exit 1; if (NR - 1 < min) { printf "FAIL: %d rows, expected >= %d\n", NR - 1, min; exit 1 }
              printf "ok: %d well-formed rows\n", NR - 1 }' "$f"
}

case $mode in
summary)
    dir=$1
    shift
    json=$dir/summary.json
    [ -f "$json" ] || json=$dir/eval.json
    [ -f "$json" ] || fail "$dir has neither summary.json nor eval.json"
    status=0
    for cond in "$@"; do
        set -- $cond
        awk -v key="$1" -v op="$2" -v want="$3" '
            !found && match($0, "\"" key "\": *[^,}]+") {
                v = substr($0, RSTART, RLENGTH); sub(/^[^:]*: */, "", v); found = 1
                inf = (v == "\"inf\""); x = v + 0
                if (v == "null" || (v !~ /^-?[0-9.]+([eE][-+]?[0-9]+)?$/ && !inf)) ok = 0
                else if (want == "inf") ok = inf && op == "=="
                else if (op == "==") ok = !inf && x == want
                else if (op == ">=") ok = inf || x >= want
                else if (op == "<=") ok = !inf && x <= want
                else if (op == ">") ok = inf || x > want
                else if (op == "<") ok = !inf && x < want
                printf "%s: %s %s %s %s\n", ok ? "ok" : "FAIL", key, v, op, want
                exit ok ? 0 : 1
            }
            END { if (!found) { printf "FAIL: %s not in summary\n", key; exit 1 } }' "$json" || status=1
    done
    exit $status
    ;;
csv)
    check_csv "$1" "$2"
    ;;
same)
    strip() {
        awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i ~ /_ms$/ && $i != "pose_age_ms" && $i != "pvs_age_ms" && $i != "pred_horizon_ms") skip[i] = 1 }
            { out = ""; for (i = 1; i <= NF; i++) if (!skip[i]) out = out $i ","; print out }' "$1/frames.csv"
    }
    a=$(mktemp)
    b=$(mktemp)
    strip "$1" >"$a"
    strip "$2" >"$b"
    if cmp -s "$a" "$b"; then
        echo "ok: logs identical apart from wall-clock columns ($(wc -l <"$a") lines)"
        rm -f "$a" "$b"
    else
        diff "$a" "$b" | head -5
        rm -f "$a" "$b"
        fail "logs differ"
    fi
    ;;
interrupt)
    dir=$1
    secs=$2
    shift 2
    rm -rf "$dir"
    "$@" >/dev/null 2>&1 &
    pid=$!
    i=0
    # wait until a few rows exist, then kill hard mid-run
    while [ $i -lt $((secs * 10)) ]; do
        rows=0
        [ -f "$dir/frames.csv" ] && rows=$(($(wc -l <"$dir/frames.csv") - 1))
        [ "$rows" -ge 4 ] && break
        sleep 0.1
        i=$((i + 1))
    done
    kill -9 $pid 2>/dev/null || fail "the replay finished before it could be interrupted"
    wait $pid 2>/dev/null
    [ -f "$dir/summary.json" ] && fail "summary.json exists: the run was not interrupted"
    check_csv "$dir" 4
    ;;
*)
    fail "unknown mode $mode"
    ;;
esac
