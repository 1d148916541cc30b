#include "analysis/batch_csv.h"

#include <array>

#include <fmt/format.h>

#include "analysis/format_error.h"
#include "analysis/csv_fields.h"
#include "analysis/input_names.h"
#include "analysis/number_text.h"
#include "analysis/recording_csv.h"

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

// The load case's quantities, read as a recording reads them (analysis/recording_csv.h).
constexpr std::array<Quantity, 3> kLoadQuantities{Quantity::torque, Quantity::misalignment,
                                                  Quantity::direction};

BatchColumn* slot_of(Quantity quantity, BatchColumns& columns) {
  switch (quantity) {
    case Quantity::torque: return &columns.torque;
    case Quantity::misalignment: return &columns.misalignment;
    case Quantity::direction: return &columns.direction;
    default: return nullptr;
  }
}

std::string allowed_columns() {
  std::string text;
  for (Quantity quantity : kLoadQuantities) text += column_spellings(quantity) + "; ";
  return text + "mu; coupling";
}

}  // namespace

BatchColumns parse_batch_header(std::string_view header) {
  CsvFields names;
  if (auto problem = names.split(header)) throw FormatError("input header: " + *problem);
  BatchColumns columns;
  columns.count = static_cast<int>(names.size());
  for (int i = 0; i < columns.count; ++i) {
    const std::string_view name = names[i];
    BatchColumn* slot = nullptr;
    double to_si = 1.0;
    std::string_view unit;
    if (name == "mu") {
      slot = &columns.mu;
    } else if (name == "coupling") {
      slot = &columns.coupling;
    } else if (const std::optional<Quantity> quantity = column_quantity(name, unit)) {
      slot = slot_of(*quantity, columns);
      if (slot != nullptr) {
        const std::optional<UnitSpelling> spelling = find_unit_spelling(*quantity, unit);
        if (!spelling) {
          throw FormatError(fmt::format("input header: unknown unit '{}' in column '{}' "
                                        "(accepted, in any case: {})",
                                        unit, name, column_spellings(*quantity)));
        }
        to_si = spelling->scale;
      }
    }
    if (slot == nullptr) {
      throw FormatError(fmt::format("input header: unknown column '{}' (allowed: {})", name,
                                    allowed_columns()));
    }
    if (slot->index != -1) {
      throw FormatError(fmt::format("input header: column '{}' repeats '{}'", name, slot->name));
    }
    *slot = {i, std::string(name), to_si};
  }
  for (const auto& [column, name] :
       {std::pair{&columns.torque, column_spellings(Quantity::torque)},
        {&columns.misalignment, column_spellings(Quantity::misalignment)},
        {&columns.mu, std::string("mu")}}) {
    if (column->index == -1) {
      throw FormatError(fmt::format("input header: required column missing (one of: {})", name));
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
  if (columns.coupling.index != -1) row.coupling = row.fields[columns.coupling.index];
  if (row.coupling.empty()) return std::string("coupling is empty");
  double values[4] = {0.0, 0.0, 0.0, 0.0};
  const BatchColumn* numeric[4] = {&columns.torque, &columns.misalignment, &columns.direction,
                                   &columns.mu};
  for (int k = 0; k < 4; ++k) {
    if (numeric[k]->index == -1) continue;   // no direction column: 0
    const std::string_view cell = row.fields[numeric[k]->index];
    const auto value = parse_double(cell);
    if (!value) return fmt::format("{} '{}' is not a number", numeric[k]->name, cell);
    values[k] = *value * numeric[k]->to_si;
  }
  row.point = {.torque_nm = values[0],
               .misalignment_rad = values[1],
               .direction_rad = values[2],
               .friction_coefficient = values[3]};
  return std::nullopt;
}

std::string describe_row_error(const InvalidInput& error, const BatchColumns& columns,
                               const BatchRow& row) {
  const std::string_view field = error.field();
  const BatchColumn* column =
      field == "operating_point.torque_nm"              ? &columns.torque
      : field == "operating_point.misalignment_rad"     ? &columns.misalignment
      : field == "operating_point.direction_rad"        ? &columns.direction
      : field == "operating_point.friction_coefficient" ? &columns.mu
      : column_for_field(field) == "coupling"           ? &columns.coupling
                                                        : nullptr;
  if (column == nullptr) return describe_input_error(error, "", "");
  if (column->index < 0) return describe_input_error(error, "coupling", row.coupling);
  std::string text = describe_input_error(error, column->name,
                                          row.fields[static_cast<std::size_t>(column->index)]);
  if (column == &columns.torque && refuses_negative_torque(error)) {
    text += negative_torque_hint("for a dyno that logs the drive torque negative, write the " +
                                 column->name + " column's magnitude");
  }
  return text;
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
