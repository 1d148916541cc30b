// Errors raised by the core when its inputs are not a physical coupling or operating point, or
// when an iteration does not converge. The core never aborts and never returns NaN: every
// entry point either returns finite numbers or throws one of these.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace gc {

/// Base of every error the core raises; edges (CLI, service) catch this one type.
class ModelError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An input outside its physical range. `field` names it as the user wrote it
/// (e.g. "operating_point.misalignment_rad"), `value` is what was given and `allowed` the range.
class InvalidInput : public ModelError {
 public:
  InvalidInput(std::string field, double value, std::string allowed);
  InvalidInput(std::string field, std::string message);

  const std::string& field() const noexcept { return field_; }

 private:
  std::string field_;
};

/// An iteration (eqs 20-22, eq 23's root) stopped before meeting its tolerance.
class NotConverged : public ModelError {
 public:
  using ModelError::ModelError;
};

/// The caller's cancellation predicate (LoadSharingOptions::cancelled) asked the core to stop:
/// not a property of the inputs, so the caller decides what to report (the service: its
/// per-calculation deadline or its shutdown).
class Cancelled : public ModelError {
 public:
  using ModelError::ModelError;
};

/// A number for an error message: 6 significant digits, no trailing zeros ("0.00064").
std::string format_number(double value);
/// A value as InvalidInput prints it: 10 significant digits, so what a user typed reads back as
/// typed and a range can be copied back exactly.
std::string format_precise(double value);

/// Throws InvalidInput unless `value` is finite and lo <= value <= hi (bounds inclusive).
void require_in_range(std::string_view field, double value, double lo, double hi);
/// Throws InvalidInput unless `value` is finite and strictly positive.
void require_positive(std::string_view field, double value);
/// Throws InvalidInput unless `value` is finite and not negative.
void require_non_negative(std::string_view field, double value);
/// Throws InvalidInput unless `value` is finite.
void require_finite(std::string_view field, double value);

}  // namespace gc
