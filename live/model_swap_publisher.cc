#include "live/model_swap_publisher.h"

#include <spdlog/spdlog.h>

#include <algorithm>

#include "core/model_error.h"
#include "gearcoupling.h"
#include "live/live_names.h"
#include "live/live_qos.h"
#include "live/live_topics.h"

namespace gc::live {

namespace {

/// A writer of `topic` in a publisher of `partitions`; DDS's return code when it is refused.
dds_return_t make_writer_in(dds_entity_t participant, dds_entity_t topic, const protocol::Qos& qos,
                            const std::vector<std::string>& partitions, protocol::Entity& publisher,
                            protocol::Entity& writer) {
  publisher = make_publisher_in(participant, partitions);
  const dds_entity_t made = dds_create_writer(publisher.get(), topic, qos.get(), nullptr);
  if (made >= 0) writer = protocol::Entity(made);
  return made;
}

}  // namespace

ModelSwapPublisher::ModelSwapPublisher(dds_entity_t participant,
                                       const std::vector<std::string>& test_cells,
                                       const std::string& user_data,
                                       const std::string& operator_name)
    : topic_(make_model_topic(participant)) {
  const protocol::Qos qos = model_qos();
  if (!user_data.empty()) dds_qset_userdata(qos.get(), user_data.data(), user_data.size());
  const std::string operator_in = operator_name.empty() ? "" : operator_partition(operator_name);
  for (const std::string& test_cell : test_cells) {
    if (writers_.count(test_cell) != 0) continue;
    CellWriter w;
    const std::string cell = cell_partition(test_cell);
    dds_return_t made = DDS_RETCODE_NOT_ALLOWED_BY_SECURITY;
    if (!operator_in.empty()) {
      made = make_writer_in(participant, topic_.get(), qos, {cell, operator_in}, w.publisher, w.writer);
      if (made == DDS_RETCODE_NOT_ALLOWED_BY_SECURITY) {
        spdlog::warn("model swaps of test cell {}: this identity's permissions do not grant "
                     "partition {} (made by an older make-security.sh?): the audit trail will not "
                     "name operator-{} as authenticated", test_cell, operator_in, operator_name);
      }
    }
    if (made < 0) made = make_writer_in(participant, topic_.get(), qos, {cell}, w.publisher, w.writer);
    protocol::check_dds(made, "dds_create_writer(model)");
    writers_.emplace(test_cell, std::move(w));
  }
}

void ModelSwapPublisher::publish(const std::string& test_cell, const std::string& model_text,
                                 std::uint32_t residual_decimation) {
  require_test_cell_name(test_cell);
  const auto found = writers_.find(test_cell);
  if (found == writers_.end()) {
    std::string known;
    for (const auto& [name, w] : writers_) known += (known.empty() ? "" : ", ") + name;
    throw InvalidInput("test_cell", "'" + test_cell + "' is not one of this publisher's test "
                                    "cells (" + known + ")");
  }
  gearcoupling_ModelSwap swap{};
  std::copy_n(test_cell.c_str(), test_cell.size() + 1, swap.test_cell);
  swap.model_text = const_cast<char*>(model_text.c_str());
  swap.residual_decimation = residual_decimation;
  protocol::check_dds(dds_write(found->second.writer.get(), &swap), "dds_write(model)");
}

bool ModelSwapPublisher::wait_for_readers(std::uint32_t readers,
                                          std::chrono::milliseconds timeout) const {
  for (const auto& [test_cell, w] : writers_) {
    if (!live::wait_for_readers(w.writer.get(), readers, timeout)) return false;
  }
  return true;
}

}  // namespace gc::live
