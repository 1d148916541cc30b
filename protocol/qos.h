// Every QoS the protocol uses, in one place (docs/protocol.md explains each choice).
#pragma once

#include <cstdint>
#include <string>

#include "protocol/calculation.h"
#include "protocol/dds_entity.h"

namespace gc::protocol {

/// Request readers and writers, and reply readers: RELIABLE, KEEP_ALL, VOLATILE. KEEP_ALL
/// because a request or reply must never be overwritten by the next one: under a burst the writer
/// blocks (up to `max_blocking_s`) for the reader to acknowledge instead of dropping samples.
/// (Reply writers are KEEP_LAST: tagged_reply_writer_qos.)
Qos request_reply_qos(double max_blocking_s = 10.0);

/// How many of its latest replies a reply writer of `calculation` keeps for readers that have
/// not acknowledged them (KEEP_LAST depth): 512, and 64 for tooth contact, whose replies carry
/// every tooth (5.8 kB for the bundled couplings' 100, up to 560 kB for 10,000). Deep enough that
/// a client keeping the 256 requests in flight of docs/protocol.md rule 9 can have resent any
/// small reply it missed; for tooth contact, shallow enough that a reader that never acknowledges
/// holds at most 64 replies of the service's memory (370 kB with the bundled couplings, 36 MB at
/// the largest). Batches: kBatchReplyHistoryDepth.
std::int32_t reply_history_depth(Calculation calculation);

/// A batch's reply carries up to 4096 cases (0.5 MB of load cases, at most about 2 MB of
/// errors): 16 of them are at most 35 MB, as 64 of the largest tooth contacts. A client keeps at
/// most this many batches in flight (docs/protocol.md, "Batches"), so a batch reply it missed is
/// still resent.
inline constexpr std::int32_t kBatchReplyHistoryDepth = 16;

/// Reply writers: RELIABLE, KEEP_LAST reply_history_depth(calculation), VOLATILE, max blocking
/// `max_blocking_s`, with USER_DATA = `tag`: the service tags its reply writers with its instance
/// id so a client can tell which instance's writer its reply reader matched. KEEP_LAST, not
/// KEEP_ALL: a KEEP_ALL writer keeps every reply until every matched reader has acknowledged it
/// and blocks (or fails) once 500 kB wait, so a reader of another process in the client's
/// partition that never reads (it needs only the partition's name, which discovery tells every
/// participant) stopped the client's replies (issue 38, finding 6). A KEEP_LAST writer drops its
/// oldest reply beyond the depth, acknowledged or not, and Cyclone 0.10 never makes one wait
/// (ddsi_endpoint.c: its watermarks are INT32_MAX), so a reader that does not acknowledge costs
/// only itself. Reply readers keep KEEP_ALL (request_reply_qos): history is not matched between
/// writer and reader.
Qos tagged_reply_writer_qos(const std::string& tag, Calculation calculation, double max_blocking_s);

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
