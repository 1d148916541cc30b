// Recordings (docs/recordings.md): every documented error with its line and column, units
// converted to SI, loading direction and rotation phase derived, and a bounded chunk size.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "analysis/format_error.h"
#include "analysis/recording_csv.h"
#include "core/loading_direction.h"
#include "core/model_error.h"
#include "diagnosis/synthesis/synthesize.h"
#include "run_process.h"

namespace gc::analysis {
namespace {

using cli::testing::temp_path;
using cli::testing::write_file;

const std::string kHeader = "time_s,torque_nm,misalignment_deg,direction_deg,msy_nm,msz_nm\n";

Recording read_text(const std::string& text) {
  const std::string path = temp_path("recording") + ".csv";
  write_file(path, text);
  return read_recording(path);
}

InvalidInput header_error(const std::string& header) {
  try {
    read_text(header + "\n0,1e6,0.1,0,1,2\n");
  } catch (const InvalidInput& error) {
    return error;
  }
  ADD_FAILURE() << "header accepted: " << header;
  return InvalidInput("none", "none");
}

TEST(RecordingReader, MissingRequiredColumnIsNamed) {
  const InvalidInput error = header_error("time_s,torque_nm,misalignment_deg,direction_deg,msy_nm");
  EXPECT_EQ(error.field(), "recording.msz");
  EXPECT_NE(std::string(error.what()).find("msz_knm"), std::string::npos) << error.what();
}

// A DAQ export carries dozens of channels: those of no known quantity are ignored, named, and
// never parsed (a text channel does not exclude the row).
TEST(RecordingReader, UnknownColumnsAreIgnoredAndListed) {
  const Recording recording = read_text(
      "Ch1,time_s,torque_nm,humidity_pct,misalignment_deg,direction_deg,msy_nm,msz_nm\n"
      "x,0.1,1e6,41,0.2,0,1,2\n"
      "y,0.2,1.1e6,n/a,0.2,0,3,4\n");
  EXPECT_EQ(recording.ignored_columns, (std::vector<std::string>{"Ch1", "humidity_pct"}));
  ASSERT_EQ(recording.samples.size(), 2u);
  EXPECT_EQ(recording.excluded_rows, 0u);
  EXPECT_EQ(recording.samples[1].input.torque_nm, 1.1e6);
  EXPECT_EQ(recording.samples[1].measured.z_nm, 4.0);
}

// msy_kNm, msy_Nm and msy_KNM are the listed units in another case: accepted, same scale.
TEST(RecordingReader, UnitsMatchInAnyCase) {
  const Recording recording = read_text(
      "time_S,torque_MNm,misalignment_DEG,direction_Rad,msy_kNm,msz_KNM,speed_RPM\n"
      "0.5,1.5,0.2,0.1,3,-4,12\n");
  ASSERT_EQ(recording.samples.size(), 1u);
  const RecordedSample& s = recording.samples[0];
  EXPECT_EQ(s.input.time_s, 0.5);
  EXPECT_EQ(s.input.torque_nm, 1.5e6);
  EXPECT_NEAR(s.input.misalignment_rad, 0.2 * std::numbers::pi / 180.0, 1e-15);
  EXPECT_EQ(s.input.direction_rad, 0.1);
  EXPECT_EQ(s.measured.y_nm, 3e3);
  EXPECT_EQ(s.measured.z_nm, -4e3);
  EXPECT_EQ(s.input.speed_rpm, 12.0);
}

// --columns msy_knm=Ch3_kNm: a DAQ's channel names read as the documented columns.
TEST(RecordingReader, RenamesReadTheFilesColumnsUnderDocumentedNames) {
  const std::string path = temp_path("renamed") + ".csv";
  write_file(path, "t,Torque,Mis,Dir,Ch3_kNm,Ch4_kNm,Ch5\n0.1,1e6,0.2,0,1.5,2.5,9\n");
  RecordingOptions options;
  options.renames = parse_column_renames(
      "time_s=t,torque_nm=Torque,misalignment_deg=Mis,direction_deg=Dir,msy_knm=Ch3_kNm,msz_knm=Ch4_kNm");
  const Recording recording = read_recording(path, options);
  ASSERT_EQ(recording.samples.size(), 1u);
  EXPECT_EQ(recording.samples[0].measured.y_nm, 1.5e3);
  EXPECT_EQ(recording.samples[0].measured.z_nm, 2.5e3);
  EXPECT_EQ(recording.ignored_columns, (std::vector<std::string>{"Ch5"}));
}

TEST(RecordingReader, RenameOfAColumnTheFileLacksIsNamed) {
  const std::string path = temp_path("renamed") + ".csv";
  write_file(path, kHeader + "0.1,1e6,0.2,0,1,2\n");
  RecordingOptions options;
  options.renames = parse_column_renames("msy_knm=Ch3_kNm");
  try {
    read_recording(path, options);
    FAIL() << "accepted";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.field(), "recording.columns");
    EXPECT_NE(std::string(error.what()).find("no column 'Ch3_kNm'"), std::string::npos) << error.what();
  }
}

TEST(RecordingReader, MalformedRenamesAreAFormatErrorNamingTheItem) {
  EXPECT_THROW(parse_column_renames("msy_knm"), FormatError);
  EXPECT_THROW(parse_column_renames("moment_knm=Ch3"), FormatError);
  EXPECT_THROW(parse_column_renames("msy_knm="), FormatError);
  try {
    parse_column_renames("msy_knm=Ch3,bogus=Ch4");
    FAIL();
  } catch (const FormatError& error) {
    EXPECT_NE(std::string(error.what()).find("'bogus=Ch4'"), std::string::npos) << error.what();
  }
}

// The same tokenizer as batch input (analysis/csv_fields.h): a byte-order mark, CRLF, blank
// lines and quoted numbers read as in a plain file, and line numbers count the blank lines.
TEST(RecordingReader, ByteOrderMarkCrlfBlankLinesAndQuotedNumbersReadAsPlain) {
  const Recording plain = read_text(kHeader + "0.1,1e6,0.2,0,1,2\n0.2,1e6,0.2,0,3,4\n");
  const Recording spreadsheet = read_text(
      "\xEF\xBB\xBF" + kHeader.substr(0, kHeader.size() - 1) + "\r\n\r\n"
      "\"0.1\",1e6,0.2,0,1,2\r\n  \r\n0.2,\"1e6\",0.2,0,3,4\r\n\r\n");
  ASSERT_EQ(spreadsheet.samples.size(), plain.samples.size());
  EXPECT_EQ(spreadsheet.excluded_rows, 0u);
  EXPECT_EQ(spreadsheet.samples[1].measured.z_nm, plain.samples[1].measured.z_nm);
  const Recording comma = read_text("\n" + kHeader + "\n0.1,1e6,\"0,2\",0,1,2\n");
  ASSERT_EQ(comma.problems.size(), 1u);
  EXPECT_EQ(comma.problems[0].line, 4);  // a blank line before the header, one after it
  EXPECT_EQ(comma.problems[0].column, 3);
  EXPECT_NE(comma.problems[0].message.find("not a number '0,2'"), std::string::npos) << comma.problems[0].message;
}

TEST(RecordingReader, UnknownUnitIsNamedWithTheAcceptedSpellings) {
  const InvalidInput error = header_error("time_s,torque_lbft,misalignment_deg,direction_deg,msy_nm,msz_nm");
  EXPECT_EQ(error.field(), "recording.torque_lbft");
  EXPECT_NE(std::string(error.what()).find(":1:2:"), std::string::npos);
  EXPECT_NE(std::string(error.what()).find("torque_knm"), std::string::npos) << error.what();
}

TEST(RecordingReader, RepeatedQuantityIsAnError) {
  EXPECT_EQ(header_error("time_s,torque_nm,torque_knm,misalignment_deg,direction_deg,msy_nm,msz_nm").field(),
            "recording.torque_knm");
}

// Each malformed row is excluded and reported with its line (header = 1) and column.
struct BadRow {
  std::string row;
  int column;
  std::string words;
};

class BadRows : public ::testing::TestWithParam<BadRow> {};

TEST_P(BadRows, AreExcludedAndReportedWithLineAndColumn) {
  const BadRow& bad = GetParam();
  const Recording recording =
      read_text(kHeader + "0,1e6,0.1,0,1,2\n" + bad.row + "\n0.2,1e6,0.1,0,1,2\n");
  EXPECT_EQ(recording.rows_read, 3u);
  EXPECT_EQ(recording.samples.size(), 2u);
  ASSERT_EQ(recording.excluded_rows, 1u);
  ASSERT_EQ(recording.problems.size(), 1u);
  EXPECT_EQ(recording.problems[0].line, 3);
  EXPECT_EQ(recording.problems[0].column, bad.column);
  EXPECT_NE(recording.problems[0].message.find(bad.words), std::string::npos)
      << recording.problems[0].message;
}

INSTANTIATE_TEST_SUITE_P(
    EveryKind, BadRows,
    ::testing::Values(BadRow{"0.1,1e6,,0,1,2", 3, "empty cell"},
                      BadRow{"0.1,1e6,0.1,0,nan,2", 5, "not a finite number"},
                      BadRow{"0.1,1e6,0.1,0,1,inf", 6, "not a finite number"},
                      BadRow{"0.1,1e6,0.1,north,1,2", 4, "not a number 'north'"},
                      BadRow{"0.1,1e6,0.1,0,1", 0, "5 fields, the header has 6"},
                      BadRow{"-0.5,1e6,0.1,0,1,2", 1, "time goes backwards"}));

// Found by fuzz/recording_csv_fuzzer's checks: a finite cell whose unit takes it past the
// largest double came through as an infinite torque, and a speed of 1e308 rpm (or a time of
// 1e300 s) as an infinite rotation phase. Each is now an excluded row naming its column.
TEST(RecordingReader, ValuesInfiniteInSiOrBeyondThePhaseLimitsAreExcludedAndReported) {
  const Recording recording = read_text(
      "time_s,torque_knm,misalignment_deg,direction_deg,msy_nm,msz_nm,speed_rpm\n"
      "0,1e3,0.1,0,1,2,12\n"
      "0.1,1e308,0.1,0,1,2,12\n"      // 1e311 N·m
      "0.2,1e3,0.1,0,1,2,1e308\n"     // speed over 1e5 rpm
      "1e300,1e3,0.1,0,1,2,12\n"      // time over 1e9 s
      "0.3,1e3,0.1,0,1,2,-1e5\n");    // the limits themselves are allowed
  ASSERT_EQ(recording.samples.size(), 2u);
  ASSERT_EQ(recording.excluded_rows, 3u);
  EXPECT_EQ(recording.problems[0].column, 2);
  EXPECT_NE(recording.problems[0].message.find("'1e308' is not a finite number in N·m"),
            std::string::npos) << recording.problems[0].message;
  EXPECT_EQ(recording.problems[1].column, 7);
  EXPECT_NE(recording.problems[1].message.find("allowed [-100000, 100000] rpm"),
            std::string::npos) << recording.problems[1].message;
  EXPECT_EQ(recording.problems[2].column, 1);
  EXPECT_NE(recording.problems[2].message.find("allowed [-1e+09, 1e+09] s"), std::string::npos)
      << recording.problems[2].message;
  // 0.3 s at the mean of 12 and -1e5 rpm: finite, and negative.
  ASSERT_TRUE(recording.samples[1].input.rotation_phase_rad.has_value());
  EXPECT_TRUE(std::isfinite(*recording.samples[1].input.rotation_phase_rad));
  EXPECT_LT(*recording.samples[1].input.rotation_phase_rad, 0.0);
}

TEST(RecordingReader, ConvertsDocumentedUnitsToSi) {
  const Recording recording = read_text(
      "time_ms,torque_mnm,misalignment_mrad,direction_deg,msy_knm,msz_mnm,speed_rad_s,"
      "temperature_k,applied_my_knm,applied_mz_nm,hub_motion_mm\n"
      "1500,1.2,2,90,-3,0.5,10,300,4,5,0.6\n");
  ASSERT_EQ(recording.samples.size(), 1u);
  const RecordedSample& s = recording.samples[0];
  EXPECT_DOUBLE_EQ(s.input.time_s, 1.5);
  EXPECT_DOUBLE_EQ(s.input.torque_nm, 1.2e6);
  EXPECT_DOUBLE_EQ(s.input.misalignment_rad, 2e-3);
  EXPECT_DOUBLE_EQ(s.input.direction_rad, std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(s.measured.y_nm, -3e3);
  EXPECT_DOUBLE_EQ(s.measured.z_nm, 0.5e6);
  EXPECT_NEAR(*s.input.speed_rpm, 10 * 60 / (2 * std::numbers::pi), 1e-12);
  EXPECT_NEAR(*s.input.temperature_c, 26.85, 1e-9);
  EXPECT_DOUBLE_EQ(*s.input.applied_moment_y_nm, 4e3);
  EXPECT_DOUBLE_EQ(*s.input.applied_moment_z_nm, 5.0);
  EXPECT_DOUBLE_EQ(*s.hub_motion_m, 0.6e-3);
}

TEST(RecordingReader, DerivesLoadingDirectionFromTheAmplitude) {
  // Up 0.1 deg per sample, then down, then still for over still_after_s (0.5 s).
  const Recording recording = read_text(kHeader +
      "0,1e6,0.0,0,1,2\n0.1,1e6,0.1,0,1,2\n0.2,1e6,0.2,0,1,2\n"
      "0.3,1e6,0.1,0,1,2\n0.4,1e6,0.0,0,1,2\n"
      "0.5,1e6,0.0,0,1,2\n1.5,1e6,0.0,0,1,2\n");
  std::vector<int> directions;
  for (const auto& s : recording.samples) directions.push_back(s.input.loading_direction);
  EXPECT_EQ(directions, (std::vector<int>{0, 1, 1, -1, -1, -1, 0}));
}

TEST(RecordingReader, DeadBandFollowsTheWholeRecordingsMisalignmentNoise) {
  // 3,000 rows every 0.05 s (three chunks of 1,000): a hold at 0.1 deg for 50 s, a ramp to
  // 0.5 deg in 5 s (1.4 mrad/s), a hold for 95 s; 6e-5 rad of noise; and one bad row, still
  // reported, whose row does not enter the noise.
  std::string text = kHeader;
  for (int i = 0; i < 3000; ++i) {
    const double ramp = std::clamp((i - 1000) / 100.0, 0.0, 1.0);
    const double noise_deg = 6e-5 * 180 / std::numbers::pi * standard_normal(7, i, 0);
    text += i == 1500 ? "75,1e6,,0,1,2\n"
                      : fmt::format("{},1e6,{},0,1,2\n", i * 0.05, 0.1 + 0.4 * ramp + noise_deg);
  }
  const std::string path = temp_path("noisy") + ".csv";
  write_file(path, text);
  RecordingReader reader(path);
  std::vector<RecordedSample> chunk;
  std::vector<MeasurementSample> streamed;
  while (reader.next_chunk(chunk, 1000)) {
    for (const RecordedSample& s : chunk) streamed.push_back(s.input);
  }
  ASSERT_EQ(reader.excluded_rows(), 1u);
  EXPECT_EQ(reader.problems()[0].line, 1502);
  EXPECT_EQ(reader.problems()[0].column, 3);
  ASSERT_EQ(streamed.size(), 2999u);
  // The band is 6 sigma of the whole recording's noise, known before the first chunk.
  EXPECT_NEAR(reader.loading_dead_band_rad(), 6.0 * 6e-5, 0.1 * 6.0 * 6e-5);
  // The labels are those of the whole-recording core function over the kept rows.
  std::vector<MeasurementSample> whole = streamed;
  derive_loading_directions(whole);
  int holds = 0, still = 0, ramp = 0, rising = 0;
  for (std::size_t i = 0; i < whole.size(); ++i) {
    EXPECT_EQ(streamed[i].loading_direction, whole[i].loading_direction) << i;
    const double t = streamed[i].time_s;
    const bool in_hold = t < 50.0 || t >= 55.0;
    (in_hold ? holds : ramp) += 1;
    if (in_hold && streamed[i].loading_direction == 0) ++still;
    if (!in_hold && streamed[i].loading_direction == 1) ++rising;
  }
  EXPECT_GT(still, 0.9 * holds);  // measured: 2,889 of 2,899
  EXPECT_GT(rising, 0.9 * ramp);   // measured: 94 of 100
}

TEST(RecordingReader, IntegratesTheRotationPhaseFromTheSpeedColumn) {
  // 30 rpm = pi rad/s for 1 s, then 90 rpm = 3 pi rad/s from t = 2 s: trapezoids of
  // pi, (pi + 3 pi) / 2 = 2 pi, 3 pi; given in rad/s to check the unit too.
  const Recording recording = read_text(
      "time_s,torque_nm,misalignment_deg,direction_deg,msy_nm,msz_nm,speed_rad_s\n"
      "0,1e6,0.1,0,1,2,3.141592653589793\n1,1e6,0.1,0,1,2,3.141592653589793\n"
      "1.5,1e6,0.1,0,1,2,north\n"
      "2,1e6,0.1,0,1,2,9.42477796076938\n3,1e6,0.1,0,1,2,9.42477796076938\n");
  ASSERT_EQ(recording.samples.size(), 4u);
  EXPECT_EQ(recording.excluded_rows, 1u);  // the bad speed cell is reported, then skipped
  const double expected[] = {0.0, 1.0, 3.0, 6.0};
  for (std::size_t i = 0; i < 4; ++i) {
    ASSERT_TRUE(recording.samples[i].input.rotation_phase_rad.has_value());
    EXPECT_NEAR(*recording.samples[i].input.rotation_phase_rad, expected[i] * std::numbers::pi,
                1e-12) << i;
  }
  EXPECT_FALSE(read_text(kHeader + "0,1e6,0.1,0,1,2\n").samples[0].input.rotation_phase_rad);
}

TEST(RecordingReader, KeepsAtMostTheRequestedChunk) {
  std::string text = kHeader;
  for (int i = 0; i < 2500; ++i) text += std::to_string(i) + ",1e6,0.1,0,1,2\n";
  const std::string path = temp_path("chunks") + ".csv";
  write_file(path, text);
  RecordingReader reader(path);
  std::vector<RecordedSample> chunk;
  std::vector<std::size_t> sizes;
  while (reader.next_chunk(chunk, 1000)) sizes.push_back(chunk.size());
  EXPECT_EQ(sizes, (std::vector<std::size_t>{1000, 1000, 500}));
  EXPECT_EQ(reader.rows_read(), 2500u);
}

// Rows are parsed on several threads in batches of thousands; what is read (samples, their
// derived inputs, the excluded rows and their order) is the same as on one thread, with bad rows
// and a time going back on either side of a batch's end.
TEST(RecordingReader, ReadsTheSameOnOneAndOnSeveralThreads) {
  std::string text = kHeader;
  for (int i = 0; i < 20000; ++i) {
    const double time = i % 8191 == 0 && i > 0 ? i - 2.5 : i;  // goes back now and then
    text += i % 997 == 0 ? fmt::format("{},x,0.1,0,1,2\n", time)
                         : fmt::format("{},{},{},0,{},2\n", time, 1e6 + i, 0.1 + 1e-3 * (i % 50), i);
  }
  const std::string path = temp_path("threads") + ".csv";
  write_file(path, text);
  auto read = [&](unsigned threads) {
    RecordingOptions options;
    options.threads = threads;
    RecordingReader reader(path, options);
    std::vector<RecordedSample> all, chunk;
    while (reader.next_chunk(chunk, 5000)) all.insert(all.end(), chunk.begin(), chunk.end());
    return std::tuple{all, reader.problems(), reader.rows_read(), reader.loading_dead_band_rad()};
  };
  const auto [one, one_problems, one_rows, one_band] = read(1);
  const auto [three, three_problems, three_rows, three_band] = read(3);
  EXPECT_EQ(one_rows, 20000u);
  EXPECT_EQ(three_rows, one_rows);
  EXPECT_EQ(three_band, one_band);
  ASSERT_EQ(three.size(), one.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(three[i].input.time_s, one[i].input.time_s);
    EXPECT_EQ(three[i].input.torque_nm, one[i].input.torque_nm);
    EXPECT_EQ(three[i].input.misalignment_rad, one[i].input.misalignment_rad);
    EXPECT_EQ(three[i].input.loading_direction, one[i].input.loading_direction);
    EXPECT_EQ(three[i].input.torque_rate_nm_s, one[i].input.torque_rate_nm_s);
    EXPECT_EQ(three[i].measured.y_nm, one[i].measured.y_nm);
  }
  ASSERT_EQ(three_problems.size(), one_problems.size());
  EXPECT_GT(one_problems.size(), 20u);  // 21 bad torques, 2 times going back
  for (std::size_t i = 0; i < one_problems.size(); ++i) {
    EXPECT_EQ(three_problems[i].line, one_problems[i].line);
    EXPECT_EQ(three_problems[i].message, one_problems[i].message);
  }
}

// Plain rows read in one walk (analysis/plain_csv_row.h), others and bad ones by the general
// tokenizer, on both passes: every row keeps its own values, every problem its line.
TEST(RecordingReader, PlainOtherAndBadRowsMixedKeepEachRowsValuesAndLines) {
  const Recording recording = read_text(kHeader +
                                        "0,1e6,0.1,0,1,2\n"
                                        "0.1,1e6,,0,1,2\n"                // empty misalignment
                                        "\"0.2\", 1e6 ,+0.2,0,1,2\n"      // good, not plain
                                        "0.15,1e6,0.3,0,1,2\n"            // time goes backwards
                                        "0.3,1e6,0.4,0,x,2\n"             // msy not a number
                                        "0.3,1e6,0.4,0,1\n"               // a field short
                                        "0.4,1e6,0.5,0,1,2\n");
  const double degree = std::numbers::pi / 180.0;
  ASSERT_EQ(recording.samples.size(), 3u);
  EXPECT_EQ(recording.excluded_rows, 4u);
  const std::vector<std::pair<double, double>> expected{{0.0, 0.1}, {0.2, 0.2}, {0.4, 0.5}};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(recording.samples[i].input.time_s, expected[i].first) << i;
    EXPECT_EQ(recording.samples[i].input.misalignment_rad, expected[i].second * degree) << i;
  }
  ASSERT_EQ(recording.problems.size(), 4u);
  const std::vector<long> lines{3, 5, 6, 7};
  for (std::size_t i = 0; i < lines.size(); ++i) EXPECT_EQ(recording.problems[i].line, lines[i]) << i;
}

TEST(RecordingReader, CountsEveryExcludedRowBeyondTheKeptProblems) {
  std::string text = kHeader;
  for (int i = 0; i < 1200; ++i) text += "x,1e6,0.1,0,1,2\n";
  const Recording recording = read_text(text);
  EXPECT_EQ(recording.excluded_rows, 1200u);
  EXPECT_EQ(recording.problems.size(), RecordingReader::kKeptProblems);
  EXPECT_TRUE(recording.samples.empty());
}

TEST(RecordingReader, WrittenRowsReadBackExactly) {
  RecordedSample sample;
  sample.input.time_s = 0.25;
  sample.input.torque_nm = 1.234567e6;
  sample.input.misalignment_rad = 0.00321;
  sample.input.direction_rad = -2.5;
  sample.measured = {-123456.789, 98765.4321};
  sample.input.temperature_c = 41.5;
  std::string text = recording_header(sample);
  append_recording_row(text, sample);
  const Recording recording = read_text(text);
  ASSERT_EQ(recording.samples.size(), 1u);
  const RecordedSample& back = recording.samples[0];
  EXPECT_EQ(back.input.torque_nm, sample.input.torque_nm);
  EXPECT_EQ(back.input.misalignment_rad, sample.input.misalignment_rad);
  EXPECT_EQ(back.measured.y_nm, sample.measured.y_nm);
  EXPECT_EQ(*back.input.temperature_c, 41.5);
  EXPECT_FALSE(back.input.speed_rpm);
}

}  // namespace
}  // namespace gc::analysis
