// Protobuf text-format files with errors that name the field, the file, the line and column.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include <google/protobuf/message.h>

namespace gc::codec {

/// Parses `text` into `message`. Throws gc::InvalidInput whose field is `root` (plus
/// ".<field>" when the parser names one) and whose message names `source_name`, line and column.
void parse_text_format(std::string_view text, std::string_view source_name,
                       const std::string& root, google::protobuf::Message& message);

/// `json` (protobuf's JSON mapping of `message`'s type, proto field names as in the text files)
/// as text format, for parse_text_format's callers: a coupling or model given as a Python dict
/// reads through the same parser and checks as its file. Throws gc::InvalidInput naming `root`
/// and `source_name` with protobuf's reason when the JSON does not map onto the message.
std::string text_format_from_json(std::string_view json, std::string_view source_name,
                                  const std::string& root, google::protobuf::Message& message);

/// The whole file; throws gc::InvalidInput naming `root` and the path when it cannot be read.
std::string read_text_file(const std::filesystem::path& path, const std::string& root);

}  // namespace gc::codec
