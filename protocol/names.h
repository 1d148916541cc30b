// Topic and partition names of the protocol (docs/protocol.md). Ids print as 16 lower-case hex
// digits, so partition names never contain DDS partition wildcards.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "protocol/calculation.h"

namespace gc::protocol {

inline constexpr const char* kStatusTopic = "gearcoupling/status";
inline constexpr const char* kStatusPartition = "gearcoupling";

/// "gearcoupling/<calculation>/request"
std::string request_topic_name(Calculation calculation);
/// "gearcoupling/<calculation>/reply"
std::string reply_topic_name(Calculation calculation);
/// The calculation whose reply topic is `topic_name`, if any.
std::optional<Calculation> calculation_of_reply_topic(std::string_view topic_name);

/// 16 lower-case hex digits.
std::string hex_id(std::uint64_t id);

/// "gearcoupling.request.<instance id>": only that service instance reads it.
std::string request_partition(std::uint64_t instance_id);
/// "gearcoupling.reply.<client id>": only that client reads it.
std::string reply_partition(std::uint64_t client_id);
/// The client id named by a reply partition, if `partition` is one.
std::optional<std::uint64_t> client_id_of_reply_partition(std::string_view partition);

}  // namespace gc::protocol
