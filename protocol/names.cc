#include "protocol/names.h"

#include <charconv>

#include <fmt/format.h>

namespace gc::protocol {
namespace {

constexpr std::string_view kReplyPartitionPrefix = "gearcoupling.reply.";

}  // namespace

std::string request_topic_name(Calculation calculation) {
  return fmt::format("gearcoupling/{}/request", to_string(calculation));
}

std::string reply_topic_name(Calculation calculation) {
  return fmt::format("gearcoupling/{}/reply", to_string(calculation));
}

std::optional<Calculation> calculation_of_reply_topic(std::string_view topic_name) {
  for (Calculation calculation : kAllCalculations) {
    if (topic_name == reply_topic_name(calculation)) return calculation;
  }
  return std::nullopt;
}

std::string hex_id(std::uint64_t id) { return fmt::format("{:016x}", id); }

std::string request_partition(std::uint64_t instance_id) {
  return "gearcoupling.request." + hex_id(instance_id);
}

std::string reply_partition(std::uint64_t client_id) {
  return std::string(kReplyPartitionPrefix) + hex_id(client_id);
}

std::optional<std::uint64_t> client_id_of_reply_partition(std::string_view partition) {
  if (partition.substr(0, kReplyPartitionPrefix.size()) != kReplyPartitionPrefix) {
    return std::nullopt;
  }
  const std::string_view digits = partition.substr(kReplyPartitionPrefix.size());
  if (digits.size() != 16) return std::nullopt;
  std::uint64_t id = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), id, 16);
  if (error != std::errc() || end != digits.data() + digits.size() || id == 0) return std::nullopt;
  return id;
}

}  // namespace gc::protocol
