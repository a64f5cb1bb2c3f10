#!/bin/sh
# Assertions on `trimvr replay` outputs, in POSIX sh + awk (no Python on a
# fresh Debian). Usage:
#   replay_checks.sh summary DIR 'key op value'...   e.g. 'viewcell_miss_frames == 0'
#       ("inf", written for the PSNR of identical images, compares as +inf;
#       null, a metric that is not a number, fails every comparison;
#       'psnr_min_db == inf' asserts identical images)
#   replay_checks.sh csv DIR MIN_ROWS                frames.csv well formed, >= MIN_ROWS rows
#   replay_checks.sh same DIR1 DIR2                  frames.csv equal except wall-clock columns
#   replay_checks.sh keys DIR1 DIR2 key...           these summary.json values equal in both
#   replay_checks.sh interrupt DIR SECONDS command...  kill -9 the command mid-run, then check csv
#   replay_checks.sh sigint DIR SECONDS command...     SIGINT mid-run into a folder holding an older
#       run's outputs: non-zero exit, "interrupted" on stderr, summary.json marked interrupted with
#       as many frames as frames.csv has complete rows, and no file of the older run left
#   replay_checks.sh sigint-render DIR SECONDS command...  SIGINT mid-run of trimvr render: non-zero
#       exit, "interrupted" on stderr, frames.csv rows complete
#   replay_checks.sh sigterm-load DIR SECONDS command...  SIGTERM once the command's stderr names
#       the Vulkan device (the scene is loading, nothing computed yet): non-zero exit, "interrupted"
#       on stderr; for a replay, DIR/summary.json marked interrupted with 0 frames
#   replay_checks.sh pvs-again DIR TRIMVR SCENE pvs-option...  pvs.csv's last single-frustum PVS computed
#       again by `trimvr pvs` from its row (centre, direction, up, delta, PVS FOV): the same triangle count
set -u
mode=$1
shift

# pvs_again DIR TRIMVR SCENE pvs-option...: see the usage above
pvs_again() {
    f=$1/pvs.csv
    trimvr=$2
    scene=$3
    shift 3
    [ -f "$f" ] || fail "$f missing"
    row=$(awk -F, 'NR > 1 && $18 == 1 && $20 == 0 { r = $0 } END { print r }' "$f")
    [ -n "$row" ] || fail "$f: no single-frustum PVS"
    args=$(echo "$row" | awk -F, '{ printf "--pos %s,%s,%s --dir %s,%s,%s --up %s,%s,%s --delta %s --fov-pvs %s", \
        $6, $7, $8, $9, $10, $11, $12, $13, $14, $15, $16 }')
    want=$(echo "$row" | cut -d, -f21)
    # shellcheck disable=SC2086 # args holds separate options
    got=$("$trimvr" pvs --scene "$scene" $args "$@" 2>/dev/null | awk '/^PVS \(/ { print $3 }')
    [ "$got" = "$want" ] || fail "pvs.csv row $(echo "$row" | cut -d, -f1): trimvr pvs $args gives '$got' triangles, the replay had $want"
    echo "ok: PVS $(echo "$row" | cut -d, -f1) computed again: $got triangles"
}

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

# waits (at most SECONDS) until DIR/frames.csv has a few rows, to interrupt a run mid-way
wait_rows() {
    i=0
    while [ $i -lt $(($2 * 10)) ]; do
        rows=0
        [ -f "$1/frames.csv" ] && rows=$(($(wc -l <"$1/frames.csv") - 1))
        [ "$rows" -ge 4 ] && break
        sleep 0.1
        i=$((i + 1))
    done
}

# waits (at most SECONDS) until FILE holds TEXT
wait_text() {
    i=0
    while [ $i -lt $(($2 * 10)) ] && ! grep -q "$3" "$1" 2>/dev/null; do
        sleep 0.1
        i=$((i + 1))
    done
}

# run_and_signal DIR SECONDS SIG command...: runs the command in the background, sends it SIG once
# DIR/frames.csv has a few rows (DIR empty: once stderr names the Vulkan device) and waits; sets
# code (exit status) and msg (stderr)
run_and_signal() {
    dir=$1
    secs=$2
    sig=$3
    err=$(mktemp)
    shift 3
    "$@" >/dev/null 2>"$err" &
    pid=$!
    if [ -n "$dir" ]; then wait_rows "$dir" "$secs"; else wait_text "$err" "$secs" "vulkan device"; fi
    kill -"$sig" $pid 2>/dev/null || fail "the run finished before it could be interrupted"
    wait $pid
    code=$?
    msg=$(cat "$err")
    rm -f "$err"
}

# the checks after SIGINT: a non-zero exit that stderr explains
check_sigint() {
    [ "$code" -ne 0 ] || fail "exit status 0 after SIGINT"
    case "$msg" in *interrupted*) ;; *) fail "stderr does not say the run was interrupted: $msg" ;; esac
}

case $mode in
pvs-again)
    pvs_again "$@"
    ;;
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
keys)
    d1=$1
    d2=$2
    shift 2
    for k in "$@"; do
        v1=$(grep "^ *\"$k\": " "$d1/summary.json") || fail "$d1/summary.json has no $k"
        v2=$(grep "^ *\"$k\": " "$d2/summary.json") || fail "$d2/summary.json has no $k"
        [ "$v1" = "$v2" ] || fail "$k differs: $v1 against $v2"
        echo "ok: $v1 in both"
    done
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
    run_and_signal "$dir" "$secs" KILL "$@" # hard, mid-run
    [ -f "$dir/summary.json" ] && fail "summary.json exists: the run was not interrupted"
    check_csv "$dir" 4
    ;;
sigint)
    dir=$1
    secs=$2
    shift 2
    rm -rf "$dir"
    mkdir -p "$dir"
    echo '{"frames": 999}' >"$dir/summary.json"
    echo stale >"$dir/plot_psnr.png"
    run_and_signal "$dir" "$secs" INT "$@"
    check_sigint
    [ -f "$dir/plot_psnr.png" ] && fail "the older run's plot_psnr.png is still there"
    rows=$(($(wc -l <"$dir/frames.csv") - 1))
    grep -q '"interrupted": true' "$dir/summary.json" || fail "summary.json is not marked \"interrupted\": true"
    sh "$0" summary "$dir" "frames == $rows" || exit 1
    check_csv "$dir" 4
    echo "ok: exit $code, $rows rows: $msg"
    ;;
sigint-render)
    dir=$1
    secs=$2
    shift 2
    rm -rf "$dir"
    run_and_signal "$dir" "$secs" INT "$@"
    check_sigint
    check_csv "$dir" 4
    echo "ok: exit $code: $msg"
    ;;
sigterm-load)
    out=$1
    secs=$2
    shift 2
    run_and_signal "" "$secs" TERM "$@"
    check_sigint
    if [ "$2" = replay ]; then
        grep -q '"interrupted": true' "$out/summary.json" || fail "$out/summary.json is not marked \"interrupted\": true"
        sh "$0" summary "$out" "frames == 0" || exit 1
    fi
    echo "ok: exit $code: $(echo "$msg" | grep interrupted)"
    ;;
*)
    fail "unknown mode $mode"
    ;;
esac
