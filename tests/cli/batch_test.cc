// gearcoupling batch end to end: bad rows reported and the others exact, order and threads,
// streaming memory.
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "codec/coupling_catalog.h"
#include "core/coupling_geometry.h"
#include "core/induced_moments.h"
#include "run_process.h"

namespace gc::cli::testing {
namespace {

constexpr double kDegree = M_PI / 180.0;

const CouplingGeometry& catalog_coupling(const std::string& name) {
  static const auto catalog = codec::load_coupling_catalog(GC_BUNDLED_CATALOG_DIR);
  return catalog.at(name);
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator)) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines = split(text, '\n');
  if (!lines.empty() && lines.back().empty()) lines.pop_back();
  return lines;
}

// Checks an output row against the core run in this process, exactly: batch prints the
// shortest text that reads back to the same double.
void expect_row_equals_core(const std::string& row, long line, const std::string& coupling,
                            const OperatingPoint& point) {
  const std::vector<std::string> f = split(row, ',');
  ASSERT_EQ(f.size(), 15u) << row;
  const CouplingGeometry& g = catalog_coupling(coupling);
  const ToothContact contact = tooth_contact(g, point);
  const InducedMoments moments = induced_moments(g, point, contact);
  EXPECT_EQ(std::stol(f[0]), line);
  EXPECT_EQ(f[1], coupling);
  EXPECT_EQ(std::strtod(f[2].c_str(), nullptr), contact.load_sharing.q);
  EXPECT_EQ(std::stoi(f[3]), contact.teeth_in_contact);
  EXPECT_EQ(std::strtod(f[4].c_str(), nullptr), contact.max_tooth_load_n);
  EXPECT_EQ(std::strtod(f[5].c_str(), nullptr), moments.moment_y_nm);
  EXPECT_EQ(std::strtod(f[6].c_str(), nullptr), moments.moment_z_nm);
  EXPECT_EQ(std::strtod(f[7].c_str(), nullptr), moments.sensor_moment_y_nm);
  EXPECT_EQ(std::strtod(f[8].c_str(), nullptr), moments.sensor_moment_z_nm);
  EXPECT_EQ(std::strtod(f[9].c_str(), nullptr), moments.magnitude_nm);
  EXPECT_EQ(std::strtod(f[10].c_str(), nullptr), contact.max_stress.contact_stress_pa);
  EXPECT_EQ(std::strtod(f[11].c_str(), nullptr), contact.max_stress.bending_stress_pa);
  EXPECT_EQ(f[14], "");  // no error
}

// `rows` load cases cycling over torque, misalignment, direction and mu; every 997th row has
// a misalignment beyond the upwind jam angle, so it must fail.
std::string generated_cases(int rows) {
  std::string csv = "torque_nm,misalignment_deg,direction_deg,mu\n";
  for (int i = 0; i < rows; ++i) {
    const double misalignment = i % 997 == 5 ? 3.0 : 0.7 * (i % 101) / 100.0;
    csv += std::to_string(2e5 + 1e3 * (i % 1800)) + "," + std::to_string(misalignment) + "," +
           std::to_string((i * 7) % 360) + "," + std::to_string(0.002 * (i % 90)) + "\n";
  }
  return csv;
}

