// A Proposal as the ModelProposal sample the monitor writes (idl/gearcoupling.idl).
#pragma once

#include <dds/dds.h>

#include <cstdint>
#include <string>

#include "gearcoupling.h"
#include "live/proposal.h"

namespace gc::live {

/// Writes `proposal` through `writer` (strings lent, not copied).
void write_proposal(dds_entity_t writer, std::uint64_t monitor_id, const Proposal& proposal);

/// Disposes test cell `test_cell`'s proposal and unregisters it (a gone cell has none).
void dispose_proposal(dds_entity_t writer, const std::string& test_cell);

}  // namespace gc::live
