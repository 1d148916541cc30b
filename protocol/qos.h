// Every QoS the protocol uses, in one place (docs/protocol.md explains each choice).
#pragma once

#include <cstdint>
#include <string>

#include "protocol/dds_entity.h"

namespace gc::protocol {

/// Request and reply readers and writers: RELIABLE, KEEP_ALL, VOLATILE. KEEP_ALL because a
/// request or reply must never be overwritten by the next one: under a burst the writer blocks
/// (up to `max_blocking_s`) for the reader to acknowledge instead of dropping samples.
Qos request_reply_qos(double max_blocking_s = 10.0);

/// Reply writers: request_reply_qos() blocking at most `max_blocking_s` when the client does not
/// acknowledge (a killed client still matched until its lease ends), with USER_DATA = `tag`: the
/// service tags its reply writers with its instance id so a client can tell which instance's
/// writer its reply reader matched.
Qos tagged_reply_writer_qos(const std::string& tag, double max_blocking_s);

/// Status topic: RELIABLE, KEEP_LAST 1 per instance (the newest status is all that matters),
/// TRANSIENT_LOCAL so a late-joining client gets every live instance at once, and AUTOMATIC
/// liveliness with `lease_s` so a killed service's status goes NOT_ALIVE within that time.
Qos status_qos(double lease_s);

/// Status readers (and the topic): as status_qos() but without a liveliness request, so any
/// writer's lease is accepted and judged by its own offer.
Qos status_reader_qos();

/// A publisher or subscriber in exactly one partition.
Qos partition_qos(const std::string& partition);

}  // namespace gc::protocol
