#include "analysis/report_json.h"

#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <string_view>

#include <google/protobuf/descriptor.h>

#include "codec/result_json.h"

namespace gc::analysis {
namespace {

namespace v1 = gearcoupling::v1;
using google::protobuf::FieldDescriptor;
using google::protobuf::Message;

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

void append_indent(std::string& out, std::size_t depth) { out.append(depth, ' '); }

// A field's value as protobuf prints it, or false for a type this does not print as protobuf
// does (an int64 is a string there, a float has its own digits) or a non-finite double.
bool append_value(std::string& out, const Message& message, const FieldDescriptor& field) {
  const auto* reflection = message.GetReflection();
  switch (field.type()) {
    case FieldDescriptor::TYPE_DOUBLE: {
      const double value = reflection->GetDouble(message, &field);
      if (!std::isfinite(value)) return false;
      append_double(out, value);
      return true;
    }
    case FieldDescriptor::TYPE_INT32: {
      std::array<char, 16> buffer;
      const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(),
                                              reflection->GetInt32(message, &field));
      out.append(buffer.data(), end);
      return true;
    }
    default: return false;
  }
}

// One point, its braces at `depth`: every field but an optional one not set (protobuf's
// always_print_primitive_fields), in the message's order, keyed by its proto name.
bool append_point(std::string& out, const Message& point, std::size_t depth) {
  append_indent(out, depth);
  out += "{\n";
  const auto* descriptor = point.GetDescriptor();
  bool first = true;
  for (int i = 0; i < descriptor->field_count(); ++i) {
    const FieldDescriptor& field = *descriptor->field(i);
    if (field.is_repeated()) return false;
    if (field.has_presence() && !point.GetReflection()->HasField(point, &field)) continue;
    out += first ? "" : ",\n";
    first = false;
    append_indent(out, depth + 1);
    out += '"' + field.name() + "\": ";
    if (!append_value(out, point, field)) return false;
  }
  out += '\n';
  append_indent(out, depth);
  out += '}';
  return true;
}

// The list of `points` as protobuf prints it after its key, the key at `depth`.
std::optional<std::string> points_json(const v1::ValidationReport::ModelPoints& model, std::size_t depth) {
  std::string out = "[\n";
  for (int i = 0; i < model.points_size(); ++i) {
    if (i > 0) out += ",\n";
    if (!append_point(out, model.points(i), depth + 1)) return std::nullopt;
  }
  out += '\n';
  append_indent(out, depth);
  out += ']';
  return out;
}

// Puts each model's points where protobuf printed its empty list ("points": [] after
// "plot_points", the result's keys all before it). False when the text is not as expected.
bool fill_points(std::string& json, const v1::ValidationReport& report) {
  constexpr std::string_view kKey = "\"points\": []";
  std::size_t at = json.find("\"plot_points\": [");
  for (const v1::ValidationReport::ModelPoints& model : report.plot_points()) {
    if (at == std::string::npos || (at = json.find(kKey, at)) == std::string::npos) return false;
    if (model.points_size() == 0) {  // protobuf's empty list it is
      at += kKey.size();
      continue;
    }
    const std::size_t line = json.rfind('\n', at);
    if (line == std::string::npos || json.find_first_not_of(' ', line + 1) != at) return false;
    const std::optional<std::string> points = points_json(model, at - line - 1);
    if (!points) return false;
    json.replace(at + kKey.size() - 2, 2, *points);
    at += kKey.size() - 2 + points->size();
  }
  return true;
}

}  // namespace

std::string report_json(const v1::ValidationReport& report) {
  v1::ValidationReport outline = report;
  for (v1::ValidationReport::ModelPoints& model : *outline.mutable_plot_points()) model.clear_points();
  std::string json = codec::to_json(outline);
  return fill_points(json, report) ? json : codec::to_json(report);
}

}  // namespace gc::analysis
