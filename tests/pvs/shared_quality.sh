#!/bin/sh
# The quality bar for trim regions on real scenes (Sponza and the OpenArena levels)
# (docs/results.md, "Trim-region PVS"): at delta = 10 cm (or the
# given delta), in every
# sampled viewcell (the two largest open-floor points of each level, 50
# sample views of 320x180 each, as `trimvr bench`) FN pixels at most 0.005 %
# of a view on average and PSNR >= 50 dB (of the viewcell's mean squared
# error over its views). The lowest PSNR of a single view is printed too.
#
#   shared_quality.sh TRIMVR OUT_DIR SCENE,SCENE.. [DELTA_M]
# Skipped (77) without ../shared ($TRIMVR_SHARED).
set -u
trimvr=$1
out=$2
scenes=$3
delta=${4:-0.1}
shared=${TRIMVR_SHARED:-../shared}
if [ ! -d "$shared/scenes/openarena" ] || [ ! -d "$shared/scenes/sponza_lod4" ]; then
    echo "skip: $shared/scenes/openarena or sponza_lod4 absent (../shared not available)"
    exit 77
fi
rm -rf "$out"
if ! "$trimvr" bench --scenes "$scenes" --deltas "$delta" --methods tr --max-cells 2 --out "$out" >"$out.log" 2>&1; then
    echo "FAIL: trimvr bench --scenes $scenes exited non-zero"
    tail -n 5 "$out.log"
    exit 1
fi
awk -F, -v scenes="$scenes" '
function number(s) { return s ~ /^-?[0-9.]+([eE][-+]?[0-9]+)?$/ }
NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
{
    # "inf": every view identical to the full render; an empty cell is not a
    # number (a broken metric) and fails
    fng_cell = $col["fng_fraction_worst_cell"]; psnr = $col["psnr_worst_cell_db"]; view = $col["psnr_min_db"]
    fng = 100 * fng_cell
    ok = number(fng_cell) && fng <= 0.005 && (psnr == "inf" || (number(psnr) && psnr + 0 >= 50))
    printf "%-14s worst viewcell: FNG %s %% (<= 0.005), PSNR %s dB (>= 50); worst view %s dB  %s\n",
           $col["scene"], number(fng_cell) ? sprintf("%.4f", fng) : "\"" fng_cell "\"", psnr, view, ok ? "ok" : "FAIL"
    bad += !ok; rows++; seen[$col["scene"]]++
}
END {
    # one row per requested scene, each scene once
    n = split(scenes, want, ",")
    for (i = 1; i <= n; i++) {
        s = want[i]; sub(/^oa:/, "", s)
        got = seen[s] + (s != want[i] ? seen[want[i]] : 0)
        if (got != 1) { printf "FAIL: %d rows for scene %s, expected 1\n", got, want[i]; bad++ }
    }
    if (rows != n) { printf "FAIL: %d rows for %d scenes\n", rows, n; bad++ }
    exit bad > 0
}' "$out/bench.csv"
