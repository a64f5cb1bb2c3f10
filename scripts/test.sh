#!/bin/sh
# README command 2: installs what is missing, builds, and runs the whole test
# suite through ctest: the full build (Vulkan on lavapipe, validation layer on)
# an AddressSanitizer + UndefinedBehaviorSanitizer build of the headless unit
# tests and of the trimvr CLI for the bad-input tests, a ThreadSanitizer build
# of the asynchronous-PVS tests, and the libFuzzer targets (clang, ASan+UBSan)
# for 30 s each. Exits non-zero if any of them fails.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=$(nproc)

# clang and its libFuzzer runtime only for the fuzz targets below
TRIMVR_EXTRA_PACKAGES="clang libclang-rt-14-dev" "$root/scripts/setup.sh"

status=0
# label slow = benchmarks and timing programs: run them with `ctest -L slow`
(cd "$root/build" && ctest --output-on-failure -j"$jobs" -LE slow) || status=1

asan="$root/build-asan"
cmake -S "$root" -B "$asan" -DCMAKE_BUILD_TYPE=Debug -DTRIMVR_SANITIZE=ON -DTRIMVR_HEADLESS_ONLY=ON >/dev/null
cmake --build "$asan" -j"$jobs"
(cd "$asan" && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --output-on-failure -j"$jobs" -L unit) || status=1

# the bad-input CLI tests (one-line error, non-zero exit) under ASan+UBSan:
# a malformed file must not read memory it does not own even when it fails
asan_cli="$root/build-asan-cli"
cmake -S "$root" -B "$asan_cli" -DCMAKE_BUILD_TYPE=Debug -DTRIMVR_SANITIZE=ON >/dev/null
cmake --build "$asan_cli" -j"$jobs" --target trimvr
(cd "$asan_cli" && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --output-on-failure -j"$jobs" -L bad-input) || status=1

# libFuzzer: each parser of outside input for TV_FUZZ_SECONDS (30 s); a
# finding fails the run and leaves its reproducer in build-fuzz/fuzz-out/
fuzz="$root/build-fuzz"
CC=clang CXX=clang++ cmake -S "$root" -B "$fuzz" -DCMAKE_BUILD_TYPE=Debug -DTRIMVR_SANITIZE=ON \
    -DTRIMVR_HEADLESS_ONLY=ON -DTRIMVR_FUZZ=ON >/dev/null
cmake --build "$fuzz" -j"$jobs" --target fuzz_gltf fuzz_path fuzz_trace fuzz_q3vis
(cd "$fuzz" && ctest --output-on-failure -j"$jobs" -L fuzz) || status=1

tsan="$root/build-tsan"
cmake -S "$root" -B "$tsan" -DCMAKE_BUILD_TYPE=Debug -DTRIMVR_TSAN=ON -DTRIMVR_HEADLESS_ONLY=ON >/dev/null
cmake --build "$tsan" -j"$jobs" --target test_pvs_worker
(cd "$tsan" && TSAN_OPTIONS=halt_on_error=1 ctest --output-on-failure -L async) || status=1

exit $status
