#!/bin/sh
# Viewcell coverage on every display frame (docs/results.md, "Coverage matrix"): `trimvr replay`
# of every bundled path and of every trace of ../shared/traces (placed in builtin:interior as
# docs/results.md, "Recorded human motion", places them) with each predictor, at the fixed 50 ms
# latency model. Coverage is geometry: the sizing, the latency model and the test do not depend
# on the PVS (docs/replay.md), so the runs use `--coverage-only` (no PVS computed, nothing
# rendered; the default 640x360 aspect sets the eye's vertical FOV). Writes
# OUT/<path>-<predictor>/summary.json and OUT/coverage.md.
#
#   scripts/coverage-matrix.sh [OUT]        (default out/coverage-matrix)
#
# PREDICTORS (cv ca kalman), FRAMES (0: whole path), PATHS (paths/*.csv) override;
# TRIMVR_BUILD_DIR the build folder; TRIMVR_SHARED the shared data (../shared).
set -eu
cd "$(dirname "$0")/.."
B=${TRIMVR_BUILD_DIR:-build}
S=${TRIMVR_SHARED:-../shared}
OUT=${1:-out/coverage-matrix}
PREDICTORS=${PREDICTORS:-cv ca kalman}
FRAMES=${FRAMES:-0}
PATHS=${PATHS:-$(ls paths/*.csv)}
mkdir -p "$OUT/traces"
for f in "$S"/traces/hololens_pred6dof/[0-9].csv "$S"/traces/optitrack_spacepirate/*.csv \
    "$S"/traces/questset_quest2/*.csv; do
    [ -f "$f" ] || continue
    case $f in
    */hololens_pred6dof/*) name=hl$(basename "$f" .csv) ;;
    */optitrack_spacepirate/*) name=optitrack ;;
    *) name=quest ;;
    esac
    "$B/trimvr" path import --in "$f" --out "$OUT/traces/$name-interior.csv" --scene builtin:interior \
        --ref centroid --anchor -18,0,6 --heading 90 --eye-height 1.6 >/dev/null
    PATHS="$PATHS $OUT/traces/$name-interior.csv"
done
table=$OUT/coverage.md
printf '| path | predictor | misses / display frames | Δ mean cm | PVS FOV mean ° | PVSs (all directions) | whole-scene frames |\n' >"$table"
printf '|---|---|---|---|---|---|---|\n' >>"$table"
for p in $PATHS; do
    name=$(basename "$p" .csv)
    for pr in $PREDICTORS; do
        dir=$OUT/$name-$pr
        echo "coverage-matrix: $name $pr" >&2
        "$B/trimvr" replay --path "$p" --predictor "$pr" --coverage-only \
            --frames "$FRAMES" --no-plots --no-progress --out "$dir" >"$dir.log" 2>&1 ||
            echo "coverage-matrix: $dir failed (see $dir.log)" >&2
        j=$dir/summary.json
        [ -f "$j" ] || continue
        awk -v n="$name" -v pr="$pr" '
            /^ *"[a-z_0-9]+": / { k = $0; sub(/^ *"/, "", k); sub(/".*/, "", k)
                                  v = $0; sub(/^[^:]*: */, "", v); sub(/,$/, "", v); s[k] = v }
            END { printf "| %s | %s | %s / %s | %.1f | %.1f | %s (%s) | %s |\n", n, pr, s["viewcell_miss_frames"],
                      s["coverage_frames"], 100 * s["delta_mean_m"], s["fov_pvs_mean_deg"], s["pvs_count"],
                      s["omni_pvs_count"], s["whole_scene_frames"] }' "$j" >>"$table"
    done
done
cat "$table"
