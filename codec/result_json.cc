#include "codec/result_json.h"

#include <stdexcept>

#include <google/protobuf/util/json_util.h>

namespace gc::codec {

namespace {

std::string json_of(const google::protobuf::Message& message, bool add_whitespace) {
  google::protobuf::util::JsonPrintOptions options;
  options.add_whitespace = add_whitespace;
  options.always_print_primitive_fields = true;
  options.preserve_proto_field_names = true;
  std::string json;
  const auto status = google::protobuf::util::MessageToJsonString(message, &json, options);
  if (!status.ok()) throw std::runtime_error("JSON printing failed: " + status.ToString());
  return json;
}

}  // namespace

std::string to_json(const google::protobuf::Message& message) { return json_of(message, true); }

std::string to_compact_json(const google::protobuf::Message& message) {
  return json_of(message, false);
}

}  // namespace gc::codec
