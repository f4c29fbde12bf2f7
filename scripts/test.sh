#!/usr/bin/env bash
# The test command: installs what is missing, checks the walls between layers, builds, runs
# the scene-parser and BSDF tests under AddressSanitizer + UndefinedBehaviorSanitizer, then
# every test with ctest.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
# The walls between layers (docs/architecture.md), from the include lines: seconds.
python3 "$root/scripts/check_walls.py"

# Sanitizer build: only what the bad-input tests need.
asan="$root/build-asan"
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$root" -B "$asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPHOTON_SANITIZE=ON "${launcher[@]}" > /dev/null
cmake --build "$asan" -j2 --target test_scene_loader test_scene_loader_errors test_bsdf
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 "$asan/tests/test_scene_loader"
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 "$asan/tests/test_scene_loader_errors"
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 "$asan/tests/test_bsdf"

bash "$root/scripts/build.sh"
# playwright-core for the browser test (no browser download: it drives Debian's Chromium).
npm ci --prefix "$root/tests/web" --no-audit --no-fund
cd "$root/build" && ctest --output-on-failure -j2 --timeout 900
