#!/bin/sh
# demo_checks.sh TRIMVR CHECKER SOURCE_DIR OUT: `trimvr demo` under Xvfb for
# a fixed number of frames on the fixed-step clock; its screenshot (read back
# from the swapchain) is compared with `trimvr render --stereo` at the same
# path time. Skips (77) without xvfb-run.
set -eu
TRIMVR=$1 CHECK=$2 SRC=$3 OUT=$4
if ! command -v xvfb-run >/dev/null 2>&1; then
    echo "xvfb-run is not installed (Debian package xvfb): skipping"
    exit 77
fi
N=12 # the screenshot is frame N-1 at t = (N-1)/90 s along the path
rm -rf "$OUT"
mkdir -p "$OUT"
xvfb-run -a "$TRIMVR" demo --path "$SRC/paths/interior-walk.csv" --res 320x180 --frames $N --view full --no-hud \
    --screenshot "$OUT/demo.png" >"$OUT/demo.log" # no pipe: set -e must see the demo's exit status
cat "$OUT/demo.log"
fov_v=$(sed -n 's/.*eye FOV [0-9.]* x \([0-9.]*\) deg.*/\1/p' "$OUT/demo.log")
test -n "$fov_v"
"$TRIMVR" render --path "$SRC/paths/interior-walk.csv" --out "$OUT/ref" --res 320x180 --fov "$fov_v" --stereo \
    --every $((N - 1)) --frames 2 >/dev/null
last=$(printf '%05d' $((N - 1)))
"$CHECK" "$OUT/demo.png" "$OUT/ref/frame_${last}_left.png" "$OUT/ref/frame_${last}_right.png" \
    "$OUT/ref/frame_00000_left.png"
# the Figure 1 overview replaces the right eye; the left one stays the eye
xvfb-run -a "$TRIMVR" demo --path "$SRC/paths/interior-walk.csv" --res 320x180 --frames $N --view full --no-hud \
    --overview --screenshot "$OUT/overview.png" >/dev/null
"$CHECK" --overview "$OUT/overview.png" "$OUT/ref/frame_${last}_left.png"
# the default view (PVS, HUD on) must also run and exit 0
xvfb-run -a "$TRIMVR" demo --path "$SRC/paths/interior-walk.csv" --res 320x180 --frames 6 --every 2 \
    --screenshot "$OUT/demo-pvs.png" >"$OUT/demo-pvs.log"
grep -q "viewcell misses" "$OUT/demo-pvs.log"
