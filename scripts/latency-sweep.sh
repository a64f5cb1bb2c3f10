#!/bin/sh
# Latency sweep (docs/results.md, "Latency sweep"): `trimvr replay` of the city walk and of
# one recorded trace (HoloLens 1, placed in builtin:interior as docs/paths.md shows) at the
# fixed 50 ms latency model and at measured latency factors 0.1, 0.3 and 1, as short runs.
# Writes OUT/<path>-<latency>/ (summary.json, frames.csv), OUT/sweep.md (the table) and
# OUT/sweep.png (misses, PSNR, PVS size against the latency model).
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

# one summary.json value (a number or null)
value() {
    sed -n "s/^ *\"$2\": *\([^,]*\),*$/\1/p" "$1" | head -n 1
}

table=$OUT/sweep.md
data=$OUT/sweep.dat
printf '| path | latency | misses / frames checked | PSNR mean / p5 dB | FN px mean | PVS %% | Δ cm | PVS FOV ° | PVSs (all directions, clamped) | PVS ms |\n' >"$table"
printf '|---|---|---|---|---|---|---|---|---|---|\n' >>"$table"
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
        misses=$(value "$j" viewcell_miss_frames)
        checked=$(value "$j" coverage_frames)
        psnr=$(value "$j" psnr_mean_db)
        p5=$(value "$j" psnr_p5_db)
        fn=$(value "$j" fn_pixels_mean)
        frac=$(value "$j" pvs_fraction_mean)
        delta=$(value "$j" delta_mean_m)
        fov=$(value "$j" fov_pvs_mean_deg)
        count=$(value "$j" pvs_count)
        omni=$(value "$j" omni_pvs_count)
        clamped=$(value "$j" clamped_pvs_count)
        ms=$(value "$j" pvs_ms_mean)
        awk -v n="$name" -v l="$lat" -v m="$misses" -v c="$checked" -v ps="$psnr" -v p5="$p5" -v fn="$fn" -v fr="$frac" \
            -v d="$delta" -v fo="$fov" -v k="$count" -v o="$omni" -v cl="$clamped" -v ms="$ms" 'BEGIN {
            printf "| %s | %s | %s / %s | %s / %s | %.1f | %.2f | %.1f | %.1f | %s (%s, %s) | %.0f |\n",
                n, l, m, c, (ps == "null" ? "inf" : sprintf("%.1f", ps)), (p5 == "null" ? "inf" : sprintf("%.1f", p5)),
                fn, 100 * fr, 100 * d, fo, k, o, cl, ms }' >>"$table"
        # gnuplot rows: index, label, misses, PSNR mean (100 when identical), PVS %
        awk -v i="$i" -v n="$name" -v l="$lat" -v m="$misses" -v ps="$psnr" -v fr="$frac" 'BEGIN {
            printf "%d \"%s %s\" %s %s %.3f\n", i, n, l, m, (ps == "null" ? 100 : ps), 100 * fr }' >>"$data"
        i=$((i + 1))
    done
done
cat "$table"
if command -v gnuplot >/dev/null 2>&1; then
    gnuplot <<GP || echo "latency-sweep: gnuplot failed: no sweep.png" >&2
set terminal pngcairo size 1100,420 font ',9'
set output '$OUT/sweep.png'
set style data histograms
set style fill solid 0.7
set xtics rotate by -30
set ylabel 'viewcell-miss frames, PVS % of the scene'
set y2label 'PSNR mean (dB; 100 = identical)'
set y2tics
set key top left
plot '$data' using 3:xtic(2) title 'misses', '' using 5 title 'PVS %', '' using 0:4 axes x1y2 with linespoints pt 7 title 'PSNR mean'
GP
fi
