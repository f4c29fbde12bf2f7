#!/usr/bin/env bash
# Configures and builds photon in BUILD_DIR (default: build), Release.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
# ccache (installed by install-deps.sh) makes rebuilds of unchanged sources free, also from
# another clone of the repository (CI builds a fresh one each time): paths are hashed
# relative to the checkout, and the build folder is left out of the hash.
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1
# The test programs use precompiled headers (CMakeLists.txt); ccache caches their sources
# only when told to trust the header's timestamps and the macros it was built with.
export CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
# Unity builds: the libraries' sources compiled eight to a unit, so the headers they share
# (nlohmann/json, Embree, oneTBB, cpp-httplib) are parsed once for eight; a cold build of
# engine/, server/ and api/ took about a third of the time.
# Ninja (install-deps.sh): a build tree configured before with Makefiles starts afresh.
if [ -f "$build/CMakeCache.txt" ] && ! grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' "$build/CMakeCache.txt"; then
    rm -rf "$build/CMakeCache.txt" "$build/CMakeFiles"
fi
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=8 \
    "${launcher[@]}" "$@"
cmake --build "$build" -j2
