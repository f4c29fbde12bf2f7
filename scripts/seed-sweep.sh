#!/usr/bin/env bash
# Runs the engine's tests (the test command's, not the long comparisons) again under other
# seeds: PHOTON_TEST_SEED_SHIFT=K adds K to the seed of every scene the tests render through
# test::renderImage or test::resumedAfter (tests that build a Renderer themselves keep
# theirs, so one comparing such a render with renderImage's may fail for that alone). A
# test that passes at its own seed and fails at another holds a tolerance that one seed's
# noise alone can cross: its figure should be measured over seeds and the tolerance set
# from their spread (or the render given the samples it needs).
# Usage: scripts/seed-sweep.sh [SHIFT...]   (default: 1 2; BUILD_DIR as scripts/build.sh)
# Prints the failed cases of each shift; exits 1 if any failed.
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
shifts=("$@")
[ ${#shifts[@]} -eq 0 ] && shifts=(1 2)
names=$(awk '$2 ~ /^photon_engine_tests/ {print $1}' "$build/test-programs.txt" | paste -sd'|')
[ -n "$names" ] || { echo "seed-sweep: no engine tests listed in $build/test-programs.txt (build first)" >&2; exit 2; }
status=0
for shift in "${shifts[@]}"; do
    log="$build/seed-sweep-$shift.log"
    if PHOTON_TEST_SEED_SHIFT="$shift" ctest --test-dir "$build" -j2 -LE long -R "^($names)\$" --output-on-failure > "$log" 2>&1; then
        echo "seed shift $shift: all engine tests pass"
    else
        status=1
        echo "seed shift $shift: failed (log: $log)"
        grep -E '^\[  FAILED  \] [^ ]+$' "$log" | sort -u | sed 's/^/    /'
    fi
done
exit $status
