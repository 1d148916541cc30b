#include "analysis/batch_csv.h"

#include <array>

#include <fmt/format.h>

#include "analysis/format_error.h"
#include "analysis/csv_fields.h"
#include "analysis/input_names.h"
#include "analysis/number_text.h"
#include "codec/angle_units.h"

namespace gc::analysis {
namespace {

// The output's result columns: one table gives both the header and the values.
struct ResultColumn {
  std::string_view name;
  double (*value)(const LoadCase&);
};

constexpr std::array<ResultColumn, 12> kResultColumns = {{
    {"q", [](const LoadCase& r) { return r.contact.load_sharing.q; }},
    {"teeth_in_contact",
     [](const LoadCase& r) { return static_cast<double>(r.contact.teeth_in_contact); }},
    {"max_tooth_load_n", [](const LoadCase& r) { return r.contact.max_tooth_load_n; }},
    {"moment_y_nm", [](const LoadCase& r) { return r.moments.moment_y_nm; }},
    {"moment_z_nm", [](const LoadCase& r) { return r.moments.moment_z_nm; }},
    {"sensor_moment_y_nm", [](const LoadCase& r) { return r.moments.sensor_moment_y_nm; }},
    {"sensor_moment_z_nm", [](const LoadCase& r) { return r.moments.sensor_moment_z_nm; }},
    {"magnitude_nm", [](const LoadCase& r) { return r.moments.magnitude_nm; }},
    {"contact_stress_pa", [](const LoadCase& r) { return r.contact.max_stress.contact_stress_pa; }},
    {"bending_stress_pa", [](const LoadCase& r) { return r.contact.max_stress.bending_stress_pa; }},
    {"contact_safety_factor",
     [](const LoadCase& r) { return r.contact.max_stress.contact_safety_factor; }},
    {"bending_safety_factor",
     [](const LoadCase& r) { return r.contact.max_stress.bending_safety_factor; }},
}};

void append_row_start(std::string& out, long line, std::string_view coupling) {
  append_number(out, line);
  out += ',';
  append_csv_field(out, coupling);
}

std::string_view column_name(int index, const BatchColumns& columns) {
  if (index == columns.torque) return "torque_nm";
  if (index == columns.misalignment) return "misalignment_deg";
  if (index == columns.direction) return "direction_deg";
  if (index == columns.mu) return "mu";
  return "coupling";
}

}  // namespace

BatchColumns parse_batch_header(std::string_view header) {
  CsvFields names;
  if (auto problem = names.split(header)) throw FormatError("input header: " + *problem);
  BatchColumns columns;
  columns.count = static_cast<int>(names.size());
  for (int i = 0; i < columns.count; ++i) {
    int* slot = names[i] == "torque_nm"          ? &columns.torque
                : names[i] == "misalignment_deg" ? &columns.misalignment
                : names[i] == "direction_deg"    ? &columns.direction
                : names[i] == "mu"               ? &columns.mu
                : names[i] == "coupling"         ? &columns.coupling
                                                 : nullptr;
    if (slot == nullptr) {
      throw FormatError(fmt::format(
          "input header: unknown column '{}' (allowed: torque_nm, misalignment_deg, "
          "direction_deg, mu, coupling)",
          names[i]));
    }
    if (*slot != -1) throw FormatError(fmt::format("input header: column '{}' twice", names[i]));
    *slot = i;
  }
  for (const auto& [slot, name] : {std::pair{columns.torque, "torque_nm"},
                                   {columns.misalignment, "misalignment_deg"},
                                   {columns.direction, "direction_deg"}, {columns.mu, "mu"}}) {
    if (slot == -1) {
      throw FormatError(fmt::format("input header: required column '{}' missing", name));
    }
  }
  return columns;
}

std::optional<std::string> parse_batch_row(std::string_view line, const BatchColumns& columns,
                                           std::string_view default_coupling, BatchRow& row) {
  row.coupling = default_coupling;
  if (auto problem = row.fields.split(line)) return problem;
  if (static_cast<int>(row.fields.size()) != columns.count) {
    return fmt::format("{} fields, the header has {}", row.fields.size(), columns.count);
  }
  if (columns.coupling != -1) row.coupling = row.fields[columns.coupling];
  if (row.coupling.empty()) return std::string("coupling is empty");
  double values[4];
  const int indices[4] = {columns.torque, columns.misalignment, columns.direction, columns.mu};
  for (int k = 0; k < 4; ++k) {
    const auto value = parse_double(row.fields[indices[k]]);
    if (!value) {
      return fmt::format("{} '{}' is not a number", column_name(indices[k], columns),
                         row.fields[indices[k]]);
    }
    values[k] = *value;
  }
  row.point = {.torque_nm = values[0],
               .misalignment_rad = codec::radians_from_degrees(values[1]),
               .direction_rad = codec::radians_from_degrees(values[2]),
               .friction_coefficient = values[3]};
  return std::nullopt;
}

std::string describe_row_error(const InvalidInput& error, const BatchColumns& columns,
                               const BatchRow& row) {
  const std::string_view column = column_for_field(error.field());
  if (column.empty()) return describe_input_error(error, "", "");
  const int index = column == "torque_nm"          ? columns.torque
                    : column == "misalignment_deg" ? columns.misalignment
                    : column == "direction_deg"    ? columns.direction
                    : column == "mu"               ? columns.mu
                                                   : columns.coupling;
  const std::string_view value =
      index >= 0 ? row.fields[static_cast<std::size_t>(index)] : row.coupling;
  return describe_input_error(error, column, value);
}

std::string batch_output_header() {
  std::string header = "line,coupling";
  for (const ResultColumn& column : kResultColumns) {
    header += ',';
    header += column.name;
  }
  return header + ",error\n";
}

void append_result_row(std::string& out, long line, std::string_view coupling,
                       const LoadCase& result) {
  append_row_start(out, line, coupling);
  for (const ResultColumn& column : kResultColumns) {
    out += ',';
    append_number(out, column.value(result));
  }
  out += ",\n";  // empty error field
}

void append_error_row(std::string& out, long line, std::string_view coupling,
                      std::string_view reason) {
  append_row_start(out, line, coupling);
  out.append(kResultColumns.size(), ',');
  out += ',';
  append_csv_field(out, reason);
  out += '\n';
}

}  // namespace gc::analysis
