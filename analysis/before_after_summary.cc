#include "analysis/before_after_summary.h"

#include <fmt/format.h>

#include "analysis/table.h"
#include "core/engineering_text.h"

namespace gc::analysis {
namespace {

namespace v1 = gearcoupling::v1;

std::string change(double before, double after) {
  return before > 0.0 ? fmt::format("{:+.0f} %", 100.0 * (after / before - 1.0)) : "-";
}

std::vector<std::string> cells(const std::string& region, const v1::ChannelErrorsRecord& before,
                               const v1::ChannelErrorsRecord& after) {
  return {region,
          fmt::format("{:.2f}", before.msy().rmse_nm() / 1e3), fmt::format("{:.2f}", after.msy().rmse_nm() / 1e3),
          change(before.msy().rmse_nm(), after.msy().rmse_nm()),
          fmt::format("{:.2f}", before.msz().rmse_nm() / 1e3), fmt::format("{:.2f}", after.msz().rmse_nm() / 1e3),
          change(before.msz().rmse_nm(), after.msz().rmse_nm())};
}

std::string bin_name(const v1::BinningRecord& binning, const v1::ErrorBinRecord& bin) {
  return binning.dimension() + " " + engineering_range(bin.lower(), bin.upper(), binning.unit());
}

void compare(const v1::ModelValidation& before, const v1::ModelValidation& after, std::FILE* out) {
  fmt::print(out, "\nBefore ({}) and after ({}), RMSE per channel and region:\n", before.model(), after.model());
  Table table({"region", "M_sy' before [kN·m]", "after", "change", "M_sz' before [kN·m]", "after", "change"});
  table.add_row(cells("all samples", before.overall(), after.overall()));
  for (int d = 0; d < before.binnings_size() && d < after.binnings_size(); ++d) {
    const v1::BinningRecord& b = before.binnings(d);
    const v1::BinningRecord& a = after.binnings(d);
    for (int k = 0; k < b.bins_size() && k < a.bins_size(); ++k) {
      if (b.bins(k).errors().msy().count() == 0) continue;
      table.add_row(cells(bin_name(b, b.bins(k)), b.bins(k).errors(), a.bins(k).errors()));
    }
  }
  table.print(out);
}

}  // namespace

void print_before_after(const v1::ValidationResult& result, std::FILE* out) {
  for (int m = 1; m < result.models_size(); ++m) compare(result.models(0), result.models(m), out);
}

}  // namespace gc::analysis
