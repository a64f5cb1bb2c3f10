#!/bin/sh
# The ground-truth cache of trimvr bench (docs/bench.md), as
# cli_bench_gt_cache runs it:
#   bench_gt_cache.sh TRIMVR OUT OPTIONS...
# runs the sweep OPTIONS (methods whose PVS is repeatable, at least one with
# false-negative pixels) without a cache, then with an empty one (every
# viewcell's GT computed and written once, then read by the next method),
# then again (every GT read), then with one file damaged and another
# holding a different viewcell's GT (both rejected with a warning and
# recomputed). bench.csv must equal the uncached run's in every non-timing
# column each time.
set -u
trimvr=$1 out=$2
shift 2
here=$(dirname "$0")
rm -rf "$out" && mkdir -p "$out" || exit 1
run() { # run NAME [cache options]: bench into $out/NAME, stderr in $out/NAME.err
    name=$1
    shift
    "$trimvr" bench "$@" --out "$out/$name" 2>"$out/$name.err" >/dev/null ||
        { tail -5 "$out/$name.err"; echo "FAIL: run $name"; exit 1; }
    sh "$here/csv_equal.sh" "$out/plain/bench.csv" "$out/$name/bench.csv" uncached "$name" || exit 1
}
count() { grep -c "$1" "$out/$2.err"; }
expect() { # expect WHAT GOT WANT
    [ "$2" -eq "$3" ] || { echo "FAIL: $1: $2, expected $3"; exit 1; }
    echo "ok: $1: $2"
}

"$trimvr" bench "$@" --out "$out/plain" 2>"$out/plain.err" >/dev/null || { tail -5 "$out/plain.err"; echo "FAIL: plain run"; exit 1; }
awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) { if ($i == "fng_pixels_mean") f = i; if ($i == "psnr_mean_db") p = i } next }
         $f > 0 && $p != "inf" { found = 1 }
         END { if (!found) { print "FAIL: no row with FN pixels: the cached path would not redraw a view"; exit 1 } }' \
    "$out/plain/bench.csv" || exit 1
rows=$(($(wc -l <"$out/plain/bench.csv") - 1))

run first "$@" --gt-cache "$out/cache"
files=$(ls "$out/cache" | wc -l)
[ "$files" -ge 2 ] || { echo "FAIL: $files cache files"; exit 1; }
expect "first run, GTs written" "$(count 'gt cache: wrote' first)" "$files"
expect "first run, GTs read" "$(count 'gt cache: read' first)" $((rows * 2 - files))

run second "$@" --gt-cache "$out/cache"
expect "second run, GTs read" "$(count 'gt cache: read' second)" $((rows * 2))
expect "second run, GTs written" "$(count 'gt cache: wrote' second)" 0

set -- "$@" --gt-cache "$out/cache"
a=$(ls "$out/cache"/*.bin | sed -n 1p) b=$(ls "$out/cache"/*.bin | sed -n 2p)
cp "$a" "$out/a.bin"
printf 'X' | dd of="$a" bs=1 seek=200 conv=notrunc 2>/dev/null
cp "$out/a.bin" "$b"
run third "$@"
expect "damaged file rejected" "$(count "gt cache: .*$(basename "$a") rejected (checksum" third)" 1
expect "other viewcell's file rejected" "$(count "gt cache: .*$(basename "$b") rejected (.*key differs" third)" 1
expect "third run, GTs written" "$(count 'gt cache: wrote' third)" 2
expect "third run, warnings" "$(grep -c 'rejected' "$out/third.err")" 2
