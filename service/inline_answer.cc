#include "service/inline_answer.h"

#include <variant>

namespace gc::service {

int teeth_of(const protocol::CouplingRef& coupling, const Catalogue& catalogue) {
  if (const auto* definition = std::get_if<CouplingDefinition>(&coupling)) {
    return definition->teeth;
  }
  const auto& entries = catalogue.couplings();
  const auto entry = entries.find(std::get<protocol::CatalogueName>(coupling).name);
  return entry == entries.end() ? 0 : entry->second.definition().teeth;
}

bool cheap_to_answer(int teeth, const ContactOptions& options) {
  return teeth <= kInlineTeethBound &&
         static_cast<long>(options.slices) * options.load_sharing.max_iterations <=
             kInlineContactWorkBound;
}

bool cheap_to_answer(const protocol::ToothContactRequest& request, const Catalogue& catalogue) {
  return cheap_to_answer(teeth_of(request.coupling, catalogue), request.options);
}

bool cheap_to_answer(const protocol::InducedMomentsRequest& request, const Catalogue& catalogue) {
  return cheap_to_answer(teeth_of(request.coupling, catalogue), request.options);
}

bool cheap_to_answer(const protocol::JamAngleRequest& request, const Catalogue& catalogue) {
  return teeth_of(request.coupling, catalogue) <= kInlineTeethBound;
}

bool cheap_to_answer(const protocol::RestoringTorqueRequest& request, const Catalogue& catalogue) {
  return teeth_of(request.coupling, catalogue) <= kInlineTeethBound;
}

bool cheap_to_answer(const protocol::FrictionEstimateRequest& request,
                     const Catalogue& catalogue) {
  return teeth_of(request.coupling, catalogue) <= kInlineTeethBound;
}

bool cheap_to_answer(const protocol::BatchRequest&, const Catalogue&) { return false; }

}  // namespace gc::service
