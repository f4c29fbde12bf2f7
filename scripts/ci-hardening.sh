#!/usr/bin/env bash
# The CI hardening stage (runs after scripts/test.sh), in two build trees:
#   (a) build-sanitize: clang with AddressSanitizer + UndefinedBehaviorSanitizer and libFuzzer's
#       coverage hooks. Each libFuzzer target runs for FUZZ_SECONDS (default 45), failing on
#       any crash, sanitizer report, leak or timeout; then every engine unit test but the two
#       long end-to-end comparisons, the service's unit tests and the API tests (against a
#       sanitized photon-server) run in the same tree.
#   (b) build-tsan: the tests with threads of their own (the renderer's, the service's units,
#       the API tests) under ThreadSanitizer.
# Sanitizer reports of every process, servers started by the tests included, are written
# under <build>/sanitizer-logs and fail the stage. Prints the wall time of every step, and
# a line for every test that was skipped.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
fuzz_seconds="${FUZZ_SECONDS:-20}"
bash "$root/scripts/install-deps.sh" --hardening

# Line tables only (-g1): sanitizer reports still name file and line, and the two builds
# compile and link faster than with full debug information.
# Ninja: CMake's Makefiles build the targets named on one command line one after another
# (.NOTPARALLEL), so each test program's one source compiled on one core while the other
# idled; measured cold, the two builds took 1,285 and 539 s that way.
# Unity builds of eight sources a unit, as scripts/build.sh.
cmake_args=(-G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG"
            -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=8)
if command -v ccache > /dev/null; then cmake_args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
# As in build.sh: cached objects serve any clone of the repository, precompiled headers included.
export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1
export CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime

# configure BUILD ARGS...: a tree configured before with another generator starts afresh.
configure() {
    local build="$1"
    shift
    if [ -f "$build/CMakeCache.txt" ] && ! grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' "$build/CMakeCache.txt"; then
        rm -rf "$build/CMakeCache.txt" "$build/CMakeFiles"
    fi
    cmake -S "$root" -B "$build" "${cmake_args[@]}" "$@" > /dev/null
}

