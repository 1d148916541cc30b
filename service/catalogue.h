// The couplings one service instance serves by name, and the resolution of a request's coupling
// reference (a catalogue name or an inline definition) to a validated geometry.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "core/coupling_geometry.h"
#include "protocol/requests.h"

namespace gc::service {

class Catalogue {
 public:
  explicit Catalogue(std::map<std::string, CouplingGeometry> couplings);

  /// The geometry `coupling` names. A catalogue name returns the shared, immutable entry; an
  /// inline definition is validated into `storage` (throws InvalidInput naming
  /// "coupling.<member>"). Throws protocol::UnknownCoupling for a name not in the catalogue.
  const CouplingGeometry& resolve(const protocol::CouplingRef& coupling,
                                  std::optional<CouplingGeometry>& storage) const;

  const std::map<std::string, CouplingGeometry>& couplings() const { return couplings_; }
  /// "nrel_downwind, nrel_upwind"
  std::string names() const;

 private:
  std::map<std::string, CouplingGeometry> couplings_;
};

}  // namespace gc::service
