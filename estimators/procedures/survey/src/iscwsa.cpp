#include "plumb/survey/iscwsa.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "iscwsa_gyro.hpp"
#include "iscwsa_weights.hpp"

namespace plumb::survey::iscwsa {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using detail::Vertical;
using detail::WeightContext;
constexpr double kRad = 3.14159265358979323846 / 180.0;

// A magnitude in the units its weighting function expects: angles in radians (a gyro's rates per
// hour; "deg/sqr(hr)" is the OWSG codes' spelling of a random walk's deg/sqrt(hr)).
double si_magnitude(const Term& t) {
  if (t.unit == "deg" || t.unit == "deg.nT" || t.unit == "deg/hr" || t.unit == "deg/sqrt(hr)" || t.unit == "deg/sqr(hr)")
    return t.magnitude * kRad;
  return t.magnitude;
}

// d(position)/d(MD, I, A) of the course ending at each station (k) and of the course leaving it
// (k + 1), SPE 67616 Appendix A; columns MD, I, A.
struct Derivatives {
  std::vector<Matrix3d> ending, leaving;
};

Vector3d direction(double inc, double azi) {
  return {std::sin(inc) * std::cos(azi), std::sin(inc) * std::sin(azi), std::cos(inc)};
}
Vector3d d_direction_d_inc(double inc, double azi) {
  return {std::cos(inc) * std::cos(azi), std::cos(inc) * std::sin(azi), -std::sin(inc)};
}
Vector3d d_direction_d_azi(double inc, double azi) { return {-std::sin(inc) * std::sin(azi), std::sin(inc) * std::cos(azi), 0}; }

struct Rad {
  double md, inc, azi, azm, tvd, t;
};

Derivatives derivatives(const std::vector<Rad>& s, int revision) {
  const std::size_t n = s.size();
  Derivatives d{std::vector<Matrix3d>(n, Matrix3d::Zero()), std::vector<Matrix3d>(n, Matrix3d::Zero())};
  for (std::size_t k = 1; k < n; ++k) {
    const double half = (s[k].md - s[k - 1].md) / 2;
    const Vector3d along = 0.5 * (direction(s[k - 1].inc, s[k - 1].azi) + direction(s[k].inc, s[k].azi));
    d.ending[k].col(0) = along;
    d.ending[k].col(1) = half * d_direction_d_inc(s[k].inc, s[k].azi);
    // Revision 5 counts the whole first course against the first station's inclination.
    if (revision >= 5 && k == 1) d.ending[k](0, 1) *= 2;
    d.ending[k].col(2) = half * d_direction_d_azi(s[k].inc, s[k].azi);
    d.leaving[k - 1].col(0) = -along;
    d.leaving[k - 1].col(1) = half * d_direction_d_inc(s[k - 1].inc, s[k - 1].azi);
    d.leaving[k - 1].col(2) = half * d_direction_d_azi(s[k - 1].inc, s[k - 1].azi);
  }
  return d;
}

// One term's position changes: through both courses of each station (full) and through the course
// ending at it only (the station's own, "star").
struct TermEffect {
  std::vector<Vector3d> full, star;
  std::vector<Vector3d> dia;  // the (MD, I, A) change itself
  std::vector<int> group{};   // stations sharing one draw (gyro terms); empty: as the propagation says
};

// A lone station (the tie-in, the first of a live survey) has no course yet: nothing to scale.
double course_coefficient(const std::vector<Rad>& s, std::size_t k) {
  if (s.size() < 2) return 1.0;
  const std::size_t c = std::max<std::size_t>(k, 1);
  const double course = s[c].md - s[c - 1].md;
  return std::max(1.0, std::sqrt(10.0 / course));
}

// Near vertical the azimuth-dependent terms take the model's vertical form: the error moves the
// station sideways by the course length around it. A station's own effect ("star") is the half
// course ending at it, whether or not a station follows: the newest station of a live survey has
// no course after it yet, and its covariance must not change when the next one comes (the around
// of the last station is never used: nothing lies below it).
void vertical_form(const std::vector<Rad>& s, std::size_t k, const detail::WeightFunction& wf, double mag,
                   const Field& field, int revision, TermEffect& e) {
  const std::size_t n = s.size();
  const bool last = k + 1 == n;
  const double own = (s[k].md - s[k - 1].md) / 2;
  const double around = last ? own : (s[k + 1].md - s[k - 1].md) / 2;
  // The first course counted whole against the first station (revision 5; and the XYM3E/XYM4E
  // course-length weighting, which only revision 5 has).
  const double first_own = 2 * own;
  const double first_around = last ? first_own : (s[2].md + s[1].md - 2 * s[0].md) / 2;
  if (wf.vertical == Vertical::AccelerometerXY) {
    const double g = mag / field.gravity_mps2;
    const Vector3d side(-std::sin(s[k].azi), std::cos(s[k].azi), 0);
    e.full[k] = around * g * side;
    e.star[k] = own * g * side;
    if (revision >= 5 && k == 1) {
      e.full[k](1) = first_around * g * std::cos(s[1].azi);
      e.star[k](1) = first_own * g * std::cos(s[1].azi);
    }
    return;
  }
  const int axis = wf.vertical == Vertical::MisalignmentNorth ? 0 : 1;
  e.full[k].setZero();
  e.star[k].setZero();
  if (wf.course_coefficient) {
    // The coefficient scales the station's error, so its own course as well as the one after it.
    const double c = course_coefficient(s, k);
    e.full[k](axis) = c * (k == 1 ? first_around : around) * mag;
    e.star[k](axis) = c * (k == 1 ? first_own : own) * mag;
  } else {
    e.full[k](axis) = around * mag;
    e.star[k](axis) = own * mag;
  }
}

// The vertical form at a surveyed first station: moved sideways by the half course below it.
void first_station_vertical_form(const std::vector<Rad>& s, const detail::WeightFunction& wf, double mag,
                                 const Field& field, TermEffect& e) {
  const double below = (s[1].md - s[0].md) / 2;
  if (wf.vertical == Vertical::AccelerometerXY) {
    e.full[0] = below * mag / field.gravity_mps2 * Vector3d(-std::sin(s[0].azi), std::cos(s[0].azi), 0);
    return;
  }
  const int axis = wf.vertical == Vertical::MisalignmentNorth ? 0 : 1;
  e.full[0].setZero();
  e.full[0](axis) = (wf.course_coefficient ? course_coefficient(s, 0) : 1.0) * below * mag;
}

TermEffect sensor_term(const std::vector<Rad>& s, const Derivatives& d, const Term& t, const Field& field,
                       const ToolCode& tool) {
  const int revision = tool.revision;
  const detail::WeightFunction wf = detail::weight_function(t.weight_function);
  const std::size_t n = s.size();
  const double mag = si_magnitude(t);
  const double limit = field.vertical_inc_limit_deg * kRad;
  TermEffect e{std::vector<Vector3d>(n, Vector3d::Zero()), std::vector<Vector3d>(n, Vector3d::Zero()),
               std::vector<Vector3d>(n, Vector3d::Zero())};
  for (std::size_t k = 0; k < n; ++k) {
    const bool vertical = s[k].inc < limit && wf.vertical != Vertical::Regular;
    if (!vertical) {
      WeightContext c{s[k].md, s[k].tvd, s[k].inc, s[k].azi, s[k].azm, field.gravity_mps2, field.total_b_nT,
                      field.dip_deg * kRad, k ? s[k].md - s[k - 1].md : 0.0, tool.xy_accelerometer_cant_deg * kRad};
      Vector3d w = wf.weight(c) * mag;
      if (wf.course_coefficient) w *= course_coefficient(s, k);
      for (int i = 0; i < 3; ++i)
        if (!std::isfinite(w(i))) w(i) = 0;
      e.dia[k] = w;
    }
    if (k == 0) {
      // A tie-in has no error of its own; a surveyed first station's direction error tilts the
      // half course below it (its position, depth included, is given).
      if (field.first_station_surveyed && n > 1) {
        if (vertical)
          first_station_vertical_form(s, wf, mag, field, e);
        else
          e.full[0] = d.leaving[0].rightCols<2>() * e.dia[0].tail<2>();
      }
      continue;
    }
    if (vertical) {
      vertical_form(s, k, wf, mag, field, revision, e);
    } else {
      e.full[k] = (d.ending[k] + d.leaving[k]) * e.dia[k];
      e.star[k] = d.ending[k] * e.dia[k];
    }
  }
  return e;
}

// A gyro term: its change of (MD, I, A) at each station through the same derivatives as the
// sensor terms, and the stations that share one draw of it. Its weights take the true azimuth; the
// derivatives the survey's frame.
detail::GyroEffect gyro_changes(const std::vector<Rad>& s, const Term& t, const ToolCode& tool, const Field& field) {
  std::vector<detail::GyroStation> g;
  const double to_true = field.true_azimuth_offset_deg * kRad;
  for (const Rad& r : s) g.push_back({r.md, r.inc, r.azi + to_true, r.t});
  return detail::gyro_term(g, t, si_magnitude(t), tool.gyro, field);
}

TermEffect gyro_effect(const std::vector<Rad>& s, const Derivatives& d, const Term& t, const ToolCode& tool,
                       const Field& field) {
  detail::GyroEffect ge = gyro_changes(s, t, tool, field);
  const std::size_t n = s.size();
  TermEffect e{std::vector<Vector3d>(n, Vector3d::Zero()), std::vector<Vector3d>(n, Vector3d::Zero()),
               std::move(ge.dia), std::move(ge.group)};
  for (std::size_t k = 1; k < n; ++k) {
    e.full[k] = (d.ending[k] + d.leaving[k]) * e.dia[k];
    e.star[k] = d.ending[k] * e.dia[k];
  }
  return e;
}

// XCLA (lateral) and XCLH (high side), revision 5: a course longer than the survey interval hides a
// curvature the minimum-curvature arc does not have; at least the tortuosity's.
TermEffect course_length_term(const std::vector<Rad>& s, const Term& t, const ToolCode& tool, const Field& field) {
  const std::size_t n = s.size();
  const bool lateral = t.code != "XCLH" && t.weight_function != "XCLH";
  const double limit = field.vertical_inc_limit_deg * kRad;
  TermEffect e{std::vector<Vector3d>(n, Vector3d::Zero()), std::vector<Vector3d>(n, Vector3d::Zero()),
               std::vector<Vector3d>(n, Vector3d::Zero())};
  for (std::size_t k = 1; k < n; ++k) {
    const double course = s[k].md - s[k - 1].md;
    const double floor = tool.tortuosity_rad_per_m * course;
    Vector3d v;
    if (lateral) {
      const double turn = std::remainder(s[k].azi - s[k - 1].azi, 2 * 3.14159265358979323846);
      const double seen = s[k - 1].inc < limit ? 0.0 : std::abs(std::sin(s[k].inc) * turn);
      v = course * std::max(seen, floor) * Vector3d(-std::sin(s[k].azi), std::cos(s[k].azi), 0);
    } else {
      const double seen = std::abs(s[k].inc - s[k - 1].inc);
      v = course * std::max(seen, floor) * d_direction_d_inc(s[k].inc, s[k].azi);
    }
    e.full[k] = e.star[k] = v * t.magnitude;
  }
  return e;
}

// Stations of one group share one draw of the term: their position changes add as vectors;
// groups are independent, their covariances add. A random term is one group per station, a
// systematic one a single group; a gyro term may join stations (a continuous run that keeps its
// initialisation's error). Groups are contiguous runs of stations.
std::vector<Matrix3d> covariances(const TermEffect& e, Propagation p) {
  const std::size_t n = e.full.size();
  std::vector<Matrix3d> out(n, Matrix3d::Zero());
  const auto group = [&](std::size_t k) {
    if (!e.group.empty()) return e.group[k];
    return p == Propagation::Random ? static_cast<int>(k) : 0;
  };
  Matrix3d closed = Matrix3d::Zero();  // the groups wholly above this station
  Vector3d open = Vector3d::Zero();    // the station's own group, from the stations above it
  int open_group = n ? group(0) : 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (group(k) != open_group) {
      closed += open * open.transpose();
      open.setZero();
      open_group = group(k);
    }
    const Vector3d v = open + e.star[k];
    out[k] = closed + v * v.transpose();
    open += e.full[k];
  }
  return out;
}

}  // namespace

