#!/bin/sh
# SIGINT to `trimvr bench` once its first row is done: exit 130, stderr,
# bench.json and bench.md say it was interrupted, and bench.csv holds only complete rows (each of CELLS
# viewcells), fewer than the sweep has.
#   bench_sigint.sh TRIMVR OUT CELLS bench-option...
set -u
trimvr=$1
out=$2
cells=$3
shift 3
fail() {
    echo "FAIL: $*"
    exit 1
}
rm -rf "$out"
mkdir -p "$out"
err=$out.err
"$trimvr" bench --max-cells "$cells" --out "$out" "$@" >/dev/null 2>"$err" &
pid=$!
i=0
while [ $i -lt 1200 ] && ! grep -q ' cells, PVS ' "$err"; do
    sleep 0.1
    i=$((i + 1))
done
kill -INT $pid 2>/dev/null || fail "the sweep finished before it could be interrupted"
wait $pid
code=$?
cat "$err"
[ "$code" -eq 130 ] || fail "exit status $code after SIGINT, expected 130"
grep -q 'interrupted by signal 2' "$err" || fail "stderr does not say the run was interrupted"
[ -f "$out/bench.csv" ] || fail "no bench.csv: the finished rows were lost"
grep -q '"interrupted": true, "stopped": "interrupted by signal 2"' "$out/bench.json" || fail "bench.json does not say the sweep was interrupted"
grep -q 'Incomplete: interrupted by signal 2' "$out/bench.md" || fail "bench.md does not say the sweep was interrupted"
awk -F, -v cells="$cells" 'NR > 1 { rows++; if ($4 != cells) { print "FAIL: row of " $4 " viewcells: " $0; exit 1 } }
    END { if (rows < 1) { print "FAIL: no row"; exit 1 } print "ok: " rows " complete rows kept" }' "$out/bench.csv"