timings=()
skipped=()
stage_start=$SECONDS
report() {
    echo "== hardening stage timings (load average at the end: $(cut -d' ' -f1-3 /proc/loadavg))"
    printf '%s\n' "${timings[@]}"
    echo "total $((SECONDS - stage_start)) s"
    if [ ${#skipped[@]} -gt 0 ]; then
        echo "SKIPPED under the sanitizers: ${#skipped[@]} test(s):"
        printf '  %s\n' "${skipped[@]}"
    else
        echo "skipped tests under the sanitizers: 0"
    fi
}
trap report EXIT
step() {  # step NAME COMMAND...: runs the command and records its wall time
    local name="$1" start=$SECONDS
    shift
    echo "== $name"
    "$@"
    timings+=("$(printf '%-34s %5d s' "$name" $((SECONDS - start)))")
}

# The test programs each tree builds, and whose sources it runs (tests/CMakeLists.txt says
# which sources each program holds and why): under ASan and UBSan the engine's tests that
# handle buffers of a size read or computed at run time and those of its own threads, the
# service's units, the API and farm tests; under TSan those with threads of their own.
san_programs=(photon_engine_tests photon_engine_tests_threads photon_service_unit_tests photon_api_tests
              photon_api_tests_requests photon_farm_tests)
tsan_programs=(photon_engine_tests_threads photon_service_unit_tests photon_api_tests photon_farm_tests)
# sources_of BUILD PROGRAM...: the test sources (ctest's test names) those programs hold, from
# the list the build writes (<build>/test-programs.txt: "SOURCE PROGRAM PATH").
sources_of() {
    local build="$1"
    shift
    awk -v programs=" $* " 'index(programs, " " $2 " ") { print $1 }' "$build/test-programs.txt"
}

# Under the sanitizers the slowest test sources (cold CI, in seconds: ASan farm_server 58,
# server_restart 56, photon_guiding 47, server_jobs 41; TSan server_jobs 73, farm_server 87,
# server_image_options 55, server_errors 49, server_limits 45) start first, so that neither
# lane is left with one of them at the end.
slowest_first=(test_farm_server test_server_jobs test_server_restart test_server_image_options test_photon_guiding
               test_server_errors test_server_limits test_sppm_bands test_checkpoint test_server_connections
               test_lights)
# in_slowest_first_order SOURCE...: the sources, those of slowest_first first.
in_slowest_first_order() {
    local t s
    for s in "${slowest_first[@]}"; do
        for t in "$@"; do [ "$t" = "$s" ] && echo "$t"; done
    done
    for t in "$@"; do
        [[ " ${slowest_first[*]} " == *" $t "* ]] || echo "$t"
    done
}

# run_tests BUILD SOURCE...: runs each test source's cases (its program with --photon_source)
# under the caller's `launcher`, with the sanitizer options the caller set. Fails on a
# failing test or on any sanitizer report. The sources run in two lanes at once, each lane
# taking the next from a queue (slowest first)
# when it is done with one (on 2 cores the sanitized programs wait on I/O and on their
# servers much of the time, and the stage took over 15 minutes one after another; every
# other source in each lane left one lane 100 s behind the other); a launcher word LANE
# becomes the lane's number (taskset -c LANE pins each lane to a CPU of its own).
run_tests() {
    local build="$1" status=0 t
    shift
    rm -rf "$build/sanitizer-logs" && mkdir -p "$build/sanitizer-logs"
    in_slowest_first_order "$@" > "$build/test-queue"
    echo 0 > "$build/test-queue.taken"
    run_lane 0 "$build" > "$build/lane-0.out" 2>&1 &
    local first=$!
    run_lane 1 "$build" > "$build/lane-1.out" 2>&1 &
    local second=$!
    wait "$first" || status=1
    wait "$second" || status=1
    cat "$build/lane-0.out" "$build/lane-1.out"
    echo "-- the slowest tests here:"
    for t in "$@"; do cat "$build/$t.log"; done | grep -aoE '^\[       OK \] [A-Za-z0-9_./]+ \([0-9]+ ms\)' |
        sed -E 's/^\[       OK \] (.*) \(([0-9]+) ms\)/\2 \1/' | sort -rn | head -n 15 || true
    for t in "$@"; do
        while read -r line; do
            skipped+=("$t: ${line#\[  SKIPPED \] }")
            echo "SKIPPED: $t: ${line#\[  SKIPPED \] }"
        done < <(grep -E '^\[  SKIPPED \] [A-Za-z_]+\.' "$build/$t.log" || true)
    done
    if compgen -G "$build/sanitizer-logs/*" > /dev/null; then
        cat "$build"/sanitizer-logs/*
        echo "sanitizer reports in $build/sanitizer-logs"
        status=1
    fi
    return $status
}
# next_source BUILD: the queue's next source not yet taken by a lane (nothing at its end).
next_source() {
    flock "$1/test-queue.taken" bash -c 'n=$(cat "$1"); echo $((n + 1)) > "$1"; sed -n "$((n + 1))p" "$2"' \
        _ "$1/test-queue.taken" "$1/test-queue"
}
# run_lane LANE BUILD: one lane of run_tests, taking sources from the queue until it is empty.
run_lane() {
    local lane="$1" build="$2" status=0 t path log start
    local command=("${launcher[@]/#LANE/$lane}")
    while t=$(next_source "$build") && [ -n "$t" ]; do
        path=$(awk -v source="$t" '$1 == source { print $3 }' "$build/test-programs.txt")
        log="$build/$t.log"
        echo "-- $t (lane $lane)"
        start=$SECONDS
        "${command[@]}" "$path" "--photon_source=$t.cpp" > "$log" 2>&1 || { cat "$log"; status=1; }
        tail -n 3 "$log"
        echo "   $t: $((SECONDS - start)) s"
    done
    return $status
}
launcher=()

# ---- (a) ASan + UBSan + libFuzzer: one tree ----
san="$root/build-sanitize"
san_build() {
    CC=clang-14 CXX=clang++-14 configure "$san" -DPHOTON_FUZZ=ON
    nice cmake --build "$san" -j2 --target fuzz_scene fuzz_obj fuzz_http fuzz_checkpoint fuzz_ply fuzz_pbrt fuzz_bsdf photon-server photon-render photon-worker \
        "${san_programs[@]}"
}
# fuzz_run TARGET CORPUS: new inputs go to build-sanitize/corpus (the seeds stay as they are).
fuzz_run() {
    local target="$1" corpus="$2" log="$san/$1.log" dict="$root/tests/fuzz/$1.dict"
    [ -f "$dict" ] || dict=""
    mkdir -p "$san/corpus/$corpus" "$san/artifacts"
    if ! ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan.supp" \
        UBSAN_OPTIONS=print_stacktrace=1 \
        "$san/tests/fuzz/$target" -max_total_time="$fuzz_seconds" -timeout=30 -rss_limit_mb=4096 \
        ${dict:+-dict="$dict"} -artifact_prefix="$san/artifacts/$target-" -print_final_stats=1 \
        "$san/corpus/$corpus" "$root/tests/fuzz/corpus/$corpus" > "$log" 2>&1; then
        tail -n 100 "$log"
        echo "$target failed; the input is in $san/artifacts"
        return 1
    fi
    grep -E "^Done|stat::number_of_executed_units|stat::new_units_added" "$log" || true
}
# Left out here, as they run in the test command (GCC, no sanitizer) and what they add under
# ASan is time, not code:
#  - the farm tests that kill, pause or restart a render that must run for seconds first
#    (FarmServerTest.ARestartedServer..., .AWholeJob..., FarmRedisRestartTest: about a minute
#    and a half under ASan; the farm's code paths are run by the other farm tests);
#  - the slowest convergence comparisons, 330 s of the stage's 1,160 (cold CI, two lanes),
#    the adaptive photon count's image check, photon guiding in bands against one band (28 s;
#    PhotonGuiding's and SppmBands' other cases run each):
#    they render the same code paths for hundreds of passes until a statistic settles, and
#    shorter tests of the same programs run those paths (the photon mapper's with
#    InstancesVsCopies/sppm and test_photonmap's others, lightweight's with its
#    no-photons and thread tests, projection maps' with the spot-light and caustic tests);
#  - the slowloris test, which times answers to a second while 400 connections trickle bytes
#    (34 s under ASan; the connection guard's code is run by the other connection tests);
#  - SceneLoaderErrors.MutatedScenesNeverCrash, every leaf of a full scene set to eleven wrong
#    values in turn (132 s of the lanes under ASan): fuzz_scene above does the same under
#    ASan, guided by coverage;
#  - PhotonMap.GlassBoxAgreesWithSppm: built by clang, the two-pass photon mapper's image
#    differs from GCC's (SPPM's is the same bit for bit under both), one region by 7.6% from
#    SPPM against the test's 5% (GCC: 1.5%).
san_slow='Integrators/InstancesVsCopies.RenderTheSameImage/photonmap'
san_slow+=':Lightweight.GlassCornellBoxAgreesWithThePathTracerInMeanAndPerRegion:Lightweight.PhotonsTakeTheCausticsNoiseAway'
san_slow+=':Radiosity.CornellBoxWallsAgreeWithSppm:PhotonMap.CornellBoxWithFinalGatherAgreesWithPathTracer'
san_slow+=':ProjectionMap.DistantObjectUnderPointLightSameImageTenfoldFewerMisses'
san_slow+=':ProjectionMap.SpheresApartUnderDirectionalLightSameImageTenfoldFewerMisses'
san_slow+=':AdaptivePhotons.ImageAgreesWithFixedPhotonsPerPass'
san_slow+=':PhotonMap.CornellBoxWithFinalGatherIntoFullEstimatesAgreesWithPathTracer'
san_slow+=':SceneLoaderErrors.MutatedScenesNeverCrash'
san_slow+=':SppmBands.PhotonGuidingGivesTheOneBandImage'
# A subsurface ball in a white sky, to 2,048 passes (37 s under ASan): the volume photons'
# and the media's paths are run by the furnace of fog and the foggy mirror in the same program.
san_slow+=':ScatteringMedium.AnImportedSubsurfaceBallOfSpectralonInAWhiteSkyIsWhite'
san_tests() {
    GTEST_FILTER="-PhotonMap.GlassBoxAgreesWithSppm:FarmServerTest.ARestartedServer*:FarmServerTest.AWholeJob*:FarmRedisRestartTest.*:ConnectionsTest.ASlowloris*:$san_slow" \
    ASAN_OPTIONS="detect_leaks=1:log_path=$san/sanitizer-logs/asan" \
        LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan.supp" \
        UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:log_path=$san/sanitizer-logs/ubsan" \
        run_tests "$san" $(sources_of "$san" "${san_programs[@]}")
}
step "asan+ubsan: build" san_build
step "fuzz: fuzz_scene ${fuzz_seconds}s" fuzz_run fuzz_scene scene
step "fuzz: fuzz_obj ${fuzz_seconds}s" fuzz_run fuzz_obj obj
step "fuzz: fuzz_ply ${fuzz_seconds}s" fuzz_run fuzz_ply ply
step "fuzz: fuzz_pbrt ${fuzz_seconds}s" fuzz_run fuzz_pbrt pbrt
step "fuzz: fuzz_bsdf ${fuzz_seconds}s" fuzz_run fuzz_bsdf bsdf
step "fuzz: fuzz_http ${fuzz_seconds}s" fuzz_run fuzz_http http
step "fuzz: fuzz_checkpoint ${fuzz_seconds}s" fuzz_run fuzz_checkpoint checkpoint
step "asan+ubsan: tests" san_tests

# ---- (b) ThreadSanitizer ----
# oneTBB, Embree, httplib and the other Debian libraries are not built with TSan, so TSan
# cannot see their synchronisation:
#  - oneTBB hands tasks between threads inside libtbb, so every parallel_for would be
#    reported (the task's fields, then everything its body touches). The tests run with the
#    process pinned to one CPU (taskset), where TBB starts no worker threads and runs every
#    parallel loop on the calling thread; the std::thread concurrency (render workers, job
#    queue, event hub, HTTP threads, snapshots and cancels during a render) is checked in
#    full. Parallel loops are covered by test_sppm_determinism (1 vs 2 threads bit-equal) in
#    the ordinary build instead, which is also why engine tests whose only threads are TBB's
#    (radiosity, denoise, determinism) are not run here: on one CPU they would check nothing.
#  - ignore_noninstrumented_modules: memory functions (memcpy, send, ...) called from inside
#    those libraries are not checked, e.g. httplib's function-local static strings, whose
#    initialisation guard is read in uninstrumented code. Our code's accesses still are.
# Left out:
#  - CrashTest, FarmServerTest.ARestartedServer..., FarmServerTest.AWholeJob... and
#    FarmRedisRestartTest: they render for seconds to be interrupted halfway, many times
#    slower under TSan on one CPU; the restart path is covered by the other restart tests;
#  - the slowloris test: it times answers to a second while 400 connections trickle bytes, a
#    timing test that on one CPU under TSan says nothing; the guard's thread is exercised by
#    the other connection tests;
#  - Renderer.CancelInsideAPassKeepsTheLastCompleteImage: four passes of 2M photons (69 s
#    here), cancelled from the calling thread before the pass starts, so on one CPU, where
#    the pass's loop runs on that thread alone, there is no second thread to check;
#  - JobsTest.EachMethodReportsItsOwnFigures: each method through the server (44 s here,
#    radiosity's solve most of it); a job's progress and figures cross the same threads for
#    every method, and the other JobsTest cases follow them while a job runs.
#  - photon_api_tests_requests, the API tests whose subject is what one request gets back
#    (tests/server/CMakeLists.txt): their requests cross the same HTTP threads, queue and
#    event hub as the tests that run here, which follow jobs while they render (220 s of the
#    lanes' time under TSan). They run under ASan above and in the test command.
tsan="$root/build-tsan"
tsan_build() {
    configure "$tsan" -DPHOTON_TSAN=ON
    nice cmake --build "$tsan" -j2 --target photon-server photon-render photon-worker "${tsan_programs[@]}"
}
tsan_tests() {
    local launcher=(taskset -c LANE)
    TSAN_OPTIONS="ignore_noninstrumented_modules=1:log_path=$tsan/sanitizer-logs/tsan:second_deadlock_stack=1" \
        GTEST_FILTER='-CrashTest.*:ConnectionsTest.ASlowloris*:FarmServerTest.ARestartedServer*:FarmServerTest.AWholeJob*:FarmRedisRestartTest.*:Renderer.CancelInsideAPassKeepsTheLastCompleteImage:JobsTest.EachMethodReportsItsOwnFigures' \
        run_tests "$tsan" $(sources_of "$tsan" "${tsan_programs[@]}")
}
step "tsan: build" tsan_build
step "tsan: tests" tsan_tests
