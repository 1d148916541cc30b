#include "protocol/topics.h"

#include <string>

#include "protocol/calculation_traits.h"
#include "protocol/names.h"
#include "protocol/qos.h"

namespace gc::protocol {
namespace {

std::array<Entity, gc::protocol::kCalculationCount> make_topics(dds_entity_t participant, bool replies) {
  std::array<Entity, gc::protocol::kCalculationCount> topics;
  const Qos qos = request_reply_qos();
  for_each_calculation([&](auto calculation) {
    using T = CalculationTraits<decltype(calculation)::value>;
    const dds_topic_descriptor_t& type = replies ? T::reply_type() : T::request_type();
    const std::string name = replies ? reply_topic_name(T::kId) : request_topic_name(T::kId);
    topics[index_of(T::kId)] = Entity(check_dds(
        dds_create_topic(participant, &type, name.c_str(), qos.get(), nullptr), "dds_create_topic"));
  });
  return topics;
}

}  // namespace

std::array<Entity, gc::protocol::kCalculationCount> make_request_topics(dds_entity_t participant) {
  return make_topics(participant, false);
}

std::array<Entity, gc::protocol::kCalculationCount> make_reply_topics(dds_entity_t participant) {
  return make_topics(participant, true);
}

Entity make_status_topic(dds_entity_t participant) {
  const Qos qos = status_reader_qos();
  return Entity(check_dds(dds_create_topic(participant, &gearcoupling_ServiceStatus_desc,
                                           kStatusTopic, qos.get(), nullptr),
                          "dds_create_topic(status)"));
}

std::array<dds_entity_t, gc::protocol::kCalculationCount> handles(const std::array<Entity, gc::protocol::kCalculationCount>& entities) {
  std::array<dds_entity_t, gc::protocol::kCalculationCount> out{};
  for (std::size_t i = 0; i < entities.size(); ++i) out[i] = entities[i].get();
  return out;
}

}  // namespace gc::protocol
