#include "iscwsa_gyro.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace plumb::survey::iscwsa::detail {
namespace {

constexpr double kRad = 3.14159265358979323846 / 180.0;
// The earth's rate, rad/h (7.292115e-5 rad/s): the gyrocompass measures its horizontal part.
constexpr double kEarthRateRadPerHour = 7.292115e-5 * 3600.0;

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// A gyrocompass's terms (SPE 90408 Tables 3 and 4): the change of azimuth at a station, per rad/h
// of the gyro error (divided by the horizontal earth rate Omega cos(lat)), per unit of scale
// factor, or per rad of misalignment. A gyrocompass reads the earth's rate on the x-y gyros; the
// high-side (h) and lateral (l) parts of the horizontal rate give A = atan2(-l cosI, h - Omega
// sinI sin(lat)), whose derivatives are B1 (an error on the high-side rate) and B2 (on the lateral
// rate); G1..G4 are the gyros' errors proportional to the gravity along the high side (g sinI) and
// the tool axis (g cosI): mass unbalance and its quadrature; RN is noise on both axes. A triad
// (GXYZ-) solves with its z gyro too and loses the 1/cosI.
struct Gyrocompass {
  double (*weight)(double inc, double azi, double lat);
  bool per_rate;  // divided by the horizontal earth rate
  bool noise;     // a random noise: an initialising gyrocompass's is the noise reduction factor's share
};

double sq(double x) { return x * x; }

const std::map<std::string, Gyrocompass>& gyrocompasses() {
  using std::cos, std::sin, std::sqrt, std::tan;
  static const std::map<std::string, Gyrocompass> table = {
      {"GXY-B1", {[](double i, double a, double) { return sin(a) / cos(i); }, true, false}},
      {"GXY-B2", {[](double, double a, double) { return cos(a); }, true, false}},
      {"GXY-RN", {[](double i, double a, double) { return sqrt(1 - sq(cos(a) * sin(i))) / cos(i); }, true, true}},
      {"GXY-G1", {[](double i, double a, double) { return cos(a) * sin(i); }, true, false}},
      {"GXY-G2", {[](double i, double a, double) { return cos(a) * cos(i); }, true, false}},
      {"GXY-G3", {[](double, double a, double) { return sin(a); }, true, false}},
      {"GXY-G4", {[](double i, double a, double) { return sin(a) * tan(i); }, true, false}},
      {"GXY-SF", {[](double i, double a, double lat) { return tan(lat) * sin(a) * tan(i); }, false, false}},
      {"GXY-MIS", {[](double i, double, double lat) { return 1 / (cos(lat) * cos(i)); }, false, false}},
      {"GXYZ-XYB1", {[](double i, double a, double) { return sin(a) * cos(i); }, true, false}},
      {"GXYZ-XYB2", {[](double, double a, double) { return cos(a); }, true, false}},
      {"GXYZ-XYRN", {[](double i, double a, double) { return sqrt(1 - sq(sin(a) * sin(i))); }, true, true}},
      {"GXYZ-XYG1", {[](double i, double a, double) { return cos(a) * sin(i); }, true, false}},
      {"GXYZ-XYG2", {[](double i, double a, double) { return cos(a) * cos(i); }, true, false}},
      {"GXYZ-XYG3", {[](double i, double a, double) { return sin(a) * sq(cos(i)); }, true, false}},
      {"GXYZ-XYG4", {[](double i, double a, double) { return sin(a) * sin(i) * cos(i); }, true, false}},
      {"GXYZ-ZB", {[](double i, double a, double) { return sin(a) * sin(i); }, true, false}},
      {"GXYZ-ZRN", {[](double i, double a, double) { return sin(a) * sin(i); }, true, true}},
      {"GXYZ-ZG1", {[](double i, double a, double) { return sin(a) * sq(sin(i)); }, true, false}},
      {"GXYZ-ZG2", {[](double i, double a, double) { return sin(a) * sin(i) * cos(i); }, true, false}},
      {"GXYZ-SF", {[](double i, double a, double lat) { return tan(lat) * sin(a) * sin(i) * cos(i); }, false, false}},
      {"GXYZ-MIS", {[](double, double, double lat) { return 1 / cos(lat); }, false, false}},
  };
  return table;
}

// How much of the azimuth rate the gyros that run continuously miss in a course of mean
// inclination `inc`: x-y gyros see the turn about the vertical through sinI, a z gyro through
// cosI, a triad whole.
double continuous_factor(const std::string& wf, double inc) {
  if (starts_with(wf, "GXYZ-")) return 1.0;
  if (starts_with(wf, "GXY-")) return 1.0 / std::sin(inc);
  return 1.0 / std::abs(std::cos(inc));  // GZ-
}

bool within(double inc, double from_deg, double to_deg) { return inc >= from_deg * kRad && inc <= to_deg * kRad; }

// The part of the course from inclination a to b that lies within [from, to] (inclination changing
// evenly along the course, as on a minimum-curvature arc in one plane), and its mean inclination.
struct CoursePart {
  double share = 0, mean_inc = 0;
};
CoursePart part_within(double a, double b, double from_deg, double to_deg) {
  if (a == b) return {within(b, from_deg, to_deg) ? 1.0 : 0.0, b};
  const double lo = std::max(std::min(a, b), from_deg * kRad), hi = std::min(std::max(a, b), to_deg * kRad);
  if (!(hi > lo)) return {};
  return {(hi - lo) / std::abs(b - a), (lo + hi) / 2};
}

// Hours between two stations: the course over the running speed, or the stations' own times.
double hours(const GyroStation& a, const GyroStation& b, std::size_t k, const GyroRunning& r) {
  if (r.running_speed_m_per_h > 0) return (b.md - a.md) / r.running_speed_m_per_h;
  // Two stations are never surveyed at once: equal times are times not given (a listed survey's 0).
  const double dt = b.t_s - a.t_s;
  if (!(dt > 0))
    throw std::invalid_argument("gyro model: the continuous terms time the drift by the stations' times, and station " +
                                std::to_string(k) + "'s does not follow station " + std::to_string(k - 1) +
                                "'s; give each station its time or the tool code a running speed");
  return dt / 3600.0;
}

}  // namespace