TEST(CliBatch, BadRowIsReportedWithItsLineAndTheOthersMatchTheCore) {
  const std::string in = temp_path("gc_batch_small");
  write_file(in,
             "torque_nm,misalignment_deg,direction_deg,mu\n"
             "1.5e6,0.4,30,0.1\n"     // line 2
             "1e6,2,0,0.1\n"          // line 3: beyond the jam angle
             "1e6,0.2,90,0.12\n"      // line 4
             "1e6,0.2,x,0.12\n"       // line 5: not a number
             "8e5,0,0,0\n"            // line 6: aligned
             "1e308,0.4,0,0.1\n");    // line 7: above the core's torque bound
  const ProcessResult run = run_gearcoupling({"batch", "--in", in});
  EXPECT_EQ(run.exit_code, 1);  // some rows failed
  const std::vector<std::string> rows = lines_of(run.out);
  ASSERT_EQ(rows.size(), 7u) << run.out;
  EXPECT_EQ(rows[0].rfind("line,coupling,q,teeth_in_contact,max_tooth_load_n,moment_y_nm", 0), 0u);
  expect_row_equals_core(rows[1], 2, "nrel_upwind", {1.5e6, 0.4 * kDegree, 30 * kDegree, 0.1});
  EXPECT_EQ(rows[2].rfind("3,nrel_upwind,,,,,,,,,,,,,\"misalignment_deg 2: ", 0), 0u) << rows[2];
  expect_row_equals_core(rows[3], 4, "nrel_upwind", {1e6, 0.2 * kDegree, 90 * kDegree, 0.12});
  EXPECT_EQ(rows[4], "5,nrel_upwind,,,,,,,,,,,,,direction_deg 'x' is not a number");
  expect_row_equals_core(rows[5], 6, "nrel_upwind", {8e5, 0.0, 0.0, 0.0});
  EXPECT_EQ(rows[6].rfind("7,nrel_upwind,,,,,,,,,,,,,", 0), 0u) << rows[6];
  EXPECT_NE(rows[6].find("torque_nm 1e308: operating_point.torque_nm"), std::string::npos);
  EXPECT_EQ(run.out.find("nan"), std::string::npos);
  EXPECT_EQ(run.out.find("inf"), std::string::npos);
  EXPECT_NE(run.err.find("line 3: misalignment_deg 2: operating_point.misalignment_rad"),
            std::string::npos) << run.err;
  EXPECT_NE(run.err.find("line 5: direction_deg 'x' is not a number"), std::string::npos);
  EXPECT_NE(run.err.find("3 of 6 rows failed"), std::string::npos);
}

TEST(CliBatch, AllGoodRowsExitZero) {
  const std::string in = temp_path("gc_batch_good");
  write_file(in, "torque_nm,misalignment_deg,direction_deg,mu\n1e6,0.1,0,0.1\n");
  const ProcessResult run = run_gearcoupling({"batch", "--in", in});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(run.err.empty());
}

TEST(CliBatch, ReadsStandardInputWithAnyColumnOrderAndACouplingPerRow) {
  const std::string in = temp_path("gc_batch_stdin");
  write_file(in,
             "mu,coupling,torque_nm,direction_deg,misalignment_deg\n"
             "0.1,nrel_downwind,1.2e6,45,1.0\n"
             "0.05,nrel_upwind,9e5,10,0.3\n");
  const ProcessResult run = run_gearcoupling({"batch", "--in", "-", "--out", "-"}, in);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::vector<std::string> rows = lines_of(run.out);
  ASSERT_EQ(rows.size(), 3u);
  expect_row_equals_core(rows[1], 2, "nrel_downwind", {1.2e6, 1.0 * kDegree, 45 * kDegree, 0.1});
  expect_row_equals_core(rows[2], 3, "nrel_upwind", {9e5, 0.3 * kDegree, 10 * kDegree, 0.05});
}

TEST(CliBatch, WritesToTheOutFile) {
  const std::string in = temp_path("gc_batch_in");
  const std::string out = temp_path("gc_batch_out");
  write_file(in, generated_cases(5));  // rows 0-4: no bad row yet
  const ProcessResult run = run_gearcoupling({"batch", "--in", in, "--out", out});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(run.out.empty());
  EXPECT_EQ(lines_of(read_file(out)).size(), 6u);
}

TEST(CliBatch, AcceptsByteOrderMarkAndWindowsLineEnds) {
  const std::string in = temp_path("gc_batch_crlf");
  write_file(in, "\xEF\xBB\xBFtorque_nm,misalignment_deg,direction_deg,mu\r\n1e6,0.2,90,0.12\r\n");
  const ProcessResult run = run_gearcoupling({"batch", "--in", in});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::vector<std::string> rows = lines_of(run.out);
  ASSERT_EQ(rows.size(), 2u);
  expect_row_equals_core(rows[1], 2, "nrel_upwind", {1e6, 0.2 * kDegree, 90 * kDegree, 0.12});
}

