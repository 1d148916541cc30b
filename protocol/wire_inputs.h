// Request members between core value types and the IDL's C types (idl/gearcoupling.idl).
// to_wire() fills a zeroed C struct with memory from dds_alloc/dds_string_dup, released by
// dds_sample_free(..., DDS_FREE_CONTENTS) (see OwnedSample); from_wire() copies out.
#pragma once

#include <cstddef>

#include "gearcoupling.h"
#include "protocol/requests.h"

namespace gc::protocol {

/// Most bytes of a coupling name on the wire (`catalogue_name`, an inline definition's `name`):
/// names are echoed in error replies and logs, so their length is bounded (issue 9).
inline constexpr std::size_t kMaxNameBytes = 256;

void to_wire(const CouplingDefinition& in, gearcoupling_CouplingDefinition& out);
/// Throws InvalidInput("coupling.name", ...) for a name over kMaxNameBytes.
CouplingDefinition from_wire(const gearcoupling_CouplingDefinition& in);

void to_wire(const CouplingRef& in, gearcoupling_CouplingRef& out);
/// Throws InvalidInput("coupling", ...) for a discriminator outside CouplingSource, and
/// InvalidInput("coupling.catalogue_name" or "coupling.name", ...) for a name over
/// kMaxNameBytes.
CouplingRef from_wire(const gearcoupling_CouplingRef& in);

void to_wire(const OperatingPoint& in, gearcoupling_OperatingPoint& out);
OperatingPoint from_wire(const gearcoupling_OperatingPoint& in);

void to_wire(const ContactOptions& in, gearcoupling_ContactOptions& out);
ContactOptions from_wire(const gearcoupling_ContactOptions& in);

void to_wire(const FrictionMeasurement& in, gearcoupling_FrictionMeasurement& out);
FrictionMeasurement from_wire(const gearcoupling_FrictionMeasurement& in);

/// A string copied with dds_string_dup, for a C sample that dds_sample_free releases.
char* wire_string(const std::string& text);

}  // namespace gc::protocol
