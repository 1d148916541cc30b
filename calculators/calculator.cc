#include "calculators/calculator.h"

namespace gc::calculators {

std::vector<LoadCaseOutcome> Calculator::load_cases(const std::vector<LoadCaseInput>& cases,
                                                    const ContactOptions& options) const {
  std::vector<LoadCaseOutcome> out(cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    try {
      out[i].result = load_case(cases[i].coupling, cases[i].point, options);
      out[i].result->contact.teeth = {};  // as over DDS; and a batch's memory stays small
    } catch (...) {
      out[i].error = std::current_exception();
    }
  }
  return out;
}

}  // namespace gc::calculators