// The tokenizer recordings use too (analysis/csv_fields.h): blank lines, a trailing one included,
// are no rows; quoted fields are fields ("1e6" a number, "0,2" not); lines keep their numbers.
TEST(CliBatch, BlankLinesAreSkippedAndQuotedNumbersRead) {
  const std::string in = temp_path("gc_batch_blank");
  write_file(in, "torque_nm,misalignment_deg,direction_deg,mu\n\n\"1e6\",0.2,\"90\",0.12\n  \n"
                 "1e6,\"0,2\",90,0.12\n\n");
  const ProcessResult run = run_gearcoupling({"batch", "--in", in});
  EXPECT_EQ(run.exit_code, 1) << run.err;   // the decimal comma row fails, nothing else
  const std::vector<std::string> rows = lines_of(run.out);
  ASSERT_EQ(rows.size(), 3u) << run.out;
  expect_row_equals_core(rows[1], 3, "nrel_upwind", {1e6, 0.2 * kDegree, 90 * kDegree, 0.12});
  EXPECT_TRUE(rows[2].starts_with("5,nrel_upwind,")) << rows[2];
  EXPECT_NE(rows[2].find("misalignment_deg '0,2' is not a number"), std::string::npos) << rows[2];
  EXPECT_NE(run.err.find("1 of 2 rows failed"), std::string::npos) << run.err;
}

TEST(CliBatch, HeaderOnlyGivesHeaderOnlyAndNoHeaderIsAnError) {
  const std::string in = temp_path("gc_batch_header_only");
  write_file(in, "torque_nm,misalignment_deg,direction_deg,mu\n");
  const ProcessResult run = run_gearcoupling({"batch", "--in", in});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(lines_of(run.out).size(), 1u);
  write_file(in, "");
  const ProcessResult empty = run_gearcoupling({"batch", "--in", in});
  EXPECT_EQ(empty.exit_code, 2);
  EXPECT_NE(empty.err.find("no header line"), std::string::npos) << empty.err;
}

TEST(CliBatch, BadHeaderExitsTwoNamingTheColumn) {
  const std::string in = temp_path("gc_batch_header");
  write_file(in, "torque_nm,misalignment_deg,direction_deg,friction\n1e6,0.1,0,0.1\n");
  const ProcessResult run = run_gearcoupling({"batch", "--in", in});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("unknown column 'friction'"), std::string::npos) << run.err;
  write_file(in, "torque_nm,misalignment_deg,direction_deg\n1e6,0.1,0\n");
  const ProcessResult missing = run_gearcoupling({"batch", "--in", in});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("required column missing (one of: mu)"), std::string::npos) << missing.err;
}

// The recordings' unit rules (analysis/recording_csv.h): any unit a recording accepts, in any
// case, and direction optional (0). Each row must equal the same load case in SI and degrees.
TEST(CliBatch, ReadsAnyUnitARecordingAcceptsAndDirectionIsOptional) {
  const std::string in = temp_path("gc_batch_units");
  write_file(in, "torque_kNm,misalignment_mrad,mu\n1500,3.5,0.1\n");
  const ProcessResult run = run_gearcoupling({"batch", "--in", in});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::vector<std::string> rows = lines_of(run.out);
  ASSERT_EQ(rows.size(), 2u) << run.out;
  expect_row_equals_core(rows[1], 2, "nrel_upwind", {1500 * 1e3, 3.5 * 1e-3, 0.0, 0.1});

  write_file(in, "torque_mnm,misalignment_rad,direction_deg,mu\n1.5,0.0035,90,0.1\n");
  const ProcessResult radians = run_gearcoupling({"batch", "--in", in});
  ASSERT_EQ(radians.exit_code, 0) << radians.err;
  expect_row_equals_core(lines_of(radians.out).at(1), 2, "nrel_upwind", {1.5 * 1e6, 0.0035, 90 * kDegree, 0.1});
}

TEST(CliBatch, UnknownUnitAndRepeatedQuantityNameTheColumns) {
  const std::string in = temp_path("gc_batch_bad_unit");
  write_file(in, "torque_lbft,misalignment_deg,mu\n1e6,0.1,0.1\n");
  const ProcessResult unit = run_gearcoupling({"batch", "--in", in});
  EXPECT_EQ(unit.exit_code, 2);
  EXPECT_NE(unit.err.find("input header: unknown unit 'lbft' in column 'torque_lbft' (accepted, in "
                          "any case: torque_nm, torque_knm, torque_mnm)"),
            std::string::npos) << unit.err;
  write_file(in, "torque_nm,torque_knm,misalignment_deg,mu\n1e6,1e3,0.1,0.1\n");
  const ProcessResult twice = run_gearcoupling({"batch", "--in", in});
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_NE(twice.err.find("input header: column 'torque_knm' repeats 'torque_nm'"), std::string::npos)
      << twice.err;
}

