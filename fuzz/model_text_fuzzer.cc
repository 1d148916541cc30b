// libFuzzer target: a model configuration (protobuf text format, idl/model_config.proto)
// through codec::parse_model_text, as `validate --model` and `diagnose` read it: the coupling
// from the bundled catalogue or a coupling file beside it, the effects from the registry with
// their parameters. A model that loads then predicts a few samples, as validation does.
//
// Checks: loading throws nothing but InvalidInput naming a field; predictions are finite or
// InvalidInput / NotConverged.
//
// Harness limit: a coupling_file that is absolute or climbs out with ".." is not followed (the
// fuzzer would read whatever the machine holds, /dev/zero included); relative names resolve in
// data/couplings/, so the bundled files are reachable.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <google/protobuf/io/tokenizer.h>
#include <google/protobuf/text_format.h>

#include "codec/model_file.h"
#include "fuzz/fuzz_checks.h"
#include "fuzz/load_cases.h"
#include "idl/model_config.pb.h"

namespace {

// Reads the text as the codec will, quietly, to see where its coupling_file points; string
// concatenation and escapes ("." "./", "\\057") make any test on the raw text leaky.
class SilentErrors : public google::protobuf::io::ErrorCollector {
 public:
  void AddError(int, google::protobuf::io::ColumnNumber, const std::string&) override {}
};

bool names_a_file_outside_the_catalogue(std::string_view text) {
  gearcoupling::v1::ModelConfig config;
  google::protobuf::TextFormat::Parser parser;
  SilentErrors silent;
  parser.RecordErrorsTo(&silent);
  if (!parser.ParseFromString(std::string(text), &config) || !config.has_coupling_file()) {
    return false;
  }
  const std::filesystem::path file(config.coupling_file());
  if (file.is_absolute()) return true;
  for (const auto& part : file) {
    if (part == "..") return true;
  }
  return false;
}

void predict(const gc::CouplingModel& model, const gc::OperatingPoint& point, int direction) {
  gc::MeasurementSample sample;
  sample.time_s = 1.0;
  sample.torque_nm = point.torque_nm;
  sample.misalignment_rad = point.misalignment_rad;
  sample.direction_rad = point.direction_rad;
  sample.loading_direction = direction;
  sample.speed_rpm = 12.0;
  sample.temperature_c = 40.0;
  sample.rotation_phase_rad = 1.0;
  gc::fuzz::expect_result_or<gc::InvalidInput, gc::NotConverged>([&] {
    const gc::ModelPrediction prediction = model.predict(sample);
    gc::fuzz::check_finite("prediction.y_nm", prediction.moments.y_nm);
    gc::fuzz::check_finite("prediction.z_nm", prediction.moments.z_nm);
  });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (names_a_file_outside_the_catalogue(text)) return -1;  // not added to the corpus
  std::optional<gc::codec::ModelFile> file;
  gc::fuzz::expect_result_or<gc::InvalidInput>([&] {
    file.emplace(gc::codec::parse_model_text(text, "fuzz.textproto", GC_FUZZ_CATALOG_DIR,
                                             GC_FUZZ_CATALOG_DIR));
  });
  if (!file) return 0;
  gc::fuzz::check(file->model.geometry().jam_angle());
  int direction = -1;
  for (const gc::OperatingPoint& point : gc::fuzz::load_cases(file->model.geometry())) {
    predict(file->model, point, direction++);
  }
  return 0;
}
