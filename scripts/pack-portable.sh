#!/bin/sh
# Builds the portable configuration (-DTRIMVR_PORTABLE=ON: no window, images
# through libpng/libjpeg instead of OpenImageIO) and packs it into one
# relocatable archive for machines without trimvr's packages (docs/portable.md):
#
#   trimvr-portable/trimvr        launcher: LD_LIBRARY_PATH=<its folder>/lib, then bin/trimvr
#   trimvr-portable/bin/trimvr    the stripped binary
#   trimvr-portable/lib/          every shared library it needs except glibc's
#                                 (libc, libm, libpthread, libdl, librt, ld-linux);
#                                 the Vulkan loader libvulkan.so.1 is included, the
#                                 Vulkan driver (ICD) is not: it comes from the node
#   trimvr-portable/paths/        the bundled head-motion paths
#
# usage: scripts/pack-portable.sh [ARCHIVE]   (default out/trimvr-portable.tar.gz)
# env:   TRIMVR_PORTABLE_BUILD  build folder (default build-portable)
#        TRIMVR_PORTABLE_CMAKE  extra cmake arguments (e.g. a compiler launcher)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${TRIMVR_PORTABLE_BUILD:-$root/build-portable}
archive=${1:-$root/out/trimvr-portable.tar.gz}
case $archive in /*) ;; *) archive=$(pwd)/$archive ;; esac

# shellcheck disable=SC2086
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DTRIMVR_PORTABLE=ON ${TRIMVR_PORTABLE_CMAKE:-} >/dev/null
cmake --build "$build" -j"$(nproc)" --target trimvr

stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
pkg=$stage/trimvr-portable
mkdir -p "$pkg/bin" "$pkg/lib"
cp "$build/trimvr" "$pkg/bin/trimvr"
strip "$pkg/bin/trimvr"
cp -r "$root/paths" "$pkg/paths"

# ldd lists the whole closure; glibc stays the node's (its loader must match its libc)
ldd "$pkg/bin/trimvr" | awk '$2 == "=>" && $3 ~ /^\// { print $1, $3 }' | while read -r soname path; do
    case $soname in
    libc.so.* | libm.so.* | libpthread.so.* | libdl.so.* | librt.so.* | ld-linux*) ;;
    *) cp -L "$path" "$pkg/lib/$soname" && strip --strip-unneeded "$pkg/lib/$soname" ;;
    esac
done

cat >"$pkg/trimvr" <<'EOF'
#!/bin/sh
# trimvr from this folder: its own libraries first, then the system's (glibc, the Vulkan driver).
here=$(cd "$(dirname "$0")" && pwd)
LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" exec "$here/bin/trimvr" "$@"
EOF
chmod +x "$pkg/trimvr"

cat >"$pkg/README.txt" <<EOF
trimvr portable build ($(cd "$root" && git describe --always --dirty 2>/dev/null || echo unknown), $(date -u +%Y-%m-%d))
Run ./trimvr (the launcher), e.g. ./trimvr bench --help. Needs from the system: glibc and a
Vulkan 1.3 driver (ICD; select one with VK_DRIVER_FILES=/path/icd.json). No window (no demo),
no OpenEXR; plots need gnuplot on the PATH (else only the .gp scripts are written).
Third-party scenes: set TRIMVR_SHARED to the folder holding scenes/. See docs/portable.md.
EOF

mkdir -p "$(dirname "$archive")"
tar -C "$stage" -czf "$archive" trimvr-portable
echo "pack-portable: $archive ($(du -k "$archive" | cut -f1) KiB, $(ls "$pkg/lib" | wc -l) libraries)"
