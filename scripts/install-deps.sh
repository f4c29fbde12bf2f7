#!/usr/bin/env bash
# Installs the Debian 12 packages photon builds and tests with (run as root).
# Only calls apt when something is missing, so repeated runs are quick.
# With --hardening also what scripts/ci-hardening.sh needs (clang and its sanitizer and
# libFuzzer runtimes, LLVM's linker).
set -euo pipefail
packages=(cmake g++ pkg-config libembree-dev libtbb-dev libopenimageio-dev openimageio-tools
          nlohmann-json3-dev libassimp-dev libtinyobjloader-dev libnanoflann-dev libnanovdb-dev libtinygltf-dev libcpp-httplib-dev libsqlite3-dev zlib1g-dev libgtest-dev
          libcli11-dev libspdlog-dev libhiredis-dev redis-server
          python3 python3-jsonschema chromium ccache ninja-build)
if [ "${1:-}" = --hardening ]; then packages+=(clang-14 libclang-rt-14-dev lld-14); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Node.js and npm drive the browser test; any install that provides the commands will do.
command -v node > /dev/null || missing+=(nodejs)
command -v npm > /dev/null || missing+=(npm)
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update
  apt-get install -y --no-install-recommends "${missing[@]}"
fi
