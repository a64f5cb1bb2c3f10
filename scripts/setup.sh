#!/bin/sh
# Installs the Debian 12 packages trimvr needs (only the missing ones), then
# configures and builds build/ (or $TRIMVR_BUILD_DIR). Called by both README
# commands; safe to run again.
set -eu

PACKAGES="cmake make gcc g++ pkg-config glslang-tools libvulkan-dev mesa-vulkan-drivers
vulkan-validationlayers libglfw3-dev libcglm-dev libtinygltf-dev nlohmann-json3-dev
libopenimageio-dev openimageio-tools gnuplot-nox xvfb xauth parallel libpng-dev libjpeg-dev ${TRIMVR_EXTRA_PACKAGES:-}"

missing=""
for p in $PACKAGES; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing="$missing $p"
    fi
done

if [ -n "$missing" ]; then
    if [ "$(id -u)" -ne 0 ]; then
        echo "trimvr setup: missing Debian packages:$missing" >&2
        echo "trimvr setup: run as root:  apt-get update && apt-get install -y --no-install-recommends$missing" >&2
        exit 1
    fi
    echo "trimvr setup: installing$missing"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    # shellcheck disable=SC2086
    apt-get install -y -qq --no-install-recommends $missing
fi

root=$(cd "$(dirname "$0")/.." && pwd)
build=${TRIMVR_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@" >/dev/null
cmake --build "$build" -j"$(nproc)"
