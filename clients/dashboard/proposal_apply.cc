#include "clients/dashboard/proposal_apply.h"

#include <unistd.h>

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <google/protobuf/struct.pb.h>
#include <spdlog/spdlog.h>

#include "codec/result_json.h"
#include "live/live_names.h"
#include "live/swap_operator.h"
#include "protocol/dds_error.h"

namespace gc::dashboard {
namespace {

/// `text` as a JSON string, quoted and escaped (protobuf's JSON mapping).
std::string quoted(const std::string& text) {
  google::protobuf::Value value;
  value.set_string_value(text);
  return codec::to_compact_json(value);
}

JsonAnswer error(int status, const std::string& message) {
  return {status, "{\"error\": " + quoted(message) + "}"};
}

/// "dashboard@HOST": where a swap came from (the audit trail's `source`; `by` names the person).
std::string dashboard_source() {
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  return std::string("dashboard@") + host;
}

}  // namespace

ProposalApplier::ProposalApplier(dds_entity_t participant, status::MonitorBoard& proposals,
                                 std::vector<std::string> operator_cells,
                                 const std::string& operator_name)
    : proposals_(proposals), cells_(std::move(operator_cells)) {
  if (cells_.empty()) return;
  by_ = live::swap_operator(operator_name, live::operator_of_identity());
  try {
    swaps_ = std::make_unique<live::ModelSwapPublisher>(
        participant, cells_, live::swap_user_data(by_, dashboard_source()),
        live::operator_of_identity());
  } catch (const protocol::DdsError& error) {
    throw std::runtime_error(fmt::format(
        "--operator-cells {}: this dashboard's DDS identity may not publish model swaps for these "
        "test cells; applying a proposal needs an operator identity granted them "
        "(make-security.sh --operator NAME --cells ...; docs/security.md). DDS said: {}",
        fmt::join(cells_, ","), error.what()));
  }
}

JsonAnswer ProposalApplier::apply(const std::map<std::string, std::string>& parameters) const {
  const auto cell = parameters.find("test_cell");
  const auto id = parameters.find("proposal");
  if (cell == parameters.end() || cell->second.empty()) return error(400, "test_cell: missing");
  if (id == parameters.end() || id->second.empty()) return error(400, "proposal: missing");
  if (std::find(cells_.begin(), cells_.end(), cell->second) == cells_.end()) {
    return error(403, cells_.empty()
                          ? "this dashboard is read-only: start it with --operator-cells (and, "
                            "under DDS Security, an operator identity) to apply proposals"
                          : fmt::format("test_cell: this dashboard operates {} only (--operator-cells)",
                                        fmt::join(cells_, ", ")));
  }
  const auto proposals = proposals_.proposals();
  const auto found = std::find_if(proposals.begin(), proposals.end(), [&](const auto& p) {
    return p.test_cell() == cell->second && p.proposal_id() == id->second;
  });
  if (found == proposals.end()) {
    return error(404, fmt::format("proposal: test cell {} has no proposal {}", cell->second, id->second));
  }
  if (found->state() != "standing") {
    return error(409, fmt::format("proposal: {} is {}: {}", id->second, found->state(), found->state_reason()));
  }
  swaps_->publish(cell->second, found->model_text());
  spdlog::info("test cell {}: proposal {} applied from the dashboard by {} (model {})",
               cell->second, id->second, by_, found->model_name());
  return {200, fmt::format("{{\"applied\": {}, \"model\": {}}}", quoted(id->second),
                           quoted(found->model_name()))};
}

}  // namespace gc::dashboard
