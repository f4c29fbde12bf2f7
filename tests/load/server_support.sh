# Sourced by the load scripts: checks for wrk and starts photon-server on a free loopback
# port with a fresh data directory, removed (and the server stopped) when the script exits.
#   start_server BUILD_DIR [SERVER_OPTION...]   sets $work, $server and $base
require_wrk() {
  command -v wrk > /dev/null || { echo "$(basename "$0"): needs wrk (apt-get install wrk)" >&2; exit 2; }
}

start_server() {
  local build="$1"; shift
  work="$(mktemp -d)"
  "$build/app/photon-server" --host 127.0.0.1 --port 0 --data "$work/store" "$@" > "$work/server.log" 2>&1 &
  server=$!
  trap 'kill $server 2>/dev/null; wait $server 2>/dev/null; rm -rf "$work"' EXIT
  for _ in $(seq 100); do grep -q "listening on" "$work/server.log" && break; sleep 0.1; done
  base="$(grep -o 'http://[0-9.:]*' "$work/server.log" | head -1)"
}
