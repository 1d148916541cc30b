#include "live/model_swap_publisher.h"

#include <algorithm>

#include "gearcoupling.h"
#include "live/live_names.h"
#include "live/live_qos.h"
#include "live/live_topics.h"

namespace gc::live {

ModelSwapPublisher::ModelSwapPublisher(dds_entity_t participant)
    : publisher_(make_live_publisher(participant)), topic_(make_model_topic(participant)) {
  const protocol::Qos qos = model_qos();
  writer_ = protocol::Entity(protocol::check_dds(
      dds_create_writer(publisher_.get(), topic_.get(), qos.get(), nullptr),
      "dds_create_writer(model)"));
}

void ModelSwapPublisher::publish(const std::string& test_cell, const std::string& model_text,
                                 std::uint32_t residual_decimation) {
  require_test_cell_name(test_cell);
  gearcoupling_ModelSwap swap{};
  std::copy_n(test_cell.c_str(), test_cell.size() + 1, swap.test_cell);
  swap.model_text = const_cast<char*>(model_text.c_str());
  swap.residual_decimation = residual_decimation;
  protocol::check_dds(dds_write(writer_.get(), &swap), "dds_write(model)");
}

bool ModelSwapPublisher::wait_for_readers(std::uint32_t readers,
                                          std::chrono::milliseconds timeout) const {
  return live::wait_for_readers(writer_.get(), readers, timeout);
}

}  // namespace gc::live
