// Request members between core value types and the IDL's C types (idl/gearcoupling.idl).
// to_wire() fills a zeroed C struct with memory from dds_alloc/dds_string_dup, released by
// dds_sample_free(..., DDS_FREE_CONTENTS) (see OwnedSample); from_wire() copies out.
#pragma once

#include "gearcoupling.h"
#include "protocol/requests.h"

namespace gc::protocol {

void to_wire(const CouplingDefinition& in, gearcoupling_CouplingDefinition& out);
CouplingDefinition from_wire(const gearcoupling_CouplingDefinition& in);

void to_wire(const CouplingRef& in, gearcoupling_CouplingRef& out);
/// Throws InvalidInput("coupling", ...) for a discriminator outside CouplingSource.
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