TEST(CliBatch, NegativeTorqueSaysTheModelTakesItsMagnitude) {
  const std::string in = temp_path("gc_batch_negative");
  write_file(in, "torque_knm,misalignment_deg,mu\n-1500,0.2,0.1\n");
  const ProcessResult run = run_gearcoupling({"batch", "--in", in});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("line 2: torque_knm -1500: operating_point.torque_nm = -1500000 is out of "
                         "range: allowed (0, 1e12] N·m; the model takes the torque as a magnitude "
                         "(T > 0): for a dyno that logs the drive torque negative, write the "
                         "torque_knm column's magnitude"),
            std::string::npos) << run.err;
}

TEST(CliMoments, NegativeTorqueFlagSaysTheModelTakesItsMagnitude) {
  const ProcessResult run = run_gearcoupling(
      {"moments", "--torque-nm", "-1.5e6", "--misalignment-deg", "0.3", "--mu", "0.1"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--torque-nm -1.5e6: operating_point.torque_nm = -1500000 is out of range: "
                         "allowed (0, 1e12] N·m; the model takes the torque as a magnitude (T > 0): "
                         "for a dyno that logs the drive torque negative, give --torque-nm its "
                         "magnitude"),
            std::string::npos) << run.err;
}

TEST(CliBatch, RefusesToOverwriteItsInput) {
  const std::string in = temp_path("gc_batch_same");
  const std::string cases = "torque_nm,misalignment_deg,direction_deg,mu\n1e6,0.1,0,0.1\n";
  write_file(in, cases);
  const ProcessResult run = run_gearcoupling({"batch", "--in", in, "--out", in});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("is the input file"), std::string::npos) << run.err;
  EXPECT_EQ(read_file(in), cases);
}

TEST(CliBatch, OneAndTwoThreadsWriteIdenticalOutputInInputOrder) {
  // 20 000 rows: several chunks of 4096 lines per thread, and bad rows in several of them.
  const std::string in = temp_path("gc_batch_threads");
  write_file(in, generated_cases(20000));
  const ProcessResult one = run_gearcoupling({"batch", "--in", in, "-j1"});
  const ProcessResult two = run_gearcoupling({"batch", "--in", in, "-j", "2"});
  const ProcessResult three = run_gearcoupling({"batch", "--in", in, "--jobs", "3"});
  EXPECT_EQ(one.exit_code, 1);
  EXPECT_EQ(two.exit_code, 1);
  EXPECT_EQ(one.out, two.out);
  EXPECT_EQ(one.err, two.err);
  EXPECT_EQ(one.out, three.out);
  const std::vector<std::string> rows = lines_of(two.out);
  ASSERT_EQ(rows.size(), 20001u);
  for (std::size_t i = 1; i < rows.size(); i += 1999) {
    EXPECT_EQ(std::stol(rows[i]), static_cast<long>(i) + 1) << "row order";
  }
  EXPECT_EQ(lines_of(two.err).size(), 21u + 1u);  // 21 bad rows (i % 997 == 5) and the summary
  EXPECT_NE(two.err.find("21 of 20000 rows failed"), std::string::npos);
}

TEST(CliBatch, MemoryDoesNotGrowWithTheNumberOfRows) {
#ifdef GC_SANITIZED_BUILD
  GTEST_SKIP() << "sanitizer runtimes keep freed memory in quarantine";
#endif
  const std::string small = temp_path("gc_batch_2k");
  const std::string large = temp_path("gc_batch_200k");
  write_file(small, generated_cases(2000));
  write_file(large, generated_cases(200000));
  const ProcessResult small_run = run_gearcoupling({"batch", "--in", small, "--out", "/dev/null"});
  const ProcessResult large_run = run_gearcoupling({"batch", "--in", large, "--out", "/dev/null"});
  EXPECT_EQ(large_run.exit_code, 1);  // the generated bad rows
  // Holding 200 000 rows of input or output would take over 40 MB; streaming keeps the peak
  // within a chunk's worth of the 2 000-row run.
  EXPECT_LT(large_run.max_rss_kb, small_run.max_rss_kb + 8 * 1024)
      << "2k rows: " << small_run.max_rss_kb << " KiB, 200k rows: " << large_run.max_rss_kb;
  EXPECT_LT(large_run.max_rss_kb, 64 * 1024);
}

}  // namespace
}  // namespace gc::cli::testing