bool known_weight_function(const std::string& name) {
  return detail::weight_function(name).weight != nullptr || detail::is_course_length_term(name, "") ||
         detail::gyro_kind(name) != detail::GyroKind::None;
}

bool needs_latitude(const ToolCode& tool) {
  for (const Term& t : tool.terms)
    if (detail::gyro_kind(t.weight_function) == detail::GyroKind::Stationary) return true;
  return false;
}

bool has_gyro_terms(const ToolCode& tool) {
  for (const Term& t : tool.terms)
    if (detail::gyro_kind(t.weight_function) != detail::GyroKind::None) return true;
  return false;
}

namespace {

// A term's effect on the stations of one leg, [first, end): the leg's own stations carry its
// changes, the others none (a gyro leg's run starts at its own first station).
TermEffect leg_effect(const std::vector<Rad>& s, const Derivatives& d, const Term& t, const ToolCode& tool,
                      const Field& field, std::size_t first, std::size_t end) {
  const std::size_t n = s.size();
  const bool xcl = detail::is_course_length_term(t.weight_function, t.code);
  const bool gyro = detail::gyro_kind(t.weight_function) != detail::GyroKind::None;
  if (!xcl && !gyro && !detail::weight_function(t.weight_function).weight)
    throw std::invalid_argument("ISCWSA model: term " + t.code + " has an unknown weighting function '" +
                                t.weight_function + "'");
  if (first >= end)  // a leg below the last station (a live survey's next): nothing yet
    return {std::vector<Vector3d>(n, Vector3d::Zero()), std::vector<Vector3d>(n, Vector3d::Zero()),
            std::vector<Vector3d>(n, Vector3d::Zero())};
  if (gyro && (first > 0 || end < n)) {
    // The leg's run, as if it were the whole well, placed among the well's stations; its groups
    // keep their labels (shifted past the well's), the stations outside it join the nearest.
    const std::vector<Rad> own(s.begin() + static_cast<std::ptrdiff_t>(first), s.begin() + static_cast<std::ptrdiff_t>(end));
    const detail::GyroEffect run = gyro_changes(own, t, tool, field);
    TermEffect e{std::vector<Vector3d>(n, Vector3d::Zero()), std::vector<Vector3d>(n, Vector3d::Zero()),
                 std::vector<Vector3d>(n, Vector3d::Zero()), std::vector<int>(n, 0)};
    const int shift = static_cast<int>(first);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t j = std::clamp(k, first, end - 1) - first;
      e.group[k] = run.group[j] + shift;
      if (k < first || k >= end) continue;
      e.dia[k] = run.dia[j];
      e.star[k] = d.ending[k] * e.dia[k];
      e.full[k] = (d.ending[k] + d.leaving[k]) * e.dia[k];
    }
    return e;
  }
  TermEffect e = xcl ? course_length_term(s, t, tool, field) : gyro ? gyro_effect(s, d, t, tool, field)
                                                                    : sensor_term(s, d, t, field, tool);
  for (std::size_t k = 0; k < n; ++k) {
    if (k >= first && k < end) continue;
    e.full[k].setZero();
    e.star[k].setZero();
    e.dia[k].setZero();
  }
  return e;
}

}  // namespace

