// Redis Streams replies as entries, and the consumer groups the farm reads them with.
#pragma once
#include <map>
#include <string>
#include <vector>
#include "redis_client.h"

namespace photon::farm {

struct StreamEntry {
    std::string id;
    std::map<std::string, std::string> fields;
    // The field, or std::invalid_argument naming the entry and the missing field.
    const std::string& field(const std::string& name) const;
};

// The entries of an XREADGROUP reply for one stream (none when it timed out).
std::vector<StreamEntry> entriesOfRead(const RedisReply& reply);
// The entries an XAUTOCLAIM reply hands over (Redis 7: next id, entries, deleted ids).
std::vector<StreamEntry> entriesOfClaim(const RedisReply& reply);
// The entries of an XRANGE reply.
std::vector<StreamEntry> entriesOfRange(const RedisReply& reply);
// Creates the consumer group on the stream (and the stream), reading from its start; a
// group that exists already is kept.
void ensureGroup(RedisClient& redis, const std::string& stream, const std::string& group);

}  // namespace photon::farm
