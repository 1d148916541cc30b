#include <fmt/format.h>

#include "calculators/client_id_prefix.h"
#include "clients/cli/subcommand.h"
#include "codec/coupling_catalog.h"
#include "codec/result_json.h"
#include "protocol/domain_id.h"

namespace gc::cli {

FlagSpec catalogue_flag() {
  return {"catalogue", "DIR",
          "catalogue directory of *.textproto couplings ($GEARCOUPLING_CATALOG)",
          codec::default_catalog_dir().string()};
}

FlagSpec domain_flag(std::string help) {
  return {"domain", "N", help + ", 0.." + std::to_string(protocol::kMaxDomainId), "0"};
}

int domain_from(const Flags& flags) { return flags.integer("domain", 0, protocol::kMaxDomainId); }

FlagSpec json_flag() {
  return {"json", "", "print the result as JSON (field names carry their units)", std::nullopt,
          true};
}

std::vector<FlagSpec> calculator_flags(bool json) {
  std::vector<FlagSpec> flags = {
      {"coupling", "NAME|FILE",
       "coupling: a name in the catalogue, or a .textproto file (a path with '/' or ending in "
       ".textproto)",
       "nrel_upwind"},
      catalogue_flag(),
      {"remote", "", "compute on gearcoupling-service over DDS (CYCLONEDDS_URI) instead of here",
       std::nullopt, true},
      domain_flag("DDS domain of the service, with --remote"),
      {"timeout-s", "s", "with --remote, seconds the whole command may take, discovery and every request included, (0, 3600]", "10", false,
       '\0', {"timeout"}},
      {"client-id-prefix", "HEX8", std::string("with --remote, ") + calculators::kClientIdPrefixHelp,
       calculators::client_id_prefix_from_environment()},
  };
  if (json) flags.push_back(json_flag());
  return flags;
}

std::vector<FlagSpec> refused_calculator_flags(std::string_view subcommand) {
  const std::string reason = fmt::format(
      "not taken by {}: it computes in process, on the model file's coupling (--model); the "
      "service computes single load cases only (docs/cli.md)",
      subcommand);
  std::vector<FlagSpec> flags;
  for (FlagSpec& flag : calculator_flags(/*json=*/false)) {
    if (flag.name == "catalogue") continue;
    flag.refused = reason;
    flags.push_back(std::move(flag));
  }
  return flags;
}

FlagSpec live_domain_flag() {
  return domain_flag("DDS domain of the live test cell (CYCLONEDDS_URI)");
}

void append(std::vector<FlagSpec>& flags, std::vector<FlagSpec> more) {
  for (FlagSpec& flag : more) flags.push_back(std::move(flag));
}

void print_json(const google::protobuf::Message& message, std::FILE* out) {
  fmt::print(out, "{}", codec::to_json(message));
}

}  // namespace gc::cli
