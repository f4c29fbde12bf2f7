#include "stream_entries.h"
#include <stdexcept>

namespace photon::farm {
namespace {

std::vector<StreamEntry> entriesOf(const RedisReply& list) {
    std::vector<StreamEntry> out;
    for (const RedisReply& e : list.elements) {
        if (e.elements.size() < 2 || e.at(1).nil()) continue;  // an entry deleted meanwhile
        StreamEntry entry{e.at(0).string, {}};
        const RedisReply& fields = e.at(1);
        for (size_t i = 0; i + 1 < fields.elements.size(); i += 2)
            entry.fields[fields.elements[i].string] = fields.elements[i + 1].string;
        out.push_back(std::move(entry));
    }
    return out;
}

}  // namespace

const std::string& StreamEntry::field(const std::string& name) const {
    auto it = fields.find(name);
    if (it == fields.end()) throw std::invalid_argument("stream entry " + id + " has no field \"" + name + "\"");
    return it->second;
}

std::vector<StreamEntry> entriesOfRead(const RedisReply& reply) {
    if (reply.nil() || reply.elements.empty()) return {};
    return entriesOf(reply.at(0).at(1));
}

std::vector<StreamEntry> entriesOfClaim(const RedisReply& reply) {
    if (reply.nil() || reply.elements.size() < 2) return {};
    return entriesOf(reply.at(1));
}

std::vector<StreamEntry> entriesOfRange(const RedisReply& reply) { return entriesOf(reply); }

void ensureGroup(RedisClient& redis, const std::string& stream, const std::string& group) {
    try {
        redis.command({"XGROUP", "CREATE", stream, group, "0", "MKSTREAM"});
    } catch (const RedisError& e) {
        if (std::string(e.what()).rfind("BUSYGROUP", 0) != 0) throw;
    }
}

}  // namespace photon::farm
