#!/usr/bin/env bash
# Queue soak (a script, not a timed test): submits JOBS small jobs to one server, then for
# SECONDS has 100 wrk connections poll job status, images and the job list while one SSE
# client per job follows its events. Prints one JSON object: answers by status, errors (any
# non-2xx/3xx other than "no image yet"), the SSE streams' statuses and final events, every
# job's status at the end (none may be missing) and the server's peak RSS (VmHWM).
#   tests/load/queue_soak.sh [BUILD_DIR] [JOBS=20] [SECONDS=60] [CONNECTIONS=100]
# Needs wrk (Debian package wrk) and curl. Binds 127.0.0.1 only.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${1:-$root/build}"
jobs="${2:-20}"
seconds="${3:-60}"
connections="${4:-100}"
source "$root/tests/load/server_support.sh"
require_wrk
start_server "$build" --max-streams 56

# The Cornell box at 128x128 with 100k photons a pass: seconds a job on two cores, so
# several finish within the soak and the rest wait in the queue. Passes vary by job.
ids=()
for i in $(seq "$jobs"); do
  passes=$((40 + 20 * (i % 4)))
  body="$(sed 's/"resolution": *\[512, *512\]/"resolution": [128, 128]/' "$root/scenes/cornell-box.json")"
  id="$(curl -sf -X POST -H 'Content-Type: application/json' -H "Idempotency-Key: soak-$i" --data-binary "$body" \
        "$base/api/v1/jobs?passes=$passes&photons_per_pass=100000" | sed -n 's/.*"id": *"\([0-9a-f]*\)".*/\1/p')"
  [ -n "$id" ] || { echo "queue_soak: submission $i failed" >&2; exit 1; }
  ids+=("$id")
done

# One SSE follower per job, for as long as the soak lasts (jobs still queued then are cut off).
followers=()
for id in "${ids[@]}"; do
  curl -sN --max-time "$seconds" -o "$work/sse-$id.txt" -w '%{http_code}\n' "$base/api/v1/jobs/$id/events" \
    > "$work/sse-$id.code" 2>/dev/null &
  followers+=($!)
done
idlist="$(IFS=,; echo "${ids[*]}")"
wrk -t2 -c"$connections" -d"${seconds}s" --timeout 10s -s "$root/tests/load/soak.lua" "$base" -- "$idlist" \
  > "$work/wrk.txt"
for pid in "${followers[@]}"; do wait "$pid" 2>/dev/null || true; done

# Every job must still be listed, each with a status that makes sense.
curl -sf "$base/api/v1/jobs?limit=1000" > "$work/listing.json"
read -r completed running queued missing < <(python3 - "$work/listing.json" "${ids[@]}" <<'PY'
import json, sys
listed = {j["id"]: j["status"] for j in json.load(open(sys.argv[1]))["jobs"]}
count = {"completed": 0, "running": 0, "queued": 0}
bad = 0
for job in sys.argv[2:]:
    status = listed.get(job)
    if status in count: count[status] += 1
    else: bad += 1
print(count["completed"], count["running"], count["queued"], bad)
PY
)
sse_ok=0; sse_bad=0; sse_done=0
for id in "${ids[@]}"; do
  if [ "$(cat "$work/sse-$id.code")" = "200" ]; then sse_ok=$((sse_ok + 1)); else sse_bad=$((sse_bad + 1)); fi
  grep -q '^event: done' "$work/sse-$id.txt" && sse_done=$((sse_done + 1))
done
hwm_kib="$(awk '/VmHWM/ {print $2}' "/proc/$server/status")"
soak="$(sed -n 's/^SOAK //p' "$work/wrk.txt")"
requests="$(awk '/requests in/ {print $1}' "$work/wrk.txt")"
cat <<JSON
{"jobs": $jobs, "seconds": $seconds, "connections": $connections, "requests": ${requests:-0},
 "wrk": $soak,
 "sse": {"streams": $jobs, "status_200": $sse_ok, "other_status": $sse_bad, "ended_with_done": $sse_done},
 "jobs_at_end": {"completed": $completed, "running": $running, "queued": $queued, "missing_or_bad": $missing},
 "server_peak_rss_mib": $(echo "scale=1; $hwm_kib / 1024" | bc)}
JSON
