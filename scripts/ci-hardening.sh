#!/usr/bin/env bash
# The CI hardening stage (runs after scripts/test.sh):
#   (a) each libFuzzer target in tests/fuzz for FUZZ_SECONDS (default 60), failing on any
#       crash, sanitizer report, leak or timeout;
#   (b) the engine tests that use threads and the server API tests under ThreadSanitizer;
#   (c) the engine unit tests and the server API tests under AddressSanitizer + UBSan.
# Each tree has its own build folder (build-fuzz, build-tsan, build-asan). Sanitizer reports
# of every process, servers started by the tests included, are written under
# <build>/sanitizer-logs and fail the stage. Prints the wall time of every step.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
fuzz_seconds="${FUZZ_SECONDS:-60}"
bash "$root/scripts/install-deps.sh" --hardening

cmake_args=(-DCMAKE_BUILD_TYPE=RelWithDebInfo)
if command -v ccache > /dev/null; then cmake_args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi

timings=()
stage_start=$SECONDS
report_timings() {
    echo "== hardening stage timings (load average at the end: $(cut -d' ' -f1-3 /proc/loadavg))"
    printf '%s\n' "${timings[@]}"
    echo "total $((SECONDS - stage_start)) s"
}
trap report_timings EXIT
step() {  # step NAME COMMAND...: runs the command and records its wall time
    local name="$1" start=$SECONDS
    shift
    echo "== $name"
    "$@"
    timings+=("$(printf '%-34s %5d s' "$name" $((SECONDS - start)))")
}

