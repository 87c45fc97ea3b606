// One attitude estimate as the estimators produce it (no DDS); components map it onto
// plumb::topics::Attitude and the Attitude CSV of docs/conventions.md.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace plumb {

// What a navigator (strapdown) adds to an attitude estimate: docs/conventions.md "Navigation".
struct NavigationState {
  std::array<double, 3> position_m{};       // north, east, down from the collar
  std::array<double, 3> velocity_mps{};     // vn, ve, vd
  std::array<double, 3> position_sd_m{};    // filter standard deviations (NaN on topics and in files when unknown)
  std::array<double, 3> velocity_sd_mps{};
  bool still = false;                       // a zero-velocity update is in progress
  std::uint32_t zero_velocity_updates = 0;  // still periods used so far
  std::string azimuth_reference = "magnetic";  // "magnetic", "true" or "relative" (to an initial azimuth)
};

struct Estimate {
  std::string estimator;            // plugin name
  double t_start = 0;               // s, first sample of the window
  double t_end = 0;                 // s, last sample of the window
  double inclination_deg = 0;
  double azimuth_deg = 0;
  double gravity_toolface_deg = 0;  // at t_end
  double magnetic_toolface_deg = 0; // at t_end
  double rpm = 0;
  double inclination_sd_deg = 0;    // 0 when not estimated
  double azimuth_sd_deg = 0;
  double toolface_sd_deg = 0;
  double dip_deg = 0;
  double total_g = 0;
  double total_b = 0;
  std::uint32_t samples_used = 0;
  bool valid = false;               // inclination usable
  bool azimuth_valid = false;
  bool toolface_valid = false;
  bool rotating = false;
  bool partial_window = false;
  std::string reason;               // why not valid (or a warning); empty when all is well
  std::optional<NavigationState> navigation;  // navigators only

  // Every numeric output finite; estimators guarantee this (tests check it).
  bool all_finite() const;
};

}  // namespace plumb
