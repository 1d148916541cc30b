#include "live/model_swap_publisher.h"

#include <algorithm>

#include "core/model_error.h"
#include "gearcoupling.h"
#include "live/live_names.h"
#include "live/live_qos.h"
#include "live/live_topics.h"

namespace gc::live {

ModelSwapPublisher::ModelSwapPublisher(dds_entity_t participant,
                                       const std::vector<std::string>& test_cells,
                                       const std::string& user_data)
    : topic_(make_model_topic(participant)) {
  const protocol::Qos qos = model_qos();
  if (!user_data.empty()) dds_qset_userdata(qos.get(), user_data.data(), user_data.size());
  for (const std::string& test_cell : test_cells) {
    if (writers_.count(test_cell) != 0) continue;
    CellWriter w;
    w.publisher = make_cell_publisher(participant, test_cell);
    w.writer = protocol::Entity(protocol::check_dds(
        dds_create_writer(w.publisher.get(), topic_.get(), qos.get(), nullptr),
        "dds_create_writer(model)"));
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
