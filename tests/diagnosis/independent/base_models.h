// The models the diagnosis starts from: the paper's (data/models/paper.textproto: friction with
// mu0 = 0.1 only, the pressure-angle rotation, the full self-weight) for the upwind NREL coupling,
// possibly with one of its effects left out. The only file of this directory that names library
// effects: the base model is what is under test, never how a truth is made.
#pragma once

#include <string>

#include "core/coupling_model.h"

namespace gc::independent {

/// The paper's model of nrel_upwind; `without` names an effect of it to leave out ("" for none).
CouplingModel paper_model(const std::string& without = "");

}  // namespace gc::independent
