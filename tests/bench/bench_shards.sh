#!/bin/sh
# Sharded trimvr bench (docs/bench.md), as cli_bench_parallel runs it:
#   bench_shards.sh TRIMVR OUT OPTIONS...
# runs the sweep OPTIONS serially and as `--jobs --cells-per-job 1` shards
# (one viewcell each) under GNU parallel
# -j2, merges the parts, and requires bench.csv of both to be equal in every
# column but the timings (*_ms, pvs_over_full). Then the merge's refusals,
# each exit status 1 with one line naming the file: parts of another
# version or other settings, a shard given twice, a shard missing, a file
# that is not a part.
set -u
trimvr=$1 out=$2
shift 2
command -v parallel >/dev/null 2>&1 || { echo "skip: GNU parallel not installed (scripts/setup.sh installs it)"; exit 77; }
rm -rf "$out" && mkdir -p "$out" || exit 1
t0=$(date +%s)
"$trimvr" bench "$@" --out "$out/serial" >"$out/serial.log" 2>&1 || { tail -5 "$out/serial.log"; echo "FAIL: serial run"; exit 1; }
t1=$(date +%s)
"$trimvr" bench "$@" --out "$out/parts" --jobs --cells-per-job 1 >"$out/jobs.txt" || { echo "FAIL: --jobs"; exit 1; }
parallel --will-cite -j2 <"$out/jobs.txt" >"$out/parallel.log" 2>&1 || { tail -5 "$out/parallel.log"; echo "FAIL: a shard failed"; exit 1; }
t2=$(date +%s)
"$trimvr" bench merge --out "$out/merged" "$out"/parts/part-*.json || { echo "FAIL: merge"; exit 1; }
echo "serial $((t1 - t0)) s, $(wc -l <"$out/jobs.txt") shards under parallel -j2 $((t2 - t1)) s"
sh "$(dirname "$0")/csv_equal.sh" "$out/serial/bench.csv" "$out/merged/bench.csv" serial merged || exit 1

# refuse: expect exit 1 and one stderr line containing $1 and $2
refuse() {
    want1=$1 want2=$2
    shift 2
    "$trimvr" bench merge --out "$out/bad-out" "$@" 2>"$out/refuse.err" >/dev/null
    s=$?
    if [ $s -ne 1 ] || [ "$(wc -l <"$out/refuse.err")" -ne 1 ] || ! grep -q -- "$want1" "$out/refuse.err" ||
        ! grep -q -- "$want2" "$out/refuse.err"; then
        echo "FAIL: merge of $* exited $s, expected 1 and one line with '$want1' and '$want2':"
        cat "$out/refuse.err"
        exit 1
    fi
    echo "ok: refused: $(cat "$out/refuse.err")"
}
mkdir -p "$out/bad"
sed 's/"version": "/"version": "other-/' "$out/parts/part-1.json" >"$out/bad/part-1.json"
refuse "bad/part-1.json" "versions" "$out/parts/part-0.json" "$out/bad/part-1.json"
sed 's/;samples=/;samples=9/' "$out/parts/part-1.json" >"$out/bad/part-1.json"
refuse "bad/part-1.json" "settings" "$out/parts/part-0.json" "$out/bad/part-1.json"
refuse "part-0.json" "both are shard 0/" "$out/parts/part-0.json" "$out"/parts/part-*.json
refuse "shard 1/" "missing" "$out/parts/part-0.json"
echo '{"format": "trimvr-bench-part 1", "cells": [' >"$out/bad/cut.json"
refuse "bad/cut.json" "end of file" "$out/bad/cut.json"
