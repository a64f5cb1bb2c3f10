#!/bin/sh
# check_pvs_no_int64.sh TRIMVR OUT_PREFIX - the PVS on a device without 64-bit atomics
# (TRIMVR_NO_INT64=1 leaves shaderInt64 and shaderBufferInt64Atomics off, render/device.c):
# it runs P2's variant built without them (no validation message, under TRIMVR_VALIDATION=1
# as every test), says so once, and its ids hold every id of the default PVS (the front-patch
# rule it turns off only removes triangles on this cell), more of them here.
set -u
trimvr=$1 out=$2
cell="--scene builtin:city --pos 0,1.7,30 --dir 0,0,-1 --res 128x128"
$trimvr pvs $cell --ids "$out-default.ids" > "$out-default.log" 2>&1 || { cat "$out-default.log"; echo "FAIL: default run"; exit 1; }
TRIMVR_NO_INT64=1 $trimvr pvs $cell --ids "$out-noi64.ids" > "$out-noi64.log" 2>&1
rc=$?
cat "$out-noi64.log"
[ $rc = 0 ] || { echo "FAIL: the run without 64-bit atomics exited $rc"; exit 1; }
! grep -qE "vulkan validation:|validation layer reported" "$out-noi64.log" || { echo "FAIL: validation messages without 64-bit atomics"; exit 1; }
[ "$(grep -c 'P2 without 64-bit atomics (front-patch rule off)' "$out-noi64.log")" = 1 ] ||
    { echo "FAIL: the fallback variant is not logged once"; exit 1; }
grep -q 'P2 with 64-bit atomics (front-patch rule on)' "$out-default.log" || { echo "FAIL: default variant not logged"; exit 1; }
missing=$(sort "$out-default.ids" | comm -23 - "$(sort "$out-noi64.ids" > "$out-noi64.sorted"; echo "$out-noi64.sorted")" | wc -l)
d=$(wc -l < "$out-default.ids") n=$(wc -l < "$out-noi64.ids")
echo "default $d ids, without 64-bit atomics $n ids, $missing default ids missing from it"
[ "$missing" = 0 ] && [ "$n" -gt "$d" ] || { echo "FAIL: not a strict superset of the default PVS"; exit 1; }
echo ok