# test_tree BUILD ENGINE_TEST...: runs those engine tests and the server tests of BUILD, with
# the sanitizer options the caller set (reports go to BUILD/sanitizer-logs), each under the
# caller's `launcher` command if it sets one. Fails on a test failure or on any report, a
# server's started by a test included.
test_tree() {
    local build="$1" status=0 t
    shift
    local tests=("${@/#/$build/tests/}" "${server_tests[@]/#/$build/tests/server/}")
    for t in "${tests[@]}"; do
        echo "-- ${t##*/}"
        "${launcher[@]}" "$t" --gtest_brief=1 || status=1
    done
    if compgen -G "$build/sanitizer-logs/*" > /dev/null; then
        cat "$build"/sanitizer-logs/*
        echo "sanitizer reports in $build/sanitizer-logs"
        status=1
    fi
    return $status
}
# build_tree BUILD CMAKE_OPTION ENGINE_TEST...: the servers and those tests, in BUILD.
build_tree() {
    local build="$1" option="$2"
    shift 2
    cmake -S "$root" -B "$build" "${cmake_args[@]}" "$option" > /dev/null
    nice cmake --build "$build" -j2 --target photon-server photon-render "$@" "${server_tests[@]}"
}
launcher=()
fresh_logs() { rm -rf "$1/sanitizer-logs" && mkdir -p "$1/sanitizer-logs"; }
server_tests=(test_server_jobs test_server_errors test_server_restart test_server_openapi test_fuzz_regressions
              test_server_idempotency test_server_limits test_server_assets test_server_faults)

# ---- (a) libFuzzer ----
fuzz="$root/build-fuzz"
fuzz_build() {
    CC=clang-14 CXX=clang++-14 cmake -S "$root" -B "$fuzz" "${cmake_args[@]}" -DPHOTON_FUZZ=ON -DBUILD_TESTING=OFF \
        > /dev/null
    nice cmake --build "$fuzz" -j2 --target fuzz_scene fuzz_obj fuzz_http fuzz_checkpoint
}
# fuzz_run TARGET CORPUS: new inputs go to build-fuzz/corpus (the seeds stay as they are).
fuzz_run() {
    local target="$1" corpus="$2" log="$fuzz/$1.log" dict="$root/tests/fuzz/$1.dict"
    [ -f "$dict" ] || dict=""
    mkdir -p "$fuzz/corpus/$corpus" "$fuzz/artifacts"
    if ! ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan.supp" \
        UBSAN_OPTIONS=print_stacktrace=1 \
        "$fuzz/tests/fuzz/$target" -max_total_time="$fuzz_seconds" -timeout=30 -rss_limit_mb=4096 \
        ${dict:+-dict="$dict"} -artifact_prefix="$fuzz/artifacts/$target-" -print_final_stats=1 \
        "$fuzz/corpus/$corpus" "$root/tests/fuzz/corpus/$corpus" > "$log" 2>&1; then
        tail -n 100 "$log"
        echo "$target failed; the input is in $fuzz/artifacts"
        return 1
    fi
    grep -E "^Done|stat::number_of_executed_units|stat::new_units_added" "$log" || true
}
step "fuzz: build" fuzz_build
step "fuzz: fuzz_scene ${fuzz_seconds}s" fuzz_run fuzz_scene scene
step "fuzz: fuzz_obj ${fuzz_seconds}s" fuzz_run fuzz_obj obj
step "fuzz: fuzz_http ${fuzz_seconds}s" fuzz_run fuzz_http http
step "fuzz: fuzz_checkpoint ${fuzz_seconds}s" fuzz_run fuzz_checkpoint checkpoint

# ---- (b) ThreadSanitizer ----
# oneTBB, Embree, httplib and the other Debian libraries are not built with TSan, so TSan
# cannot see their synchronisation:
#  - oneTBB hands tasks between threads inside libtbb, so every parallel_for would be
#    reported (the task's fields, then everything its body touches). The tests run with the
#    process pinned to one CPU (taskset), where TBB starts no worker threads and runs every
#    parallel loop on the calling thread; the std::thread concurrency (render workers,
#    job queue, event hub, HTTP threads, snapshots and cancels during a render) is checked
#    in full. Parallel loops are covered by test_sppm_determinism (1 vs 2 threads bit-equal)
#    in the ordinary build instead.
#  - ignore_noninstrumented_modules: memory functions (memcpy, send, ...) called from inside
#    those libraries are not checked, e.g. httplib's function-local static strings, whose
#    initialisation guard is read in uninstrumented code. Our code's accesses still are.
# Left out: CrashTest (renders 200 passes of 200k photons to be killed halfway; ~4 minutes
# under TSan on one CPU, and the restart path is covered by the other restart tests).
tsan="$root/build-tsan"
tsan_engine_tests=(test_sppm_determinism test_renderer test_checkpoint test_radiosity test_denoise)
tsan_run() {
    fresh_logs "$tsan"
    local launcher=(taskset -c 0)
    TSAN_OPTIONS="ignore_noninstrumented_modules=1:log_path=$tsan/sanitizer-logs/tsan:second_deadlock_stack=1" \
        GTEST_FILTER='-CrashTest.*' test_tree "$tsan" "${tsan_engine_tests[@]}"
}
step "tsan: build" build_tree "$tsan" -DPHOTON_TSAN=ON "${tsan_engine_tests[@]}"
step "tsan: tests" tsan_run

# ---- (c) AddressSanitizer + UndefinedBehaviorSanitizer ----
# Left out, as too slow under ASan for what they add: test_sppm_vs_path (converges two
# integrators to 1% at thousands of samples; the same code runs here in test_renderer and
# test_furnace) and test_cli (renders whole example scenes through photon-render). The
# browser page test needs Chromium and is not a C++ test.
asan="$root/build-asan"
asan_engine_tests=(test_bsdf test_checkpoint test_denoise test_furnace test_image_io test_lights
                   test_point_light_plane test_radiosity test_renderer test_sampling test_scene_loader
                   test_scene_loader_errors test_sppm_determinism test_sppm_radius)
asan_run() {
    fresh_logs "$asan"
    ASAN_OPTIONS="detect_leaks=1:log_path=$asan/sanitizer-logs/asan" \
        UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:log_path=$asan/sanitizer-logs/ubsan" \
        test_tree "$asan" "${asan_engine_tests[@]}"
}
step "asan+ubsan: build" build_tree "$asan" -DPHOTON_SANITIZE=ON "${asan_engine_tests[@]}"
step "asan+ubsan: tests" asan_run
