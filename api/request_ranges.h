// Range requests (RFC 9110 section 14), bounded. httplib answers a Range header on any
// response, building every part in memory: 2,600 ranges of a 60 KB job list made a 150 MB
// response from 8 KB of request. And on a response from a content provider (the images)
// Debian's httplib 0.11.4 sends the range's bytes with status 200 and no Content-Range,
// which a client takes for the whole image. So the API (images included) and the metrics
// ignore Range, as a server may (RFC 9110 14.2), and are sent whole; the page's files honour
// a few ranges.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace photon::api {

// At most this many ranges of one request for a file are honoured.
constexpr size_t kMaxRanges = 4;

// The ranges a request for `path` keeps: none under /api/ and for /metrics; for the page's
// files the ranges themselves when there are at most kMaxRanges of them, each with a start,
// in increasing order without overlaps (a suffix range "-N" only alone); otherwise none.
// Ranges are (first, last) with -1 for an open end, as httplib parses them.
std::vector<std::pair<long, long>> rangesToHonour(const std::string& path,
                                                  const std::vector<std::pair<long, long>>& ranges);

}  // namespace photon::api
