// An estimate is only as good as the assumptions behind it.
// Every windowed plugin compares the window's |G|, |B| and dip with a reference (parameters, or
// learnt from the first window that looks like the Earth) and refuses, with the reason and
// standard deviations of 0 (unknown), what departs beyond the stated tolerance; and it clears the
// azimuth and toolface validity when their standard deviation exceeds a stated limit (near vertical).
#pragma once

#include <optional>
#include <vector>

#include "plumb/core/estimate.hpp"
#include "plumb/estimator/estimator.hpp"
#include "plumb/estimator/parameter_reader.hpp"

namespace plumb::windowed {

using estimator::ParameterReader;

// What a reference learnt from the data must look like: the Earth (gravity 9.78-9.83 m/s^2, the
// docs/conventions.md reference scenario's 10 included; total field 22-67 uT), with some margin.
inline constexpr double kEarthGravityMin = 9.7, kEarthGravityMax = 10.1;  // m/s^2
inline constexpr double kEarthFieldMin = 20, kEarthFieldMax = 70;         // uT

struct ReferenceOptions {
  std::optional<double> gravity;   // m/s^2; empty: learnt
  std::optional<double> field_uT;  // uT; empty: learnt
  std::optional<double> dip_deg;   // deg; empty: learnt
  double gravity_tol = 0.1;        // m/s^2
  double field_tol_uT = 1.5;
  double dip_tol_deg = 1.0;
  double max_sd_deg = 10;          // azimuth/toolface invalid above this standard deviation
};

// The parameters (names as the strapdown plugin's where they mean the same) and their defaults.
std::vector<estimator::ParameterSpec> reference_parameter_specs();
ReferenceOptions read_reference_options(const ParameterReader& reader, const estimator::Parameters& given);

class ReferenceCheck {
 public:
  void configure(const ReferenceOptions& options);
  void reset();  // forgets what was learnt
  // Checks one estimate (learning the reference from it when none is known yet) and marks it.
  void apply(Estimate& e);

 private:
  ReferenceOptions options_;
  std::optional<double> gravity_, field_, dip_;  // the references in use
};

}  // namespace plumb::windowed