GyroKind gyro_kind(const std::string& wf) {
  if (gyrocompasses().count(wf)) return GyroKind::Stationary;
  if (wf == "GXY-GD" || wf == "GXYZ-GD" || wf == "GZ-GD") return GyroKind::Drift;
  if (wf == "GXY-GRW" || wf == "GXYZ-GRW" || wf == "GZ-GRW") return GyroKind::RandomWalk;
  if (wf == "EXT-REF" || wf == "EXT-TIE") return GyroKind::Reference;
  return GyroKind::None;
}

GyroEffect gyro_term(const std::vector<GyroStation>& s, const Term& term, double mag, const GyroRunning& r,
                     const Field& field) {
  const std::size_t n = s.size();
  const bool random = term.propagation == Propagation::Random;
  GyroEffect e{std::vector<Eigen::Vector3d>(n, Eigen::Vector3d::Zero()), std::vector<int>(n, 0)};
  for (std::size_t k = 0; k < n; ++k) e.group[k] = random ? static_cast<int>(k) : 0;
  // The continuous run starts at the first station in its inclination range and goes on to the
  // end (one initialisation); the stations before it are gyrocompassed where the static range
  // holds them. A gyrocompass initialises the run at the last static station before it, or at
  // the run's first station when there is none.
  std::size_t c0 = n;
  if (r.continuous)
    for (std::size_t k = 0; k < n && c0 == n; ++k)
      if (within(s[k].inc, r.continuous_start_inc_deg, r.continuous_end_inc_deg)) c0 = k;
  const auto stationary = [&](std::size_t k) {
    return k < c0 && within(s[k].inc, r.static_start_inc_deg, r.static_end_inc_deg);
  };
  const std::size_t i0 = c0 < n && c0 > 0 && stationary(c0 - 1) ? c0 - 1 : c0;
  const bool gyrocompass_init = r.initialisation == GyroInitialisation::Gyrocompass;
  const GyroKind kind = gyro_kind(term.weight_function);

  if (kind == GyroKind::Stationary) {
    if (!std::isfinite(field.latitude_deg))
      throw std::invalid_argument("gyro model: term " + term.code + " is a gyrocompass's and needs the well's latitude");
    const double lat = field.latitude_deg * kRad;
    const Gyrocompass& g = gyrocompasses().at(term.weight_function);
    const double per = g.per_rate ? 1 / (kEarthRateRadPerHour * std::cos(lat)) : 1.0;
    const auto weight = [&](double inc, double azi) {
      const double w = g.weight(inc, azi, lat) * per * mag;
      return std::isfinite(w) ? w : 0.0;  // horizontal: out of an x-y gyrocompass's range
    };
    for (std::size_t k = 0; k < c0; ++k)
      if (stationary(k)) e.dia[k](2) = weight(s[k].inc, s[k].azi);
    if (c0 < n && gyrocompass_init) {
      // The run keeps the azimuth error of the gyrocompass that initialised it: evaluated at the
      // initialisation's inclination (the code's, or the initialising station's) and the run's
      // first azimuth, held to the end. A noise term is that gyrocompass's own measurement, longer
      // than a station's (the noise reduction factor): one draw of its own for the whole run.
      const double inc = std::isfinite(r.initialisation_inc_deg) ? r.initialisation_inc_deg * kRad : s[i0].inc;
      const double held = weight(inc, s[c0].azi) * (g.noise ? r.noise_reduction_factor : 1.0);
      for (std::size_t k = c0; k < n; ++k) {
        e.dia[k](2) = held;
        if (random) e.group[k] = static_cast<int>(n);
      }
    }
    return e;
  }
  if (kind == GyroKind::Reference) {
    for (std::size_t k = c0; k < n; ++k) e.dia[k](2) = mag;
    return e;
  }
  // Drift and random walk: a bias b gives an azimuth error b t / sinI (x-y gyros) after t hours, a
  // random walk q gives q sqrt(t) / sinI; course by course, at the course's mean inclination, over
  // the courses ending in the gyro set's own range where it has one (from the first station), else
  // in the run's (whose first course ends at its first station, after the initialisation). The
  // run's stations carry what has grown.
  // A gyro set with its own range hands over to (or from) another within a course: each takes its
  // part of the course. The run's own range counts whole courses: its first one begins at the
  // initialisation, below the range.
  double from = r.continuous_start_inc_deg, to = r.continuous_end_inc_deg;
  bool own_range = false;
  if (starts_with(term.weight_function, "GZ-") && std::isfinite(r.z_drift_from_inc_deg))
    from = r.z_drift_from_inc_deg, to = r.z_drift_to_inc_deg, own_range = true;
  if (starts_with(term.weight_function, "GXY-") && std::isfinite(r.xy_drift_from_inc_deg))
    from = r.xy_drift_from_inc_deg, to = r.xy_drift_to_inc_deg, own_range = true;
  double accumulated = 0;
  for (std::size_t k = 1; k < n; ++k) {
    const double mean_inc = (s[k].inc + s[k - 1].inc) / 2;
    const CoursePart part = own_range ? part_within(s[k - 1].inc, s[k].inc, from, to)
                                      : CoursePart{within(s[k].inc, from, to) ? 1.0 : 0.0, mean_inc};
    const double f = continuous_factor(term.weight_function, part.mean_inc);
    const double t = r.continuous && part.share > 0 ? part.share * hours(s[k - 1], s[k], k, r) : 0.0;
    if (t > 0)
      accumulated = kind == GyroKind::Drift ? accumulated + t * f : std::sqrt(accumulated * accumulated + t * f * f);
    if (!std::isfinite(accumulated))
      throw std::invalid_argument("gyro model: term " + term.code + " runs x-y gyros (or a z gyro) continuously through a "
                                  "course they cannot see turn (vertical, or horizontal); start the continuous range "
                                  "where they can");
    if (k >= c0) e.dia[k](2) = accumulated * mag;
  }
  return e;
}

}  // namespace plumb::survey::iscwsa::detail
