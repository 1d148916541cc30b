#include "analysis/plain_csv_row.h"

#include <charconv>
#include <cmath>
#include <cstring>

#include "analysis/number_text.h"

namespace gc::analysis {
namespace {

// The end of the plain field at `at` by its use, or nullptr when it is not plain. A skipped
// field may hold anything but a quote: a quoted field may hold a comma, which only the general
// tokenizer reads right.
const char* plain_field_end(const char* at, const char* end, CellUse use, double*& value) {
  switch (use) {
    case CellUse::skip: {
      const char* comma = static_cast<const char*>(std::memchr(at, ',', static_cast<std::size_t>(end - at)));
      const char* field_end = comma != nullptr ? comma : end;
      return std::memchr(at, '"', static_cast<std::size_t>(field_end - at)) == nullptr ? field_end : nullptr;
    }
    case CellUse::check:
      return plain_moderate_number_end(at, end);
    case CellUse::convert: {
      // from_chars stops at the comma; it reads no '+', no blank, no quote: those give up.
      const auto [number_end, error] = std::from_chars(at, end, *value);
      if (error != std::errc() || number_end == at || !std::isfinite(*value)) return nullptr;
      ++value;
      return number_end;
    }
  }
  return nullptr;
}

}  // namespace

bool read_plain_row(std::string_view record, std::span<const CellUse> uses, std::span<double> values) {
  const char* at = record.data();
  const char* const end = at + record.size();
  double* value = values.data();
  for (std::size_t field = 0; field < uses.size(); ++field) {
    if (field > 0) {
      if (at == end || *at != ',') return false;  // fewer fields, or text after a number
      ++at;
    }
    at = plain_field_end(at, end, uses[field], value);
    if (at == nullptr) return false;
  }
  return at == end;  // else more fields, or text after the last number
}

}  // namespace gc::analysis
