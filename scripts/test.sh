#!/usr/bin/env bash
# The test command: installs what is missing, builds, runs every test with ctest, then
# the scene-parser tests again under AddressSanitizer and UndefinedBehaviorSanitizer.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh"
(cd "$root/build" && ctest --output-on-failure -j2 --timeout 900)

# Sanitizer build: only what the bad-input tests need.
asan="$root/build-asan"
cmake -S "$root" -B "$asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPHOTON_SANITIZE=ON > /dev/null
cmake --build "$asan" -j2 --target test_scene_loader test_bsdf
export ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
"$asan/tests/test_scene_loader"
"$asan/tests/test_bsdf"
