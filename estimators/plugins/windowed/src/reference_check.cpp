#include "plumb/windowed/reference_check.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace plumb::windowed {

namespace {

std::optional<double> optional_number(const ParameterReader& reader, const estimator::Parameters& given,
                                      const std::string& name, double min, double max) {
  const auto it = given.find(name);
  if (it == given.end() || it->second.empty()) return std::nullopt;
  return reader.number(name, min, max);
}

template <typename... Args>
void add_reason(Estimate& e, const char* fmt, Args... args) {
  char text[200];
  std::snprintf(text, sizeof text, fmt, args...);
  e.reason = e.reason.empty() ? std::string(text) : e.reason + "; " + text;
}

// What a magnitude far outside the Earth's says: most often an input in another unit than the one
// the estimators take (m/s^2, uT), where giving the reference would be the wrong remedy.
const char* gravity_advice(double g) {
  if (std::abs(g - 1) < 0.05) return "accelerometers in g? convert on input: --units accel=g";
  if (std::abs(g - 1000) < 50) return "accelerometers in mg? convert on input: --units accel=mg";
  return "give `gravity` if this is right";
}
const char* field_advice(double b) {
  if (b > 0.2 && b < 0.7) return "magnetometers in gauss? convert on input: --units mag=gauss";
  if (b > 0.02 && b < 0.07) return "magnetometers in mT? convert on input: --units mag=mT";
  if (b > 20000 && b < 70000) return "magnetometers in nT? convert on input: --units mag=nT";
  return "give `field_uT` if this is right";
}

// The data contradict the gravity assumption: nothing of this window can be trusted.
void refuse_all(Estimate& e) {
  e.valid = e.azimuth_valid = e.toolface_valid = false;
  e.inclination_sd_deg = e.azimuth_sd_deg = e.toolface_sd_deg = 0;
}

// The field is disturbed: the azimuth (from the field) cannot be trusted; gravity still can.
void refuse_azimuth(Estimate& e) {
  e.azimuth_valid = false;
  e.azimuth_sd_deg = 0;
}

}  // namespace

std::vector<estimator::ParameterSpec> reference_parameter_specs() {
  return {
      {"gravity", "", "local gravity (m/s^2); empty: learnt from the first window with 9.7-10.1 m/s^2"},
      {"field_uT", "", "reference total field (uT); empty: learnt from the first window with 20-70 uT"},
      {"dip_deg", "", "reference dip (deg, positive down); empty: learnt with the field"},
      {"gravity_tol", "0.1", "a window's |G| further than this from the reference is invalid (m/s^2)"},
      {"field_tol_uT", "1.5", "a window's |B| further than this from the reference invalidates its azimuth (uT)"},
      {"dip_tol_deg", "1", "a window's dip further than this from the reference invalidates its azimuth (deg)"},
      {"max_sd_deg", "10", "azimuth and toolface are flagged invalid when their standard deviation exceeds this (deg)"},
  };
}

ReferenceOptions read_reference_options(const ParameterReader& reader, const estimator::Parameters& given) {
  ReferenceOptions o;
  o.gravity = optional_number(reader, given, "gravity", 0.1, 100);
  o.field_uT = optional_number(reader, given, "field_uT", 0.01, 1000);
  o.dip_deg = optional_number(reader, given, "dip_deg", -90, 90);
  o.gravity_tol = reader.number("gravity_tol", 0, 100);
  o.field_tol_uT = reader.number("field_tol_uT", 0, 1000);
  o.dip_tol_deg = reader.number("dip_tol_deg", 0, 180);
  o.max_sd_deg = reader.number("max_sd_deg", 0, 180);
  return o;
}

void ReferenceCheck::configure(const ReferenceOptions& options) {
  options_ = options;
  reset();
}

void ReferenceCheck::reset() {
  gravity_ = options_.gravity;
  field_ = options_.field_uT;
  dip_ = options_.dip_deg;
}

void ReferenceCheck::apply(Estimate& e) {
  if (!e.valid) return;
  if (!gravity_) {
    if (e.total_g < kEarthGravityMin || e.total_g > kEarthGravityMax) {
      add_reason(e, "|G| %.4g m/s^2 outside the Earth's %.4g-%.4g (%s)", e.total_g, kEarthGravityMin, kEarthGravityMax,
                 gravity_advice(e.total_g));
      refuse_all(e);
      return;
    }
    gravity_ = e.total_g;
  } else if (std::abs(e.total_g - *gravity_) > options_.gravity_tol) {
    add_reason(e, "|G| %.4g m/s^2 departs from the reference %.4g by more than gravity_tol %.3g", e.total_g, *gravity_,
               options_.gravity_tol);
    refuse_all(e);
    return;
  }
  if (!field_) {
    if (e.total_b < kEarthFieldMin || e.total_b > kEarthFieldMax) {
      add_reason(e, "|B| %.4g uT outside the Earth's %.3g-%.3g (%s)", e.total_b, kEarthFieldMin, kEarthFieldMax,
                 field_advice(e.total_b));
      refuse_azimuth(e);
    } else {
      field_ = e.total_b;
      if (!dip_) dip_ = e.dip_deg;
    }
  } else if (std::abs(e.total_b - *field_) > options_.field_tol_uT) {
    add_reason(e, "|B| %.4g uT departs from the reference %.4g by more than field_tol_uT %.3g", e.total_b, *field_,
               options_.field_tol_uT);
    refuse_azimuth(e);
  }
  if (dip_ && std::abs(e.dip_deg - *dip_) > options_.dip_tol_deg) {
    add_reason(e, "dip %.3g deg departs from the reference %.3g by more than dip_tol_deg %.3g", e.dip_deg, *dip_,
               options_.dip_tol_deg);
    refuse_azimuth(e);
  }
  // Near vertical the azimuth and toolface are ill-conditioned: their sigma says by how much.
  if (e.azimuth_valid && e.azimuth_sd_deg > options_.max_sd_deg) {
    add_reason(e, "near vertical: azimuth sd %.3g deg above max_sd_deg %.3g", e.azimuth_sd_deg,
               options_.max_sd_deg);
    e.azimuth_valid = false;
  }
  if (e.toolface_valid && e.toolface_sd_deg > options_.max_sd_deg) {
    add_reason(e, "near vertical: toolface sd %.3g deg above max_sd_deg %.3g", e.toolface_sd_deg,
               options_.max_sd_deg);
    e.toolface_valid = false;
  }
}

}  // namespace plumb::windowed
