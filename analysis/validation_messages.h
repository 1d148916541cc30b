// Validation results (diagnosis/validation/) as gearcoupling.v1 messages (idl/validation.proto),
// for --json and for the HTML report's data.
#pragma once

#include <string_view>

#include "diagnosis/validation/error_bins.h"
#include "diagnosis/validation/plot_points.h"
#include "idl/validation.pb.h"

namespace gc::codec {

gearcoupling::v1::ErrorMetricsRecord to_message(const ErrorMetrics& metrics,
                                                double reference_torque_nm);
gearcoupling::v1::ChannelErrorsRecord to_message(const ChannelErrors& errors,
                                                 double reference_torque_nm);

/// One model's errors on a recording: overall, binned, mapped, worst regions, rejections.
gearcoupling::v1::ModelValidation to_message(std::string_view model_name,
                                             const ValidationAccumulator& validation);

}  // namespace gc::codec

namespace gc::codec {

/// The plotted subset of one model's comparison.
gearcoupling::v1::ValidationReport::ModelPoints to_message(std::string_view model_name,
                                                           const std::vector<ComparedPoint>& points);

}  // namespace gc::codec
