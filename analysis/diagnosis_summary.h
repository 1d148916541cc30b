// diagnose's terminal output: per round the candidates ranked by held-out RMSE, the verdict in
// plain language, and the residual's signature when no effect explains it.
#pragma once

#include <cstdio>

#include "idl/diagnosis.pb.h"

namespace gc::analysis {

void print_diagnosis_summary(const gearcoupling::v1::DiagnosisResult& result, std::FILE* out);

}  // namespace gc::analysis
