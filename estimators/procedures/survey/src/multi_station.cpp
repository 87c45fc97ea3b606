#include "plumb/survey/multi_station.hpp"

#include <cmath>

#include "plumb/core/attitude.hpp"

namespace plumb::survey {

AxialBiasEstimate estimate_axial_bias(const std::vector<Station>& stations, const ReferenceField& ref, double sd_b,
                                      double sd_dip) {
  AxialBiasEstimate out;
  if (!ref.total_b_uT || !ref.dip_deg) {
    out.reason = "needs the reference total field and dip";
    return out;
  }
  const double f = *ref.total_b_uT, dip = *ref.dip_deg * kDeg;
  const double wb = 1 / (sd_b * sd_b), wd = 1 / (sd_dip * sd_dip);
  double normal = 0, rhs = 0, sb = 0, sd = 0;
  struct Row {
    double hb, hd, rb, rd;
  };
  std::vector<Row> rows;
  for (const auto& s : stations) {
    if (!(std::isfinite(s.total_b_uT) && s.total_b_uT > 0 && std::isfinite(s.dip_deg))) continue;
    const double inc = s.inclination_deg * kDeg, az = s.magnetic_azimuth_deg * kDeg;
    const double bz = std::cos(dip) * std::sin(inc) * std::cos(az) + std::sin(dip) * std::cos(inc);  // Bz / |B|
    const double hb = bz;
    const double hd = (std::cos(inc) / f - std::sin(dip) * bz / f) / std::cos(dip) / kDeg;  // deg per uT
    const double rb = s.total_b_uT - f, rd = s.dip_deg - *ref.dip_deg;
    normal += wb * hb * hb + wd * hd * hd;
    rhs += wb * hb * rb + wd * hd * rd;
    rows.push_back({hb, hd, rb, rd});
  }
  out.stations = rows.size();
  if (rows.empty()) {
    out.reason = "no station with a measured field";
    return out;
  }
  if (normal <= 0) {
    out.reason = "the stations' attitudes do not observe an axial bias";
    return out;
  }
  out.bias_uT = rhs / normal;
  out.sd_uT = 1 / std::sqrt(normal);
  double b0 = 0, b1 = 0, d0 = 0, d1 = 0;
  for (const auto& r : rows) {
    b0 += r.rb * r.rb, d0 += r.rd * r.rd;
    const double eb = r.rb - out.bias_uT * r.hb, ed = r.rd - out.bias_uT * r.hd;
    b1 += eb * eb, d1 += ed * ed;
  }
  const double n = static_cast<double>(rows.size());
  sb = std::sqrt(b0 / n), sd = std::sqrt(d0 / n);
  out.rms_b_before_uT = sb;
  out.rms_dip_before_deg = sd;
  out.rms_b_after_uT = std::sqrt(b1 / n);
  out.rms_dip_after_deg = std::sqrt(d1 / n);
  out.valid = true;
  return out;
}

double azimuth_without_axial_bias(double inclination_deg, double magnetic_azimuth_deg, double bias_uT,
                                  const ReferenceField& ref) {
  const double f = ref.total_b_uT.value_or(50), dip = ref.dip_deg.value_or(60) * kDeg, g = 9.80665;
  const double inc = inclination_deg * kDeg;
  // The azimuth the closed form returns as a function of the axial bias, at this attitude; the
  // measured azimuth is A(b), so the unbiased one is A_measured - (A(b) - A(0)) (exact to first order).
  const auto azimuth_with = [&](double a_rad, double b) {
    const Eigen::Vector3d G = gravity_tool(inc, 0, g);
    Eigen::Vector3d B = field_tool(inc, a_rad, 0, f, dip);
    B.z() += b;
    return closed_form_attitude(G, B).azimuth_deg;
  };
  const double a = magnetic_azimuth_deg * kDeg;
  const double shift = wrap_deg_180(azimuth_with(a, bias_uT) - azimuth_with(a, 0));
  return wrap_deg_360(magnetic_azimuth_deg - shift);
}

}  // namespace plumb::survey
