// gearcoupling batch: load cases from CSV through eqs 5-48, results to CSV (format in
// batch_csv.h). Streams in bounded chunks: read a chunk of lines, compute its parts on all
// threads, write them in input order, repeat; memory does not grow with the input.
#include <malloc.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

#include <fmt/format.h>

#include "analysis/batch_csv.h"
#include "clients/cli/jobs_flag.h"
#include "clients/cli/operating_point_flags.h"
#include "clients/cli/subcommand.h"
#include "core/model_error.h"

namespace gc::cli {

using analysis::BatchColumns;
using analysis::next_csv_line;
using analysis::BatchRow;
using analysis::append_error_row;
using analysis::append_result_row;
using analysis::batch_output_header;
using analysis::describe_row_error;
using analysis::parse_batch_header;
using analysis::parse_batch_row;
using calculators::LoadCaseInput;
using calculators::LoadCaseOutcome;
namespace {

// Lines each thread takes per chunk: large enough to amortise starting the threads, small
// enough that a chunk's text and results stay within a few megabytes.
constexpr std::size_t kLinesPerThread = 4096;

std::vector<FlagSpec> batch_flags() {
  std::vector<FlagSpec> flags = {
      {"in", "FILE|-", "input CSV of load cases ('-': standard input)", std::nullopt},
      {"out", "FILE|-", "output CSV of results ('-': standard output)", "-"},
      jobs_flag(),
  };
  append(flags, contact_option_flags());
  append(flags, calculator_flags(/*json=*/false));
  flags.push_back({"json", "", "", std::nullopt, true, '\0', {},
                   "batch writes CSV (see --out and --help)"});
  return flags;
}

// What every worker reads; nothing here changes while a chunk runs.
struct BatchJob {
  const Calculator& calculator;
  BatchColumns columns;
  std::string default_coupling;
  ContactOptions options;
};

// What one worker produces for its share of a chunk.
struct ChunkPart {
  std::string output;
  std::string errors;
  long failed_rows = 0;
};

// Rows a thread hands to the calculator at once (Calculator::load_cases): over DDS, a batch of
// this many cases per request (protocol::kMaxBatchCases allows 4096). 512 cost the least CPU of
// 256, 512 and 1024 (client and service together, 200,000 cases: 1.55, 1.55-1.6 and 1.63 s):
// a batch's replies of 1024 cases passed 128 kB, which the service maps afresh every time
// (service/main.cc), and at 256 the client paid more per request. Small batches also let the
// threads' parsing and printing overlap the service's computing. In process the size does not
// matter.
constexpr std::size_t kCasesPerCall = 512;

void append_failed_row(std::string_view coupling, long number, const std::string& reason,
                       ChunkPart& part) {
  append_error_row(part.output, number, coupling, reason);
  part.errors += fmt::format("gearcoupling batch: line {}: {}\n", number, reason);
  ++part.failed_rows;
}

// The reason a computed row failed, as the user wrote it: `row` is parsed again from `line`
// (only for failed rows) so the error can quote its fields.
std::string failure_reason(std::exception_ptr error, std::string_view line, const BatchJob& job,
                           BatchRow& row) {
  try {
    std::rethrow_exception(error);
  } catch (const InvalidInput& e) {
    parse_batch_row(line, job.columns, job.default_coupling, row);
    return describe_row_error(e, job.columns, row);
  } catch (const std::exception& e) {  // NotConverged, or anything else: the row fails
    return e.what();
  }
}

// A chunk of input lines with their line numbers (blank lines are skipped, so they need not
// be consecutive).
struct InputLines {
  std::vector<std::string> text;
  std::vector<long> numbers;
};

// Lines [begin, end): parsed, computed kCasesPerCall at a time through the calculator, written
// in input order (a row that does not parse, or whose case fails, as an error row).
void evaluate_lines(const InputLines& lines, std::size_t begin, std::size_t end,
                    const BatchJob& job, ChunkPart& part) {
  part.output.clear();
  part.errors.clear();
  part.failed_rows = 0;
  BatchRow row;
  std::vector<LoadCaseInput> cases;
  std::vector<std::optional<std::string>> bad_rows;  // per line of the call: why it did not parse
  for (std::size_t first = begin; first < end; first += kCasesPerCall) {
    const std::size_t last = std::min(end, first + kCasesPerCall);
    cases.clear();
    bad_rows.assign(last - first, std::nullopt);
    for (std::size_t i = first; i < last; ++i) {
      if (auto bad_row = parse_batch_row(lines.text[i], job.columns, job.default_coupling, row)) {
        bad_rows[i - first] = std::move(*bad_row);
      } else {
        cases.push_back({std::string(row.coupling), row.point});
      }
    }
    const std::vector<LoadCaseOutcome> outcomes = job.calculator.load_cases(cases, job.options);
    std::size_t k = 0;
    for (std::size_t i = first; i < last; ++i) {
      const long number = lines.numbers[i];
      if (const auto& bad_row = bad_rows[i - first]) {
        parse_batch_row(lines.text[i], job.columns, job.default_coupling, row);
        append_failed_row(row.coupling, number, *bad_row, part);
        continue;
      }
      const LoadCaseOutcome& outcome = outcomes[k];
      const std::string& coupling = cases[k++].coupling;
      if (outcome.result) {
        append_result_row(part.output, number, coupling, *outcome.result);
      } else {
        append_failed_row(coupling, number,
                          failure_reason(outcome.error, lines.text[i], job, row), part);
      }
    }
  }
}

// Splits the first `count` lines into parts.size() contiguous shares, one per thread, this
// thread taking the first. Returns the number of failed rows.
long evaluate_chunk(const InputLines& lines, std::size_t count, const BatchJob& job,
                    std::vector<ChunkPart>& parts) {
  const std::size_t share = (count + parts.size() - 1) / parts.size();
  std::vector<std::jthread> workers;
  for (std::size_t k = 1; k < parts.size(); ++k) {
    const std::size_t begin = std::min(count, k * share);
    const std::size_t end = std::min(count, begin + share);
    workers.emplace_back([&, k, begin, end] { evaluate_lines(lines, begin, end, job, parts[k]); });
  }
  evaluate_lines(lines, 0, std::min(share, count), job, parts[0]);
  workers.clear();  // joins
  long failed = 0;
  for (const ChunkPart& part : parts) failed += part.failed_rows;
  return failed;
}

std::size_t read_lines(std::istream& in, long& line_number, InputLines& lines) {
  std::size_t count = 0;
  while (count < lines.text.size() && next_csv_line(in, lines.text[count], line_number)) {
    lines.numbers[count++] = line_number;
  }
  return count;
}

std::unique_ptr<std::istream> open_input(const std::string& path) {
  if (path == "-") {
    std::ios::sync_with_stdio(false);
    return std::make_unique<std::istream>(std::cin.rdbuf());
  }
  auto file = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*file) throw UsageError(fmt::format("--in {}: cannot open: {}", path, std::strerror(errno)));
  return file;
}

struct FileCloser {
  void operator()(std::FILE* file) const {
    if (file != stdout) std::fclose(file);
  }
};
using OutputFile = std::unique_ptr<std::FILE, FileCloser>;

OutputFile open_output(const std::string& path, const std::string& input_path,
                       std::FILE* standard_output) {
  if (path == "-") return OutputFile(standard_output);
  std::error_code error;  // a file that does not exist yet is not the input
  if (input_path != "-" && std::filesystem::equivalent(path, input_path, error)) {
    throw UsageError(fmt::format("--out {}: is the input file; it would be overwritten", path));
  }
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) {
    throw UsageError(fmt::format("--out {}: cannot open: {}", path, std::strerror(errno)));
  }
  return OutputFile(file);
}

