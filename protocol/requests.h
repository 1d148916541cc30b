// The five requests as core value types: what a client asks and what the service computes.
// Correlation travels beside them (wire.h), not inside.
#pragma once

#include <string>
#include <variant>

#include "core/coupling_definition.h"
#include "core/friction_estimate.h"
#include "core/operating_point.h"
#include "core/tooth_contact.h"

namespace gc::protocol {

/// A bundled coupling of the service's catalogue, by name.
struct CatalogueName {
  std::string name;
};

/// Which coupling a request is about: a catalogue name or an inline definition.
using CouplingRef = std::variant<CatalogueName, CouplingDefinition>;

struct ToothContactRequest {
  CouplingRef coupling;
  OperatingPoint operating_point;
  ContactOptions options;
};

struct JamAngleRequest {
  CouplingRef coupling;
};

struct InducedMomentsRequest {
  CouplingRef coupling;
  OperatingPoint operating_point;
  ContactOptions options;
};

struct RestoringTorqueRequest {
  CouplingRef coupling;
};

struct FrictionEstimateRequest {
  CouplingRef coupling;
  FrictionMeasurement measurement;
};

}  // namespace gc::protocol
