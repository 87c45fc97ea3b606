// csv::check_units: a file declared in one unit and written in another gives answers that look
// fine and are wrong (|f| = 1 m/s² is a tool in free fall to an estimator), so say it up front.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "plumb/csv/import.hpp"

namespace plumb::csv {
namespace {

constexpr double kGravity = 9.80665;
// A drilling tool turns at a few hundred rpm at most; 50 rad/s is 480 rpm.
constexpr double kMaxToolRate = 50.0;

struct Candidate {
  const char* name;
  double scale;
};

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

std::string number(double v) {
  char text[32];
  const double a = std::abs(v);
  // 0.9999 g prints as "1.0", not "1"
  std::snprintf(text, sizeof text, a >= 99.5 ? "%.0f" : a >= 0.95 ? "%.1f" : "%.2g", v);
  return text;
}

// The file's own number (`raw`, in the declared unit) read in another unit lands inside
// [lo, hi]: that unit's name, else empty.
std::string fitting_unit(double raw, double declared_scale, const std::vector<Candidate>& units, double lo, double hi) {
  for (const auto& u : units) {
    if (u.scale == declared_scale) continue;
    const double v = raw * u.scale;
    if (v >= lo && v <= hi) return u.name;
  }
  return {};
}

}  // namespace

std::vector<std::string> check_units(const std::vector<Sample>& first_samples, const Import& declared) {
  std::vector<std::string> findings;
  // The first second (or the first few samples, for slow loggers): a tool is seldom moved then.
  std::vector<const Sample*> start;
  double t0 = NAN;
  for (const auto& s : first_samples) {
    if ((s.flags & flags::kNotFinite) || !std::isfinite(s.t)) continue;
    if (std::isnan(t0)) t0 = s.t;
    if (s.t - t0 > 1.0 && start.size() >= 5) break;
    start.push_back(&s);
  }
  if (start.size() < 3) return findings;

  std::vector<double> f, b, w;
  for (const Sample* s : start) {
    f.push_back(s->f.norm());
    if (!(s->flags & flags::kNoMagnetometer)) b.push_back(s->b.norm());
  }
  for (const auto& s : first_samples) {
    if ((s.flags & flags::kHasGyro) && !(s.flags & flags::kNotFinite)) w.push_back(s.w.norm());
  }

  const double fm = median(f);
  if (fm < 0.75 * kGravity || fm > 1.25 * kGravity) {
    const double raw = fm / declared.accel.scale;
    const std::string unit = fitting_unit(raw, declared.accel.scale, {{"m/s2", 1}, {"g", kGravity}, {"mg", kGravity / 1000}},
                                          0.75 * kGravity, 1.25 * kGravity);
    if (!unit.empty()) {
      findings.push_back("accelerometers look like they are in " + unit + " (|f| \xE2\x89\x88 " + number(raw) +
                         "); give --units accel=" + unit);
    } else if (fm < 0.5 * kGravity || fm > 2 * kGravity) {
      findings.push_back("accelerometers read |f| \xE2\x89\x88 " + number(raw) + " " + declared.accel.name +
                         " over the first second, far from gravity (9.81 m/s2 = 1 g); check --units accel and the "
                         "fx, fy, fz columns");
    }
  }

  if (b.size() >= 3) {
    const double bm = median(b);  // microtesla; the Earth's field is 22 to 67 uT
    if (bm < 15 || bm > 80) {
      const double raw = bm / declared.mag.scale;
      const std::string unit =
          fitting_unit(raw, declared.mag.scale, {{"uT", 1}, {"nT", 1e-3}, {"mT", 1e3}, {"gauss", 100}}, 20, 70);
      if (!unit.empty()) {
        findings.push_back("magnetometers look like they are in " + unit + " (|b| \xE2\x89\x88 " + number(raw) +
                           "); give --units mag=" + unit);
      } else if (bm < 5 || bm > 500) {
        findings.push_back("magnetometers read |b| \xE2\x89\x88 " + number(raw) + " " + declared.mag.name +
                           " over the first second, far from the Earth's field (about 50 uT = 0.5 gauss); check "
                           "--units mag and the bx, by, bz columns");
      }
    }
  }

  if (w.size() >= 3) {
    const double wm = median(w);  // over all samples given: a sustained rate, not one shock
    if (wm > kMaxToolRate) {
      const double raw = wm / declared.gyro.scale;
      const std::string unit =
          fitting_unit(raw, declared.gyro.scale, {{"deg/s", std::acos(-1.0) / 180}}, 0, kMaxToolRate);
      if (!unit.empty()) {
        findings.push_back("gyros look like they are in deg/s (|w| \xE2\x89\x88 " + number(raw) +
                           " sustained, absurd in rad/s); give --units gyro=deg/s");
      } else {
        findings.push_back("gyros read |w| \xE2\x89\x88 " + number(raw) + " " + declared.gyro.name +
                           " sustained, faster than a tool turns; check --units gyro and the wx, wy, wz columns");
      }
    }
  }
  return findings;
}

}  // namespace plumb::csv
