-- wrk script: each connection alternates between a job's status and its latest PNG,
-- waiting args[2] milliseconds between requests (0: as fast as it can).
local paths = {}
local wait = 0
function init(args)
  paths = { "/api/v1/jobs/" .. args[1], "/api/v1/jobs/" .. args[1] .. "/image?format=png" }
  wait = tonumber(args[2] or "0")
end
function delay()
  return wait
end
local n = 0
function request()
  n = n + 1
  return wrk.format("GET", paths[(n % 2) + 1])
end
