#!/usr/bin/env bash
# The run command: installs what is missing, builds, and renders the glass Cornell box
# to out/cornell-glass.exr and .png with a progress bar.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh"
mkdir -p "$root/out"
"$root/build/cli/photon-render" "$root/scenes/cornell-glass.json" -o "$root/out/cornell-glass.exr" --png "$root/out/cornell-glass.png"
echo "wrote $root/out/cornell-glass.exr and $root/out/cornell-glass.png"
