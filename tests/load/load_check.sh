#!/usr/bin/env bash
# Load check (a script, not a timed test): with a job rendering, CLIENTS concurrent clients
# poll its status and image for SECONDS, each waiting DELAY_MS between requests (0: flat
# out); prints the render's passes per second without and with that load, their ratio, and
# wrk's request counts and errors, as JSON.
#   tests/load/load_check.sh [BUILD_DIR] [CLIENTS=50] [SECONDS=30] [DELAY_MS=100]
# Needs wrk (Debian package wrk). Binds 127.0.0.1 only.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${1:-$root/build}"
clients="${2:-50}"
seconds="${3:-30}"
delay="${4:-100}"
source "$root/tests/load/server_support.sh"
require_wrk
start_server "$build"
data="$work"

# A long render of the diffuse Cornell box as shipped (512x512, 200k photons per pass),
# with many passes so that it outlasts the check.
id="$(curl -sf -X POST -H 'Content-Type: application/json' --data-binary @"$root/scenes/cornell-box.json" \
      "$base/api/v1/jobs?passes=100000" | sed -n 's/.*"id": *"\([0-9a-f]*\)".*/\1/p')"
pass() { curl -sf "$base/api/v1/jobs/$id" | sed -n 's/.*"pass": *\([0-9]*\).*/\1/p'; }
rate() {  # passes per second over $1 seconds
  local p0 p1 t0 t1
  p0=$(pass); t0=$(date +%s.%N); sleep "$1"; p1=$(pass); t1=$(date +%s.%N)
  echo "($p1 - $p0) / ($t1 - $t0)" | bc -l
}
sleep 3  # let the first passes run
idle=$(rate "$seconds")
wrk -t2 -c"$clients" -d"${seconds}s" -s "$root/tests/load/poll.lua" "$base" -- "$id" "$delay" > "$data/wrk.txt" &
wrkpid=$!
sleep 1
loaded=$(rate $((seconds - 3)))
# CPU seconds the load generator itself used: on a small machine it shares the cores with
# the render, so part of any slowdown is wrk's, not the server's.
wrkcpu=$(awk '{print ($14 + $15) / 100}' "/proc/$wrkpid/stat" 2>/dev/null || echo 0)
wait $wrkpid
curl -sf -X POST -d '' "$base/api/v1/jobs/$id/cancel" > /dev/null
requests=$(awk '/requests in/ {print $1}' "$data/wrk.txt")
errors=$(awk '/Non-2xx or 3xx/ {print $NF}' "$data/wrk.txt"); errors=${errors:-0}
socket=$(awk '/Socket errors/ {print}' "$data/wrk.txt")
latency=$(awk '/Latency/ {print $2; exit}' "$data/wrk.txt")
cat <<JSON
{"clients": $clients, "seconds": $seconds, "delay_ms": $delay,
 "passes_per_second_idle": $(printf '%.4f' "$idle"), "passes_per_second_loaded": $(printf '%.4f' "$loaded"),
 "loaded_over_idle": $(printf '%.3f' "$(echo "$loaded / $idle" | bc -l)"),
 "wrk_cpu_seconds": $wrkcpu, "requests": ${requests:-0}, "non_2xx_3xx": $errors, "socket_errors": "${socket:-none}", "mean_latency": "$latency"}
JSON
