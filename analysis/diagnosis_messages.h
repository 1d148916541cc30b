// Diagnosis results (diagnosis/) as gearcoupling.v1 messages (idl/diagnosis.proto), for
// `gearcoupling diagnose --json`.
#pragma once

#include "diagnosis/diagnose.h"
#include "idl/diagnosis.pb.h"

namespace gc::codec {

/// Every round with its ranking, fits, alike effects, signature and verdict. The caller fills
/// the recording's name and the rows its reader excluded.
gearcoupling::v1::DiagnosisResult to_message(const Diagnosis& diagnosis);

}  // namespace gc::codec
