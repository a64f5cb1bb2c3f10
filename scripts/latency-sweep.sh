#!/bin/sh
# Latency sweep (docs/results.md, "Latency sweep"): `trimvr replay` of the city walk and of
# one recorded trace (HoloLens 1, placed in builtin:interior as docs/paths.md shows) at the
# fixed 50 ms latency model and at measured latency factors 0.1, 0.3 and 1, as short runs.
# Writes OUT/<path>-<latency>/ (summary.json, frames.csv), OUT/sweep.md (the table) and
# OUT/sweep.png (misses and whole-scene frames, PSNR mean and p5, PVS size, Δ and PVS FOV
# against the latency model).
#
#   scripts/latency-sweep.sh [OUT]        (default out/latency-sweep)
#
# FRAMES (300), EVERY (6), RES (320x180) and PVS_RES (256x256) override the run length,
# the compared frames, the eye and the PVS resolution; TRIMVR_BUILD_DIR the build folder;
# TRIMVR_SHARED the shared data (../shared).
set -eu
cd "$(dirname "$0")/.."
B=${TRIMVR_BUILD_DIR:-build}
S=${TRIMVR_SHARED:-../shared}
OUT=${1:-out/latency-sweep}
FRAMES=${FRAMES:-300}
EVERY=${EVERY:-6}
RES=${RES:-320x180}
PVS_RES=${PVS_RES:-256x256}
mkdir -p "$OUT"
trace=$S/traces/hololens_pred6dof/1.csv
paths=paths/city-walk.csv
if [ -f "$trace" ]; then
    "$B/trimvr" path import --in "$trace" --out "$OUT/hololens-1.csv" --scene builtin:interior \
        --anchor -6,0,6.5 --heading 0 --ref centroid --eye-height 1.7 >/dev/null
    paths="$paths $OUT/hololens-1.csv"
else
    echo "latency-sweep: $trace missing: the city walk only" >&2
fi

table=$OUT/sweep.md
data=$OUT/sweep.dat
printf '| path | latency | misses / frames checked | whole-scene frames | PSNR mean / p5 dB | FN px mean | PVS %% | Δ cm | PVS FOV ° | PVSs computed (all directions) | whole-scene PVSs | PVS ms mean |\n' >"$table"
printf '|---|---|---|---|---|---|---|---|---|---|---|---|\n' >>"$table"
: >"$data"
i=0
for p in $paths; do
    name=$(basename "$p" .csv)
    for lat in fixed50 f0.1 f0.3 f1; do
        case $lat in
        fixed50) opt="--latency-ms 50" ;;
        *) opt="--latency-factor ${lat#f}" ;;
        esac
        dir=$OUT/$name-$lat
        echo "latency-sweep: $name $lat" >&2
        # shellcheck disable=SC2086
        "$B/trimvr" replay --path "$p" $opt --frames "$FRAMES" --every "$EVERY" --res "$RES" --pvs-res "$PVS_RES" \
            --no-plots --no-progress --out "$dir" >"$dir.log" 2>&1 || echo "latency-sweep: $dir failed (see $dir.log)" >&2
        j=$dir/summary.json
        [ -f "$j" ] || continue
        # one table row and one gnuplot row (index, label, misses, whole-scene frames, PSNR
        # mean and p5 with 100 for identical, PVS %, Δ cm, FOV) from summary.json's lines
        awk -v n="$name" -v l="$lat" -v i="$i" -v table="$table" -v data="$data" '
            /^ *"[a-z_0-9]+": / { k = $0; sub(/^ *"/, "", k); sub(/".*/, "", k)
                                  v = $0; sub(/^[^:]*: */, "", v); sub(/,$/, "", v); s[k] = v }
            END {
                ps = s["psnr_mean_db"]; p5 = s["psnr_p5_db"]
                ps = (ps ~ /inf/ ? "inf" : ps); p5 = (p5 ~ /inf/ ? "inf" : p5)
                d = s["delta_mean_m"]; fv = s["fov_pvs_mean_deg"]
                printf "| %s | %s | %s / %s | %s | %s / %s | %.1f | %.2f | %s | %s | %s (%s) | %s | %s |\n",
                    n, l, s["viewcell_miss_frames"], s["coverage_frames"], s["whole_scene_frames"],
                    (ps == "inf" ? "inf" : sprintf("%.1f", ps)), (p5 == "inf" ? "inf" : sprintf("%.1f", p5)),
                    s["fn_pixels_mean"], 100 * s["pvs_fraction_mean"],
                    (d == "null" ? "-" : sprintf("%.1f", 100 * d)), (fv == "null" ? "-" : sprintf("%.1f", fv)),
                    s["pvs_count"], s["omni_pvs_count"], s["whole_scene_pvs_count"],
                    (s["pvs_ms_mean"] == "null" ? "-" : sprintf("%.0f", s["pvs_ms_mean"])) >>table
                printf "%d \"%s %s\" %s %s %s %s %.3f %s %s\n", i, n, l, s["viewcell_miss_frames"], s["whole_scene_frames"],
                    (ps == "inf" ? 100 : ps), (p5 == "inf" ? 100 : p5), 100 * s["pvs_fraction_mean"],
                    (d == "null" ? "NaN" : 100 * d), (fv == "null" ? "NaN" : fv) >>data
            }' "$j"
        i=$((i + 1))
    done
done
cat "$table"
if command -v gnuplot >/dev/null 2>&1; then
    gnuplot <<GP || echo "latency-sweep: gnuplot failed: no sweep.png" >&2
set terminal pngcairo size 1200,760 font ',9'
set output '$OUT/sweep.png'
set multiplot layout 2,2
set style data histograms
set style fill solid 0.7
set xtics rotate by -30
set key top left
set title 'frames (of those checked)'
plot '$data' using 3:xtic(2) title 'viewcell misses', '' using 4 title 'whole-scene frames'
set title 'PSNR, PVS render vs full (dB; 100 = identical)'
set yrange [0:105]
plot '$data' using 5:xtic(2) title 'mean', '' using 6 title 'p5'
set yrange [*:*]
set title 'PVS size (% of the scene, 100 = whole scene)'
plot '$data' using 7:xtic(2) title 'PVS %'
set title 'viewcell of computed PVSs (log scale)'
set logscale y
set style data linespoints
plot '$data' using 0:8:xtic(2) pt 7 title 'Δ cm', '' using 0:9 pt 5 title 'PVS FOV °'
unset multiplot
GP
fi
