// libFuzzer target: a `gearcoupling batch` input CSV, line by line as batch.cc takes it
// (next_csv_line: BOM, CRLF, blank lines): parse_batch_header, then per row parse_batch_row, Calculator::load_case (in process,
// the bundled catalogue), and for a failed row describe_row_error; the output row is written
// with append_result_row / append_error_row.
//
// Checks: the header throws nothing but analysis::FormatError; a row is either a reason (not empty) or a
// load case with finite numbers, or load_case throws InvalidInput naming a field or NotConverged
// (calculator.h); a result row holds no "nan" or "inf".
//
// Harness limit: a row naming a coupling file (a '/' or ".textproto") is skipped: the coupling
// file target covers those files, and following arbitrary paths would read the machine's files.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>

#include "analysis/batch_csv.h"
#include "analysis/csv_fields.h"
#include "analysis/format_error.h"
#include "calculators/coupling_reference.h"
#include "calculators/in_process_calculator.h"
#include "fuzz/fuzz_checks.h"

namespace {

const gc::calculators::InProcessCalculator& calculator() {
  static const gc::calculators::InProcessCalculator in_process(GC_FUZZ_CATALOG_DIR);
  return in_process;
}

void check_result_row(const std::string& row) {
  for (std::string_view bad : {"nan", "inf"}) {
    if (row.find(bad) != std::string::npos) gc::fuzz::fail("result row with " + std::string(bad) + ": " + row);
  }
}

void evaluate_row(std::string_view line, long number, const gc::analysis::BatchColumns& columns) {
  gc::analysis::BatchRow row;
  std::string out;
  if (auto reason = gc::analysis::parse_batch_row(line, columns, "nrel_upwind", row)) {
    if (reason->empty()) gc::fuzz::fail("a bad row without a reason");
    gc::analysis::append_error_row(out, number, row.coupling, *reason);
    return;
  }
  if (gc::calculators::is_file_reference(row.coupling)) return;
  try {
    const gc::analysis::LoadCase result = calculator().load_case(row.coupling, row.point, {});
    gc::fuzz::check(result.contact, static_cast<int>(result.contact.teeth.size()));
    gc::fuzz::check(result.moments);
    gc::analysis::append_result_row(out, number, row.coupling, result);
    check_result_row(out);
  } catch (const gc::InvalidInput& error) {
    gc::fuzz::check_invalid_input(error);
    const std::string reason = gc::analysis::describe_row_error(error, columns, row);
    if (reason.empty()) gc::fuzz::fail("describe_row_error gave no reason");
    gc::analysis::append_error_row(out, number, row.coupling, reason);
  } catch (const gc::NotConverged&) {
  } catch (const std::exception& error) {
    gc::fuzz::fail(std::string("undocumented exception from load_case: ") + error.what());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  std::string line;
  long line_number = 0;
  if (!gc::analysis::next_csv_line(in, line, line_number)) return 0;
  gc::analysis::BatchColumns columns;
  bool header_ok = false;
  gc::fuzz::expect_result_or<gc::analysis::FormatError>([&] {
    columns = gc::analysis::parse_batch_header(line);
    header_ok = true;
  });
  if (!header_ok) return 0;
  while (gc::analysis::next_csv_line(in, line, line_number)) evaluate_row(line, line_number, columns);
  return 0;
}
