#include "calculators/in_process_calculator.h"

#include "calculators/coupling_reference.h"
#include "codec/coupling_catalog.h"
#include "codec/nearest_name.h"
#include "core/model_error.h"

namespace gc::calculators {
namespace {

template <typename Catalog>
std::vector<std::string> known_names(const Catalog& catalog) {
  std::vector<std::string> names;
  for (const auto& [name, geometry] : catalog) names.push_back(name);
  return names;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

InProcessCalculator::InProcessCalculator(std::filesystem::path catalog_dir)
    : catalog_dir_(std::move(catalog_dir)) {}

const CouplingGeometry& InProcessCalculator::geometry(std::string_view coupling) const {
  std::lock_guard lock(mutex_);
  if (is_file_reference(coupling)) {
    auto found = files_.find(coupling);
    if (found == files_.end()) {
      found = files_.emplace(std::string(coupling),
                             codec::load_coupling_geometry(std::filesystem::path(coupling)))
                  .first;
    }
    return found->second;
  }
  if (!catalog_) {
    Couplings loaded;
    for (auto& [name, geometry] : codec::load_coupling_catalog(catalog_dir_)) {
      loaded.emplace(name, std::move(geometry));
    }
    catalog_ = std::move(loaded);
  }
  const auto found = catalog_->find(coupling);
  if (found == catalog_->end()) {
    throw InvalidInput("coupling", "no coupling named \"" + std::string(coupling) + "\" in " +
                                       catalog_dir_.string() + " (known: " +
                                       joined(known_names(*catalog_)) + ")" +
                                       codec::did_you_mean(coupling, known_names(*catalog_)));
  }
  return found->second;
}

std::string InProcessCalculator::coupling_name(std::string_view coupling) const {
  return geometry(coupling).name();
}

ToothContact InProcessCalculator::tooth_contact(std::string_view coupling,
                                                const OperatingPoint& point,
                                                const ContactOptions& options) const {
  return gc::tooth_contact(geometry(coupling), point, options);
}

LoadCase InProcessCalculator::load_case(std::string_view coupling, const OperatingPoint& point,
                                        const ContactOptions& options) const {
  const CouplingGeometry& g = geometry(coupling);
  LoadCase result{gc::tooth_contact(g, point, options), {}};
  result.moments = gc::induced_moments(g, point, result.contact);
  return result;
}

std::vector<LoadCaseOutcome> InProcessCalculator::load_cases(const std::vector<LoadCaseInput>& cases,
                                                             const ContactOptions& options) const {
  std::vector<LoadCaseOutcome> out(cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    try {
      const CouplingGeometry& g = geometry(cases[i].coupling);
      LoadCase& result = out[i].result.emplace();
      result.moments = gc::induced_moments(g, cases[i].point, options, result.contact);
    } catch (...) {
      out[i].result.reset();
      out[i].error = std::current_exception();
    }
  }
  return out;
}

JamAngleReport InProcessCalculator::jam_angle(std::string_view coupling) const {
  const CouplingGeometry& g = geometry(coupling);
  return {g.jam_angle(), g.crown_radius_m(), g.crown_radius_derived()};
}

RestoringTorque InProcessCalculator::restoring_torque(std::string_view coupling) const {
  return gc::restoring_torque(geometry(coupling));
}

FrictionEstimate InProcessCalculator::estimate_friction(
    std::string_view coupling, const FrictionMeasurement& measurement) const {
  return gc::estimate_friction(geometry(coupling), measurement);
}

}  // namespace gc::calculators
