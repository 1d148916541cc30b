#include <cstdlib>

#include <fmt/format.h>

#include "clients/cli/subcommand.h"
#include "codec/coupling_catalog.h"
#include "codec/result_json.h"

namespace gc::cli {

std::vector<FlagSpec> common_flags() {
  return {
      {"coupling", "NAME|FILE",
       "coupling: a name in the catalogue, or a .textproto file (a path with '/' or ending in "
       ".textproto)",
       "nrel_upwind"},
      {"catalog", "DIR", "catalogue directory of *.textproto couplings ($GEARCOUPLING_CATALOG)",
       codec::default_catalog_dir().string()},
      {"json", "", "print the result as JSON (field names carry their units)", std::nullopt,
       true},
      {"remote", "", "compute on gearcoupling-service over DDS (CYCLONEDDS_URI) instead of here",
       std::nullopt, true},
      {"domain", "N", "DDS domain of the service, with --remote", "0"},
      {"timeout", "S", "seconds to wait for each reply, with --remote", "10"},
      {"client-id-prefix", "HEX8",
       "with --remote and DDS Security: the client_id_prefix of this identity "
       "(docs/security.md; $GC_CLIENT_ID_PREFIX)",
       std::getenv("GC_CLIENT_ID_PREFIX") != nullptr ? std::getenv("GC_CLIENT_ID_PREFIX") : ""},
  };
}

void print_json(const google::protobuf::Message& message, std::FILE* out) {
  fmt::print(out, "{}", codec::to_json(message));
}

}  // namespace gc::cli
