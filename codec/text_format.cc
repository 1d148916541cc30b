#include "codec/text_format.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <google/protobuf/descriptor.h>
#include <google/protobuf/io/tokenizer.h>
#include <google/protobuf/text_format.h>
#include <google/protobuf/util/json_util.h>

#include "codec/nearest_name.h"
#include "core/model_error.h"

namespace gc::codec {
namespace {

namespace pb = google::protobuf;

// Turns the text-format parser's first error into an InvalidInput naming the field when the
// parser names one ("... has no field named \"x\"."), and the source, line and column always.
class ThrowingErrorCollector : public pb::io::ErrorCollector {
 public:
  ThrowingErrorCollector(std::string_view source, const std::string& root)
      : source_(source), root_(root) {}

  void AddError(int line, pb::io::ColumnNumber column, const std::string& message) override {
    if (!first_error_.empty()) return;
    // The parser counts lines and columns from zero; editors count from one.
    const std::string guess = suggestion(message);
    std::string said = message;
    if (!guess.empty() && !said.empty() && said.back() == '.') said.pop_back();  // "...\"x\"; did you"
    first_error_ = std::string(source_) + ":" + std::to_string(line + 1) + ":" +
                   std::to_string(column + 1) + ": " + said + guess;
    field_ = root_ + named_field(message);
  }

  void throw_if_failed() const {
    if (!first_error_.empty()) throw InvalidInput(field_, first_error_);
  }

 private:
  static std::string named_field(const std::string& message) {
    static constexpr std::string_view kMarker = "field named \"";
    const auto begin = message.find(kMarker);
    if (begin == std::string::npos) return "";
    const auto name_begin = begin + kMarker.size();
    const auto end = message.find('"', name_begin);
    if (end == std::string::npos) return "";
    std::string field(".");
    field.append(message, name_begin, end - name_begin);
    return field;
  }

  /// The text between the `nth` pair of double quotes of `message` (0: the first), "" if none.
  static std::string quoted(const std::string& message, int nth) {
    std::size_t at = 0;
    for (int k = 0;; ++k) {
      const auto open = message.find('"', at);
      if (open == std::string::npos) return "";
      const auto close = message.find('"', open + 1);
      if (close == std::string::npos) return "";
      if (k == nth) return message.substr(open + 1, close - open - 1);
      at = close + 1;
    }
  }

  /// "; did you mean 'x'?" for a misspelt field ("Message type \"T\" has no field named \"y\"."),
  /// from the fields of that message type (issue 39); "" for other errors or when none is near.
  static std::string suggestion(const std::string& message) {
    if (message.find("has no field named") == std::string::npos) return "";
    const pb::Descriptor* type = pb::DescriptorPool::generated_pool()->FindMessageTypeByName(quoted(message, 0));
    if (type == nullptr) return "";
    std::vector<std::string> names;
    for (int i = 0; i < type->field_count(); ++i) names.push_back(type->field(i)->name());
    return did_you_mean(quoted(message, 1), names);
  }

 private:
  std::string_view source_;
  std::string root_;
  std::string first_error_;
  std::string field_;
};

}  // namespace

void parse_text_format(std::string_view text, std::string_view source_name,
                       const std::string& root, pb::Message& message) {
  ThrowingErrorCollector errors(source_name, root);
  pb::TextFormat::Parser parser;
  parser.RecordErrorsTo(&errors);
  const bool parsed = parser.ParseFromString(std::string(text), &message);
  errors.throw_if_failed();
  if (!parsed) {
    throw InvalidInput(root, std::string(source_name) + ": not a " +
                                 message.GetDescriptor()->name() + " text proto");
  }
}

std::string text_format_from_json(std::string_view json, std::string_view source_name,
                                  const std::string& root, pb::Message& message) {
  message.Clear();
  const auto status = pb::util::JsonStringToMessage(pb::StringPiece(json.data(), json.size()), &message);
  if (!status.ok()) {
    throw InvalidInput(root, std::string(source_name) + ": not a " + message.GetDescriptor()->name() +
                                 ": " + std::string(status.message()));
  }
  std::string text;
  pb::TextFormat::PrintToString(message, &text);
  return text;
}

std::string read_text_file(const std::filesystem::path& path, const std::string& root) {
  // fopen, not ifstream: it sets errno, so the message can say why (no such file, permission).
  std::FILE* file = std::fopen(path.c_str(), "rb");
  const auto cannot_read = [&](int error) {
    return InvalidInput(root, "cannot read " + root + " file " + path.string() + ": " +
                                  std::strerror(error));
  };
  if (file == nullptr) throw cannot_read(errno);
  std::string text;
  char buffer[1 << 16];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) text.append(buffer, n);
  const int error = std::ferror(file) ? errno : 0;
  std::fclose(file);
  if (error != 0) throw cannot_read(error);   // e.g. a directory: "Is a directory"
  return text;
}

}  // namespace gc::codec
