// Shared pieces of the hidden-effect proofs: the paper's model (Section 4's friction, eqs 44-45's
// pressure-angle rotation, eq 48's self-weight), parameter draws and a threaded diagnosis.
#pragma once

#include <cstdint>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/coupling_model.h"
#include "diagnosis/diagnose.h"
#include "core/effects/effect_registry.h"
#include "diagnosis/synthesis/load_sequence.h"

namespace gc::testing {

/// The paper's configuration (data/models/paper.textproto): friction mu0 0.1, rotation by phi,
/// the full self-weight; `without` names one of them to leave out.
std::vector<std::shared_ptr<const Effect>> paper_effects(const std::string& without = "");

/// Uniform draws in [low, high] per parameter; the range is a physical sub-range of the bounds
/// large enough to matter against the noise (say why in the table that gives it).
using ParameterRanges = std::map<std::string, std::pair<double, double>>;
ParameterValues draw_parameters(const ParameterRanges& ranges, std::mt19937_64& random);

/// One of the paper's load sequences (diagnosis/synthesis/load_sequence.h) for `coupling`, 960 samples
/// 0.1 s apart, run at two directions (10 and 100 deg) so that the recording sees four (beta and
/// beta + pi each time): 1920 samples.
std::vector<MeasurementSample> paper_sequence(const CouplingDefinition& coupling, LoadSequenceKind kind);

/// Diagnosis on both cores of the test machine.
Diagnosis diagnose_on_threads(const CouplingModel& model, const std::vector<RecordedSample>& observations);

/// The held-out RMSE reduction of the round's first-ranked candidate, 0 without a ranking.
double best_reduction(const DiagnosisRound& round);

}  // namespace gc::testing
