// What both boards do with a DDS reader: create it with a data-available listener that calls
// one member of the board (in Cyclone's receive thread), and take what it holds batch by batch
// on loan until it is empty.
#pragma once

#include <dds/dds.h>

#include "protocol/dds_entity.h"
#include "protocol/qos.h"
#include "protocol/samples.h"

namespace gc::status {

/// A reader of `topic` whose data-available listener calls (owner->*kTake)(). Throws
/// protocol::DdsError naming `what`.
template <auto kTake, typename Owner>
protocol::Entity make_listening_reader(dds_entity_t subscriber, dds_entity_t topic,
                                       const protocol::Qos& qos, Owner* owner, const char* what) {
  dds_listener_t* listener = dds_create_listener(owner);
  dds_lset_data_available(listener, [](dds_entity_t, void* arg) { (static_cast<Owner*>(arg)->*kTake)(); });
  const dds_entity_t reader = dds_create_reader(subscriber, topic, qos.get(), listener);
  dds_delete_listener(listener);
  return protocol::Entity(protocol::check_dds(reader, what));
}

/// Calls `on_batch(samples)` for each batch of loaned samples until `reader` holds none.
template <typename Sample, typename OnBatch>
void take_each_batch(dds_entity_t reader, OnBatch&& on_batch) {
  for (;;) {
    protocol::LoanedSamples<Sample> samples(reader);
    if (samples.size() == 0) return;
    on_batch(samples);
  }
}

}  // namespace gc::status
