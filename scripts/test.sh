#!/bin/sh
# README command 2: installs what is missing, builds, and runs the whole test
# suite through ctest: the full build (Vulkan on lavapipe, validation layer on)
# an AddressSanitizer + UndefinedBehaviorSanitizer build of the headless unit
# tests, and a ThreadSanitizer build of the asynchronous-PVS tests. Exits
# non-zero if any of them fails.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=$(nproc)

"$root/scripts/setup.sh"

status=0
# label slow = benchmarks and timing programs: run them with `ctest -L slow`
(cd "$root/build" && ctest --output-on-failure -j"$jobs" -LE slow) || status=1

asan="$root/build-asan"
cmake -S "$root" -B "$asan" -DCMAKE_BUILD_TYPE=Debug -DTRIMVR_SANITIZE=ON -DTRIMVR_HEADLESS_ONLY=ON >/dev/null
cmake --build "$asan" -j"$jobs"
(cd "$asan" && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --output-on-failure -j"$jobs" -L unit) || status=1

tsan="$root/build-tsan"
cmake -S "$root" -B "$tsan" -DCMAKE_BUILD_TYPE=Debug -DTRIMVR_TSAN=ON -DTRIMVR_HEADLESS_ONLY=ON >/dev/null
cmake --build "$tsan" -j"$jobs" --target test_pvs_worker
(cd "$tsan" && TSAN_OPTIONS=halt_on_error=1 ctest --output-on-failure -L async) || status=1

exit $status
