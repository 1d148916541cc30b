#include "analysis/validation_messages.h"

#include "codec/count_field.h"

#include <algorithm>

#include "diagnosis/validation/worst_regions.h"

namespace gc::codec {
namespace {

namespace v1 = gearcoupling::v1;

std::string_view unit_of(BinDimension dimension) {
  switch (dimension) {
    case BinDimension::torque: return "N·m";
    case BinDimension::misalignment:
    case BinDimension::direction: return "rad";
    case BinDimension::loading: return "-";
    case BinDimension::time: return "s";
  }
  return "";
}

v1::BinningRecord binning_message(const ErrorBinning& binning, double reference_torque_nm) {
  v1::BinningRecord record;
  record.set_dimension(std::string(to_string(binning.dimension())));
  record.set_unit(std::string(unit_of(binning.dimension())));
  for (const ErrorBin& bin : binning.bins()) {
    v1::ErrorBinRecord* out = record.add_bins();
    out->set_lower(bin.lower);
    out->set_upper(bin.upper);
    out->set_seen_min(bin.seen_min);
    out->set_seen_max(bin.seen_max);
    *out->mutable_errors() = to_message(bin.errors, reference_torque_nm);
  }
  return record;
}

v1::ErrorMapRecord map_message(const ErrorMap& map, double reference_torque_nm) {
  v1::ErrorMapRecord record;
  record.add_torque_edges_nm(map.torque.bins().front().lower);
  for (const ErrorBin& bin : map.torque.bins()) record.add_torque_edges_nm(bin.upper);
  record.add_misalignment_edges_rad(map.misalignment.bins().front().lower);
  for (const ErrorBin& bin : map.misalignment.bins()) record.add_misalignment_edges_rad(bin.upper);
  for (const ChannelErrors& cell : map.cells) {
    *record.add_cells() = to_message(cell, reference_torque_nm);
  }
  return record;
}

v1::RegionRecord region_message(const RegionError& region, double reference_torque_nm) {
  v1::RegionRecord record;
  record.set_channel(std::string(to_string(region.channel)));
  record.set_dimension(std::string(to_string(region.dimension)));
  record.set_bin(static_cast<std::uint32_t>(region.bin));
  record.set_contrast(region.contrast);
  record.set_region(describe_region(region));
  record.set_description(describe(region));
  *record.mutable_metrics() = to_message(region.metrics, reference_torque_nm);
  return record;
}

v1::ErrorSignatureRecord signature_message(const ErrorSignature& signature) {
  v1::ErrorSignatureRecord record;
  record.set_channel(std::string(to_string(signature.channel)));
  record.set_noise_estimate_nm(signature.noise_estimate_nm);
  record.set_systematic_rms_nm(signature.systematic_rms_nm);
  record.set_at_noise_level(signature.at_noise_level);
  for (std::size_t d = 0; d < kBinDimensions.size(); ++d) {
    auto* share = record.add_shares();
    share->set_dimension(std::string(to_string(kBinDimensions[d])));
    share->set_explained_share(signature.explained_share[d]);
  }
  return record;
}

}  // namespace

v1::ErrorMetricsRecord to_message(const ErrorMetrics& metrics, double reference_torque_nm) {
  v1::ErrorMetricsRecord record;
  const double percent = 100.0 / reference_torque_nm;
  record.set_count(count_field(metrics.count, "count"));
  record.set_rmse_nm(metrics.rmse_nm);
  record.set_bias_nm(metrics.bias_nm);
  record.set_error_std_nm(metrics.error_std_nm);
  record.set_max_abs_error_nm(metrics.max_abs_error_nm);
  if (metrics.r_squared) record.set_r_squared(*metrics.r_squared);
  record.set_rmse_pct(metrics.rmse_nm * percent);
  record.set_bias_pct(metrics.bias_nm * percent);
  record.set_max_abs_error_pct(metrics.max_abs_error_nm * percent);
  return record;
}

v1::ChannelErrorsRecord to_message(const ChannelErrors& errors, double reference_torque_nm) {
  v1::ChannelErrorsRecord record;
  *record.mutable_msy() = to_message(errors.y.metrics(), reference_torque_nm);
  *record.mutable_msz() = to_message(errors.z.metrics(), reference_torque_nm);
  return record;
}

v1::ModelValidation to_message(std::string_view model_name,
                               const ValidationAccumulator& validation) {
  const double reference = validation.options().reference_torque_nm;
  v1::ModelValidation record;
  record.set_model(std::string(model_name));
  record.set_compared_samples(count_field(validation.overall().count(), "compared_samples"));
  record.set_rejected_samples(count_field(validation.rejected_count(), "rejected_samples"));
  for (const auto& [field, rejection] : validation.rejections()) {
    v1::RejectionRecord* out = record.add_rejections();
    out->set_field(field);
    out->set_count(count_field(rejection.count, "rejections.count"));
    out->set_first_time_s(rejection.first_time_s);
    out->set_first_message(rejection.first_message);
  }
  *record.mutable_overall() = to_message(validation.overall(), reference);
  for (Channel channel : kChannels) {
    for (const RegionError& region : worst_regions(validation, channel)) {
      *record.add_worst_regions() = region_message(region, reference);
    }
  }
  for (const ErrorBinning& binning : validation.binnings()) {
    *record.add_binnings() = binning_message(binning, reference);
  }
  *record.mutable_error_map() = map_message(validation.map(), reference);
  for (Channel channel : kChannels) {
    *record.add_signatures() = signature_message(error_signature(validation, channel));
  }
  return record;
}

}  // namespace gc::codec

namespace gc::codec {

gearcoupling::v1::ValidationReport::ModelPoints to_message(
    std::string_view model_name, const std::vector<ComparedPoint>& points) {
  gearcoupling::v1::ValidationReport::ModelPoints record;
  record.set_model(std::string(model_name));
  for (const ComparedPoint& point : points) {
    gearcoupling::v1::PlotPoint* out = record.add_points();
    const MeasurementSample& input = point.recorded.input;
    out->set_time_s(input.time_s);
    out->set_torque_nm(input.torque_nm);
    out->set_misalignment_rad(input.misalignment_rad);
    out->set_direction_rad(input.direction_rad);
    out->set_loading_direction(input.loading_direction);
    out->set_msy_nm(point.recorded.measured.y_nm);
    out->set_msz_nm(point.recorded.measured.z_nm);
    if (point.predicted) {
      out->set_model_msy_nm(point.predicted->y_nm);
      out->set_model_msz_nm(point.predicted->z_nm);
    }
  }
  return record;
}

}  // namespace gc::codec
