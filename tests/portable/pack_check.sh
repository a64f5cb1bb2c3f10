#!/bin/sh
# The portable archive (scripts/pack-portable.sh, docs/portable.md): built in its
# own folder, at most 40 MB, unpacked and moved elsewhere, resolves every library
# but glibc's inside itself, runs a quick trimvr bench and its image I/O test, and
# its demo command says it is not built in.
# usage: pack_check.sh SOURCE_DIR WORK_DIR [extra cmake arguments]
set -eu
src=$1
work=$2
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work"
mkdir -p "$work/unpacked"
t0=$(date +%s)
TRIMVR_PORTABLE_BUILD="$work/build" TRIMVR_PORTABLE_CMAKE="${3:-}" sh "$src/scripts/pack-portable.sh" \
    "$work/trimvr-portable.tar.gz"
echo "pack: $(($(date +%s) - t0)) s"
size=$(wc -c <"$work/trimvr-portable.tar.gz")
[ "$size" -le 40000000 ] || fail "archive is $size bytes, over 40 MB"

tar -C "$work/unpacked" -xzf "$work/trimvr-portable.tar.gz"
app=$work/moved/trimvr-portable # relocated after unpacking: nothing may point back
mkdir -p "$work/moved"
mv "$work/unpacked/trimvr-portable" "$app"

# through the launcher's LD_LIBRARY_PATH, only glibc may come from the system
LD_LIBRARY_PATH="$app/lib" ldd "$app/bin/trimvr" >"$work/ldd.txt"
cat "$work/ldd.txt"
grep -q "not found" "$work/ldd.txt" && fail "unresolved library"
outside=$(awk '$2 == "=>" { print $1, $3 }' "$work/ldd.txt" | grep -v " $app/lib/" |
    grep -Ev '^(libc|libm|libpthread|libdl|librt)\.so' || true)
[ -z "$outside" ] || fail "resolved outside the archive: $outside"
grep -q "libvulkan.so.1 => $app/lib/" "$work/ldd.txt" || fail "the Vulkan loader is not the archive's"

cd "$work"
"$app/trimvr" bench --scenes builtin:unit --methods tr,gt --deltas 0.05 --max-cells 1 --samples 6 --res 96x54 \
    --pvs-res 64x64 --out "$work/bench"
awk -F, 'NR > 1 { rows++ } NR > 1 && $2 == "gt" && ($11 != 0 || $12 != 0) { print "FAIL: gt row " $0; exit 1 }
    END { if (rows != 2) { print "FAIL: " rows " bench rows, expected 2"; exit 1 } }' "$work/bench/bench.csv"
"$app/trimvr" path info "$app/paths/city-walk.csv" | grep -q "scene  *builtin:city" || fail "bundled paths"
if "$app/trimvr" demo 2>"$work/demo.err"; then fail "demo ran"; fi
[ "$(wc -l <"$work/demo.err")" -eq 1 ] && grep -q "not built in this build" "$work/demo.err" || fail "demo message"

cmake --build "$work/build" --target scene_image_io_png >/dev/null
"$work/build/tests/scene/scene_image_io_png"
echo "ok: $size bytes, $(ls "$app/lib" | wc -l) libraries, bench and image I/O pass, $(($(date +%s) - t0)) s in all"