void write_parts(const std::vector<ChunkPart>& parts, std::FILE* out) {
  for (const ChunkPart& part : parts) {
    std::fwrite(part.output.data(), 1, part.output.size(), out);
    std::fputs(part.errors.c_str(), stderr);
  }
}

int run_batch(const Flags& flags, const Calculator& calculator, std::FILE* standard_output) {
  // Each call of load_cases frees its results (a few hundred kB; over DDS the batch replies too)
  // and the next allocates them again: glibc gave the top of the heap back to the kernel after
  // each free and took it again (brk), or mapped and unmapped each block over 128 kB, and the
  // page faults of memory taken afresh cost as much system time as the computing (0.9 s of 2 s
  // for 200,000 rows in process, 0.4 s of 1.1 s of the client's CPU over DDS). Kept, the memory
  // is a chunk's, which the batch needs again at once.
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's largest
  const int threads = jobs_from(flags);
  const std::unique_ptr<std::istream> in = open_input(flags.text("in"));
  std::string header;
  long line_number = 0;
  if (!next_csv_line(*in, header, line_number)) {
    throw UsageError("--in " + flags.text("in") + ": no header line");
  }
  BatchJob job{calculator, parse_batch_header(header), flags.text("coupling"),
               contact_options_from(flags)};
  const OutputFile out = open_output(flags.text("out"), flags.text("in"), standard_output);
  std::fputs(batch_output_header().c_str(), out.get());

  const std::size_t chunk_lines = kLinesPerThread * static_cast<std::size_t>(threads);
  InputLines lines{std::vector<std::string>(chunk_lines), std::vector<long>(chunk_lines)};
  std::vector<ChunkPart> parts(static_cast<std::size_t>(threads));
  long rows = 0;
  long failed = 0;
  while (const std::size_t count = read_lines(*in, line_number, lines)) {
    failed += evaluate_chunk(lines, count, job, parts);
    write_parts(parts, out.get());
    rows += static_cast<long>(count);
  }
  if (std::fflush(out.get()) != 0 || std::ferror(out.get())) {
    fmt::print(stderr, "gearcoupling batch: --out {}: write failed: {}\n", flags.text("out"),
               std::strerror(errno));
    return 1;
  }
  if (failed > 0) {
    fmt::print(stderr, "gearcoupling batch: {} of {} rows failed\n", failed, rows);
    return 1;
  }
  return 0;
}

}  // namespace

const Subcommand& batch_subcommand() {
  static const Subcommand subcommand{
      "batch",
      "CSV of load cases through contact and moments (eqs 5-48), on all cores, streaming.\n"
      "Writes one CSV row per input row, in input order.\n"
      "Input header: torque_<nm|knm|mnm>,misalignment_<rad|deg|mrad>,mu[,direction_<rad|deg|mrad>]\n"
      "[,coupling] (any order, units in any case, as a recording's; direction 0 when absent;\n"
      "coupling per row defaults to --coupling). Output: line,coupling,q,teeth_in_contact,\n"
      "max_tooth_load_n,moment_y_nm,moment_z_nm,sensor_moment_y_nm,sensor_moment_z_nm,\n"
      "magnitude_nm,contact_stress_pa,bending_stress_pa,contact_safety_factor,\n"
      "bending_safety_factor,error. A bad row is reported on stderr with its line number and\n"
      "written with empty results and the reason in 'error'; the other rows still run.\n"
      "Exit code: 0 every row ran, 1 some rows failed, 2 bad flags or header.",
      batch_flags, run_batch};
  return subcommand;
}

}  // namespace gc::cli
