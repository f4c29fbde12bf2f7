-- wrk script for queue_soak.sh: each connection cycles through the submitted jobs, asking
-- for a job's status, its latest PNG and the job list in turn. Answers are tallied by
-- status; a 404 for a job's image before its first pass ("has no image yet") is expected,
-- every other non-2xx/3xx answer is an error. done() prints the tallies as one JSON line.
local threads = {}

function setup(thread)
  table.insert(threads, thread)
end

function init(args)
  ids = {}
  for id in string.gmatch(args[1], "[^,]+") do table.insert(ids, id) end
  n = math.random(0, #ids * 3)
  counts = {}
  errors = 0
  noimage = 0
end

function request()
  n = n + 1
  local id = ids[math.floor(n / 3) % #ids + 1]
  local kind = n % 3
  if kind == 0 then return wrk.format("GET", "/api/v1/jobs/" .. id) end
  if kind == 1 then return wrk.format("GET", "/api/v1/jobs/" .. id .. "/image?format=png") end
  return wrk.format("GET", "/api/v1/jobs?limit=100")
end

function response(status, headers, body)
  counts[status] = (counts[status] or 0) + 1
  if status == 404 and string.find(body, "has no image yet", 1, true) then
    noimage = noimage + 1
  elseif status >= 400 then
    errors = errors + 1
  end
end

function done(summary, latency, requests)
  local total, errs, waiting = {}, 0, 0
  for _, t in ipairs(threads) do
    for status, c in pairs(t:get("counts")) do total[status] = (total[status] or 0) + c end
    errs = errs + t:get("errors")
    waiting = waiting + t:get("noimage")
  end
  local parts = {}
  for status, c in pairs(total) do table.insert(parts, string.format('"%d": %d', status, c)) end
  io.write(string.format('SOAK {"by_status": {%s}, "errors": %d, "no_image_yet": %d, "socket_errors": %d, ' ..
                         '"timeouts": %d, "p99_ms": %.1f}\n',
                         table.concat(parts, ", "), errs, waiting,
                         summary.errors.connect + summary.errors.read + summary.errors.write,
                         summary.errors.timeout, latency:percentile(99) / 1000))
end