void insert_leg(std::vector<Leg>& legs, Leg leg) {
  const auto at = std::lower_bound(legs.begin(), legs.end(), leg.from_md_m,
                                   [](const Leg& l, double md) { return l.from_md_m < md; });
  if (at != legs.end() && at->from_md_m == leg.from_md_m)
    *at = std::move(leg);
  else
    legs.insert(at, std::move(leg));
}

Result propagate(const std::vector<Station>& stations, const ToolCode& tool, const Field& field) {
  return propagate(stations, std::vector<Leg>{Leg{-std::numeric_limits<double>::infinity(), tool}}, field);
}

Result propagate(const std::vector<Station>& stations, const std::vector<Leg>& legs, const Field& field) {
  if (legs.empty()) throw std::invalid_argument("ISCWSA model: a survey program needs a leg");
  for (std::size_t l = 1; l < legs.size(); ++l)
    if (!(legs[l].from_md_m > legs[l - 1].from_md_m))
      throw std::invalid_argument("ISCWSA model: the survey program's legs must start at increasing depths");
  std::vector<Rad> s;
  for (const auto& st : stations) {
    if (!s.empty() && !(st.md_m > s.back().md))
      throw std::invalid_argument("ISCWSA model: measured depths must increase strictly");
    s.push_back({st.md_m, st.inclination_deg * kRad, st.azimuth_deg * kRad, st.magnetic_azimuth_deg * kRad, st.tvd_m,
                 st.t_s});
  }
  const std::size_t n = s.size();
  Result r;
  r.random.assign(n, Matrix3d::Zero());
  r.total.assign(n, Matrix3d::Zero());
  r.angle_variance.assign(n, Eigen::Vector2d::Zero());
  r.random_angle_variance.assign(n, Eigen::Vector2d::Zero());
  if (n == 0) return r;
  // Each leg's terms, one entry per draw: a per-well or global term met again in a later leg adds
  // to the entry of its first.
  struct Draw {
    std::string label, code;
    Propagation propagation;
    TermEffect effect;
  };
  std::vector<Draw> draws;
  const bool program = legs.size() > 1;
  const auto at_or_below = [&](double md) {
    return static_cast<std::size_t>(std::lower_bound(s.begin(), s.end(), md, [](const Rad& a, double m) { return a.md < m; }) -
                                    s.begin());
  };
  for (std::size_t l = 0; l < legs.size(); ++l) {
    const std::size_t first = l == 0 ? 0 : at_or_below(legs[l].from_md_m);
    const std::size_t end = l + 1 < legs.size() ? at_or_below(legs[l + 1].from_md_m) : n;
    const ToolCode& tool = legs[l].tool;
    const Derivatives d = derivatives(s, tool.revision);
    const std::string label = !program ? std::string() : (tool.name.empty() ? "leg " + std::to_string(l + 1) : tool.name) + ": ";
    for (const Term& t : tool.terms) {
      TermEffect e = leg_effect(s, d, t, tool, field, first, end);
      const bool shared = t.propagation == Propagation::WellByWell || t.propagation == Propagation::Global;
      const auto same = std::find_if(draws.begin(), draws.end(), [&](const Draw& x) {
        return shared && x.code == t.code && x.propagation == t.propagation && x.effect.group.empty() && e.group.empty();
      });
      if (same != draws.end()) {
        same->label = t.code;  // one draw of the whole well's
        for (std::size_t k = 0; k < n; ++k) {
          same->effect.full[k] += e.full[k];
          same->effect.star[k] += e.star[k];
          same->effect.dia[k] += e.dia[k];
        }
        continue;
      }
      draws.push_back({label + t.code, t.code, t.propagation, std::move(e)});
    }
  }
  for (const Draw& x : draws) {
    r.codes.push_back(x.label);
    r.per_term.push_back(covariances(x.effect, x.propagation));
    const bool random = x.propagation == Propagation::Random;
    for (std::size_t k = 0; k < n; ++k) {
      r.total[k] += r.per_term.back()[k];
      if (random) r.random[k] += r.per_term.back()[k];
      const Eigen::Vector2d angles(x.effect.dia[k](1) * x.effect.dia[k](1), x.effect.dia[k](2) * x.effect.dia[k](2));
      r.angle_variance[k] += angles;
      if (random) r.random_angle_variance[k] += angles;
    }
  }
  return r;
}

}  // namespace plumb::survey::iscwsa
