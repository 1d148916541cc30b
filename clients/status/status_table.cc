#include "clients/status/status_table.h"

#include <fmt/format.h>

#include "analysis/table.h"
#include "codec/angle_units.h"
#include "protocol/names.h"

namespace gc::status {

using analysis::format_number;

void print_instances(const std::vector<InstanceView>& instances, std::FILE* out) {
  if (instances.empty()) {
    fmt::print(out, "no service instance seen\n");
    return;
  }
  analysis::Table table({"instance", "host:pid", "state", "accepting", "uptime [s]",
                         "calculation", "served", "refused", "failed", "p50 [ms]", "p99 [ms]"});
  for (const InstanceView& view : instances) {
    const client::InstanceInfo& info = view.info;
    std::vector<std::string> lead{protocol::hex_id(info.id), fmt::format("{}:{}", info.host, info.pid),
                                  std::string(to_string(view.liveness)),
                                  info.accepting ? "yes" : "no", fmt::format("{:.0f}", info.uptime_s)};
    if (info.calculations.empty()) {
      lead.insert(lead.end(), {"", "", "", "", "", ""});
      table.add_row(lead);
    }
    for (const client::CalculationStatus& c : info.calculations) {
      std::vector<std::string> row = lead;
      // A calculation never called has no service time: "-", not 0.
      row.insert(row.end(), {c.calculation, std::to_string(c.served), std::to_string(c.refused),
                             std::to_string(c.failed),
                             c.called() ? format_number(c.p50_service_time_s * 1e3) : "-",
                             c.called() ? format_number(c.p99_service_time_s * 1e3) : "-"});
      table.add_row(row);
      lead.assign(lead.size(), "");  // the instance's cells once, on its first row
    }
  }
  table.print(out);
  for (const InstanceView& view : instances) {
    std::string couplings;
    for (const client::CatalogueCoupling& c : view.info.couplings) {
      couplings += fmt::format("{}{} ({} teeth, jam angle {} deg)", couplings.empty() ? "" : ", ",
                               c.name, c.teeth, format_number(codec::degrees_from_radians(c.jam_angle_rad)));
    }
    fmt::print(out, "{} serves: {}\n", protocol::hex_id(view.info.id),
               couplings.empty() ? "(no catalogue)" : couplings);
  }
}

void print_cells(const std::vector<gearcoupling::v1::TestCellRecord>& cells, std::FILE* out) {
  if (cells.empty()) return;
  // Moments in kN·m, as on the dashboard and in the worst region's sentence.
  analysis::Table table({"test cell", "state", "model", "model health", "taken", "evaluated",
                         "lost", "refused", "RMSE M_sy' [kN·m]", "noise M_sy' [kN·m]",
                         "RMSE M_sz' [kN·m]", "noise M_sz' [kN·m]"});
  for (const auto& cell : cells) {
    const auto& c = cell.counts();
    const auto& model = cell.model();
    table.add_row({cell.test_cell(), cell.state(), model.model_name(), cell.model_health(),
                   std::to_string(c.taken()), std::to_string(c.evaluated()),
                   std::to_string(c.lost()),
                   std::to_string(c.refused_not_finite() + c.refused_by_model() +
                                  c.refused_out_of_order()),
                   format_number(model.msy().rmse_nm() / 1e3), format_number(model.msy().noise_nm() / 1e3),
                   format_number(model.msz().rmse_nm() / 1e3), format_number(model.msz().noise_nm() / 1e3)});
  }
  fmt::print(out, "\n");
  table.print(out);
  for (const auto& cell : cells) {
    if (!cell.unit_error().empty()) fmt::print(out, "{}: {}\n", cell.test_cell(), cell.unit_error());
    if (!cell.worst_region().empty()) fmt::print(out, "{}: {}\n", cell.test_cell(), cell.worst_region());
    // What the learning loop does and waits for (issue 39): never silent about a cell far off.
    if (!cell.learning().empty()) {
      fmt::print(out, "{}: learning: {}\n", cell.test_cell(), cell.learning());
    }
  }
}

}  // namespace gc::status
