// The terminal view of the learning loop (`gearcoupling proposals`, `gearcoupling status`): each
// test cell's proposal with what it adds, why, and the error it is expected to remove; the
// monitors' audit trail of swaps and their refusals. Moments in kN·m, as diagnose prints them.
#pragma once

#include <cstdio>
#include <vector>

#include "idl/live_status.pb.h"

namespace gc::status {

/// A table of `proposals`, then each one's parameters and verdict; a line saying none when empty.
void print_proposals(const std::vector<gearcoupling::v1::ProposalRecord>& proposals, std::FILE* out);

/// Proposals, swaps and refusals, each only when there is any (status's view).
void print_learning(const std::vector<gearcoupling::v1::MonitorRecord>& monitors,
                    const std::vector<gearcoupling::v1::ProposalRecord>& proposals, std::FILE* out);

}  // namespace gc::status
