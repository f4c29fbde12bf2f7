// A whole job's progress as the fields of a result entry (farm_keys.h), and back: what the
// coordinator needs to report the pass as if it had rendered it. Doubles travel with 17
// significant digits, so they arrive as they left.
#pragma once
#include <string>
#include <vector>
#include <photon/progress.h>
#include "../job.h"
#include "stream_entries.h"

namespace photon::farm {

// Appends field, value pairs; `photons` is how many were emitted since the last report, and
// `figures` the method's figures so far (passed on as the report's pass statistics).
void appendProgressFields(std::vector<std::string>& args, const RenderProgress& progress, int64_t photons,
                          const server::MethodFigures& figures);
// Throws std::invalid_argument naming a missing or malformed field.
RenderProgress progressOfFields(const StreamEntry& entry);

}  // namespace photon::farm
