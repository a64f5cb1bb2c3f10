#!/bin/sh
# README command 1: installs what is missing, builds, and runs the main job,
# `trimvr replay` of builtin:city along paths/city-walk.csv, into out/replay
# (override with TRIMVR_OUT). Extra arguments go to `trimvr replay` and
# override the defaults below: the first 20 s of the walk, every third frame
# compared, which takes minutes rather than an hour on a CPU-only lavapipe.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
out=${TRIMVR_OUT:-$root/out/replay}
cd "$root"
# llvmpipe allocates and frees large vertex buffers per draw; keeping freed
# memory mapped makes draws 1.4-2.7x faster on lavapipe (docs/rendering.md)
GLIBC_TUNABLES=${GLIBC_TUNABLES:-glibc.malloc.mmap_max=0:glibc.malloc.trim_threshold=4294967295:glibc.malloc.top_pad=268435456}
export GLIBC_TUNABLES
exec "$root/build/trimvr" replay --scene builtin:city --path paths/city-walk.csv --out "$out" --frames 1800 --every 3 "$@"
