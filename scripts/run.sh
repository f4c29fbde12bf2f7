#!/usr/bin/env bash
# The run command: installs what is missing, builds, and starts the render service on
# http://127.0.0.1:8080/ (the page) with its jobs and images under data/.
# Extra arguments go to photon-server (e.g. --port 9000 --workers 2 --token SECRET).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh"
exec "$root/build/app/photon-server" --data "$root/data" --web-root "$root/web" "$@"
