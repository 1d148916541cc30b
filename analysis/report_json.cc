#include "analysis/report_json.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <vector>

#include <google/protobuf/descriptor.h>

#include "codec/result_json.h"

namespace gc::analysis {
namespace {

using google::protobuf::FieldDescriptor;
using google::protobuf::Message;
using google::protobuf::Reflection;

// protobuf's SimpleDtoa: "%.15g" (DBL_DIG digits) when it reads back, else "%.17g". to_chars
// with a precision prints as printf does, without its locale and format parsing.
void append_double(std::string& out, double value) {
  std::array<char, 32> buffer;
  for (const int precision : {15, 17}) {
    const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                            std::chars_format::general, precision);
    double back = 0.0;
    std::from_chars(buffer.data(), end, back);
    if (back == value || precision == 17) {
      out.append(buffer.data(), end);
      return;
    }
  }
}

template <typename Integer>
void append_integer(std::string& out, Integer value) {
  std::array<char, 24> buffer;
  const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  out.append(buffer.data(), end);
}

void append_indent(std::string& out, std::size_t depth) { out.append(depth, ' '); }

// A string as protobuf's JSON escapes it: quotes, backslashes and control characters, and the
// characters an HTML page must not see raw ('<', '>'). Other UTF-8 stays as it is.
void append_string(std::string& out, const std::string& text) {
  out += '"';
  for (const char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      case '<': out += "\\u003c"; break;
      case '>': out += "\\u003e"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          constexpr std::string_view kHex = "0123456789abcdef";
          out += "\\u00";
          out += kHex[static_cast<unsigned char>(c) >> 4];
          out += kHex[static_cast<unsigned char>(c) & 15];
        } else {
          out += c;
        }
    }
  }
  out += '"';
}

bool append_message(std::string& out, const Message& message, std::size_t depth);

// One value of `field` (element `index` of a repeated one, else -1), or false for a type this
// does not print as protobuf does (an int64 is a string there, a float has its own digits, an
// enum its name) or a non-finite double.
bool append_value(std::string& out, const Message& message, const FieldDescriptor& field, int index,
                  std::size_t depth) {
  const Reflection& r = *message.GetReflection();
  const bool one = index < 0;
  switch (field.type()) {
    case FieldDescriptor::TYPE_DOUBLE: {
      const double value = one ? r.GetDouble(message, &field) : r.GetRepeatedDouble(message, &field, index);
      if (!std::isfinite(value)) return false;
      append_double(out, value);
      return true;
    }
    case FieldDescriptor::TYPE_INT32:
      append_integer(out, one ? r.GetInt32(message, &field) : r.GetRepeatedInt32(message, &field, index));
      return true;
    case FieldDescriptor::TYPE_UINT32:
      append_integer(out, one ? r.GetUInt32(message, &field) : r.GetRepeatedUInt32(message, &field, index));
      return true;
    case FieldDescriptor::TYPE_BOOL:
      out += (one ? r.GetBool(message, &field) : r.GetRepeatedBool(message, &field, index)) ? "true" : "false";
      return true;
    case FieldDescriptor::TYPE_STRING:
      append_string(out, one ? r.GetString(message, &field) : r.GetRepeatedString(message, &field, index));
      return true;
    case FieldDescriptor::TYPE_MESSAGE:
      return append_message(out, one ? r.GetMessage(message, &field) : r.GetRepeatedMessage(message, &field, index),
                            depth);
    default: return false;
  }
}

// A repeated field's list, its brackets at `depth`: "[]" when empty.
bool append_list(std::string& out, const Message& message, const FieldDescriptor& field, std::size_t depth) {
  const int size = message.GetReflection()->FieldSize(message, &field);
  if (size == 0) {
    out += "[]";
    return true;
  }
  out += "[\n";
  for (int i = 0; i < size; ++i) {
    if (i > 0) out += ",\n";
    append_indent(out, depth + 1);
    if (!append_value(out, message, field, i, depth + 1)) return false;
  }
  out += '\n';
  append_indent(out, depth);
  out += ']';
  return true;
}

// The fields of a message type in the order protobuf prints them: by number, those of a oneof
// (a proto3 optional is one) after the others, as its default-value writer adds them once set.
std::vector<const FieldDescriptor*> fields_in_print_order(const google::protobuf::Descriptor& descriptor) {
  std::vector<const FieldDescriptor*> fields;
  for (int i = 0; i < descriptor.field_count(); ++i) fields.push_back(descriptor.field(i));
  std::sort(fields.begin(), fields.end(), [](const FieldDescriptor* a, const FieldDescriptor* b) {
    const bool a_later = a->containing_oneof() != nullptr, b_later = b->containing_oneof() != nullptr;
    return a_later != b_later ? b_later : a->number() < b->number();
  });
  return fields;
}

// A message, its braces at `depth` (the opening one where `out` ends): every field but one with
// presence that is not set (protobuf's always_print_primitive_fields), keyed by its proto name.
bool append_message(std::string& out, const Message& message, std::size_t depth) {
  out += '{';
  bool first = true;
  for (const FieldDescriptor* field_pointer : fields_in_print_order(*message.GetDescriptor())) {
    const FieldDescriptor& field = *field_pointer;
    if (field.is_map()) return false;
    if (!field.is_repeated() && field.has_presence() && !message.GetReflection()->HasField(message, &field)) continue;
    out += first ? "\n" : ",\n";
    first = false;
    append_indent(out, depth + 1);
    out += '"' + field.name() + "\": ";
    const bool written = field.is_repeated() ? append_list(out, message, field, depth + 1)
                                             : append_value(out, message, field, -1, depth + 1);
    if (!written) return false;
  }
  if (!first) {
    out += '\n';
    append_indent(out, depth);
  }
  out += '}';
  return true;
}

}  // namespace

std::string report_json(const gearcoupling::v1::ValidationReport& report) {
  std::string json;
  json.reserve(1u << 20);
  if (!append_message(json, report, 0)) return codec::to_json(report);
  return json + '\n';
}

}  // namespace gc::analysis
