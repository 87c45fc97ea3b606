#include "survey/survey_plot.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <string>

#include "plumb/core/attitude.hpp"

namespace plumb::cli {
namespace {

constexpr double kPanel = 420, kMargin = 50, kWidth = 2 * kPanel + 3 * kMargin, kHeight = kPanel + 2 * kMargin + 30;

// Maps a data box onto a square panel with equal scales on both axes (a plan must not distort).
struct Frame {
  double x0, y0, scale, left, top;
  double x(double v) const { return left + (v - x0) * scale; }
  double y(double v) const { return top + (v - y0) * scale; }
};

Frame fit(double xmin, double xmax, double ymin, double ymax, double left) {
  const double span = std::max({xmax - xmin, ymax - ymin, 1e-3}) * 1.1;
  const double cx = (xmin + xmax) / 2, cy = (ymin + ymax) / 2;
  return {cx - span / 2, cy - span / 2, kPanel / span, left, kMargin + 30};
}

void panel(std::ostream& out, double left, const std::string& title, const std::string& xlabel, const std::string& ylabel) {
  out << "<rect x='" << left << "' y='" << kMargin + 30 << "' width='" << kPanel << "' height='" << kPanel
      << "' fill='none' stroke='#888'/>\n";
  out << "<text x='" << left << "' y='" << kMargin + 20 << "' font-size='14'>" << title << "</text>\n";
  out << "<text x='" << left + kPanel / 2 << "' y='" << kMargin + 30 + kPanel + 20 << "' font-size='12' text-anchor='middle'>"
      << xlabel << "</text>\n";
  out << "<text x='" << left - 8 << "' y='" << kMargin + 30 + kPanel / 2 << "' font-size='12' text-anchor='end'>" << ylabel
      << "</text>\n";
}

}  // namespace

void write_survey_svg(std::ostream& out, const survey::Survey& s) {
  const auto& rows = s.rows();
  out << std::fixed << std::setprecision(2);
  out << "<svg xmlns='http://www.w3.org/2000/svg' width='" << kWidth << "' height='" << kHeight << "'>\n";
  out << "<text x='" << kMargin << "' y='24' font-size='16'>plumb survey: " << rows.size() << " stations, azimuths "
      << survey::to_string(s.options().reference) << ", ellipses 95 % (" << survey::kEllipse95Factor
      << " sigma), red: QC failed</text>\n";
  if (rows.empty()) {
    out << "</svg>\n";
    return;
  }
  double nmin = 1e300, nmax = -1e300, emin = 1e300, emax = -1e300, vmin = 1e300, vmax = -1e300, tmin = 1e300, tmax = -1e300;
  for (const auto& r : rows) {
    const double grow = survey::kEllipse95Factor * r.uncertainty.major_sd_m;
    nmin = std::min(nmin, r.point.north_m - grow), nmax = std::max(nmax, r.point.north_m + grow);
    emin = std::min(emin, r.point.east_m - grow), emax = std::max(emax, r.point.east_m + grow);
    vmin = std::min(vmin, r.point.vertical_section_m), vmax = std::max(vmax, r.point.vertical_section_m);
    tmin = std::min(tmin, r.point.tvd_m), tmax = std::max(tmax, r.point.tvd_m);
  }
  // Plan: east to the right, north up (y grows down in SVG, so north is negated).
  const Frame plan = fit(emin, emax, -nmax, -nmin, kMargin);
  const Frame section = fit(vmin, vmax, tmin, tmax, 2 * kMargin + kPanel);
  panel(out, kMargin, "plan", "east (m)", "north (m)");
  panel(out, 2 * kMargin + kPanel, "vertical section at " + std::to_string(s.options().section_azimuth_deg) + " deg",
        "vertical section (m)", "TVD (m)");
  const auto path = [&](const Frame& f, auto x, auto y) {
    out << "<polyline fill='none' stroke='#1f5fa8' stroke-width='1.5' points='";
    for (const auto& r : rows) out << f.x(x(r)) << ',' << f.y(y(r)) << ' ';
    out << "'/>\n";
  };
  path(plan, [](const survey::SurveyRow& r) { return r.point.east_m; }, [](const survey::SurveyRow& r) { return -r.point.north_m; });
  path(section, [](const survey::SurveyRow& r) { return r.point.vertical_section_m; }, [](const survey::SurveyRow& r) { return r.point.tvd_m; });
  for (const auto& r : rows) {
    const std::string colour = r.qc.pass ? "#1f5fa8" : "#d62728";
    const auto& u = r.uncertainty;
    // The ellipse's major axis at azimuth a (from north, clockwise) is the SVG angle a - 90.
    if (u.major_sd_m > 0)
      out << "<ellipse cx='" << plan.x(r.point.east_m) << "' cy='" << plan.y(-r.point.north_m) << "' rx='"
          << survey::kEllipse95Factor * u.major_sd_m * plan.scale << "' ry='"
          << survey::kEllipse95Factor * u.minor_sd_m * plan.scale << "' transform='rotate(" << u.major_azimuth_deg - 90
          << ' ' << plan.x(r.point.east_m) << ' ' << plan.y(-r.point.north_m) << ")' fill='none' stroke='#999'/>\n";
    out << "<circle cx='" << plan.x(r.point.east_m) << "' cy='" << plan.y(-r.point.north_m) << "' r='2.5' fill='" << colour
        << "'><title>station " << r.index << ": MD " << r.station.md_m << " m" << (r.qc.pass ? "" : ", QC: " + r.qc.reason)
        << "</title></circle>\n";
    out << "<circle cx='" << section.x(r.point.vertical_section_m) << "' cy='" << section.y(r.point.tvd_m) << "' r='2.5' fill='"
        << colour << "'/>\n";
  }
  out << "</svg>\n";
}

}  // namespace plumb::cli
