#!/bin/sh
# The quality bar for trim regions on real scenes, where it is met
# (docs/results.md, "Where trim regions stand"): at delta = 10 cm, FN pixels
# at most 0.005 % of each 320x180 sample view on average and PSNR >= 50 dB in
# every sample view of every viewcell (the two largest open-floor points of
# each level, 50 views each, as `trimvr bench`).
#
#   shared_quality.sh TRIMVR OUT_DIR SCENE,SCENE..
# Skipped (77) without ../shared ($TRIMVR_SHARED).
set -u
trimvr=$1
out=$2
scenes=$3
shared=${TRIMVR_SHARED:-../shared}
if [ ! -d "$shared/scenes/openarena" ]; then
    echo "skip: $shared/scenes/openarena absent (../shared not available)"
    exit 77
fi
rm -rf "$out"
if ! "$trimvr" bench --scenes "$scenes" --deltas 0.1 --methods tr --max-cells 2 --out "$out" >"$out.log" 2>&1; then
    echo "FAIL: trimvr bench --scenes $scenes exited non-zero"
    tail -n 5 "$out.log"
    exit 1
fi
awk -F, '
NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
{
    fng = 100 * $col["fng_fraction"]; psnr = $col["psnr_min_db"]
    ok = fng <= 0.005 && (psnr == "inf" || psnr + 0 >= 50)
    printf "%-14s FNG %.4f %% (<= 0.005)  PSNR min %s dB (>= 50)  %s\n", $col["scene"], fng, psnr, ok ? "ok" : "FAIL"
    bad += !ok; rows++
}
END { exit (bad > 0 || rows == 0) }' "$out/bench.csv"
