#include "service/catalogue.h"

#include "protocol/reply_status.h"

namespace gc::service {

Catalogue::Catalogue(std::map<std::string, CouplingGeometry> couplings)
    : couplings_(std::move(couplings)) {}

const CouplingGeometry& Catalogue::resolve(const protocol::CouplingRef& coupling,
                                           std::optional<CouplingGeometry>& storage) const {
  if (const auto* name = std::get_if<protocol::CatalogueName>(&coupling)) {
    const auto found = couplings_.find(name->name);
    if (found == couplings_.end()) throw protocol::UnknownCoupling(name->name, names());
    return found->second;
  }
  storage.emplace(std::get<CouplingDefinition>(coupling));
  return *storage;
}

std::string Catalogue::names() const {
  std::string out;
  for (const auto& [name, geometry] : couplings_) {
    if (!out.empty()) out += ", ";
    out += name;
  }
  return out;
}

}  // namespace gc::service
