// Result messages (idl/results.proto) -> JSON with protobuf's own printer: proto field names
// kept (they carry the units), every primitive field printed even when zero, doubles printed so
// that they parse back to the same value.
#pragma once

#include <string>

#include <google/protobuf/message.h>

namespace gc::codec {

/// Indented JSON of `message`, ending in a newline. Throws std::runtime_error if protobuf
/// refuses the message (it does not for the messages of results.proto).
std::string to_json(const google::protobuf::Message& message);

/// The same JSON on one line, without a newline: for a stream of messages (Server-Sent Events)
/// or an HTTP body.
std::string to_compact_json(const google::protobuf::Message& message);

}  // namespace gc::codec
