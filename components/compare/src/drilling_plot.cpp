// Errors over time of the drilling runs, six panels like the source's figures.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "plumb/compare/drilling.hpp"

namespace plumb::compare {
namespace {

constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf", "#7f7f7f"};

struct Panel {
  const char* title;
  double ErrorPoint::*field;
};
constexpr Panel kPanels[] = {{"inclination error (deg)", &ErrorPoint::inclination_deg},
                             {"azimuth error (deg)", &ErrorPoint::azimuth_deg},
                             {"toolface error (deg)", &ErrorPoint::toolface_deg},
                             {"north error (m)", &ErrorPoint::north_m},
                             {"east error (m)", &ErrorPoint::east_m},
                             {"down error (m)", &ErrorPoint::down_m}};

std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0) {
  char text[160];
  std::snprintf(text, sizeof text, f, a, b, c, d);
  return text;
}

}  // namespace

void write_drilling_plot(std::ostream& out, const std::vector<DrillingRunResult>& runs) {
  const double w = 900, ph = 170, left = 70, top = 40, gap = 30, pw = w - left - 20;
  const double h = top + 6 * (ph + gap) + 20 * static_cast<double>(runs.size()) + 20;
  double t_max = 1;
  for (const auto& r : runs)
    for (const auto& p : r.errors) t_max = std::max(t_max, p.t);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << left << "\" y=\"20\" font-size=\"14\">Navigator errors over time (drilling runs)</text>\n";
  for (std::size_t k = 0; k < std::size(kPanels); ++k) {
    const auto& panel = kPanels[k];
    const double y0 = top + static_cast<double>(k) * (ph + gap);
    double span = 1e-6;
    for (const auto& r : runs)
      for (const auto& p : r.errors) span = std::max(span, std::abs(p.*panel.field));
    span *= 1.1;
    out << fmt("<rect x=\"%g\" y=\"%g\" width=\"%g\" height=\"%g\" fill=\"none\" stroke=\"#999\"/>\n", left, y0, pw, ph);
    out << fmt("<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"#ccc\"/>\n", left, y0 + ph / 2, left + pw, y0 + ph / 2);
    out << "<text x=\"" << left + 5 << "\" y=\"" << y0 + 13 << "\">" << panel.title << "</text>\n";
    out << fmt("<text x=\"%g\" y=\"%g\" text-anchor=\"end\">%.3g</text>\n", left - 4, y0 + 10, span);
    out << fmt("<text x=\"%g\" y=\"%g\" text-anchor=\"end\">%.3g</text>\n", left - 4, y0 + ph, -span);
    out << fmt("<text x=\"%g\" y=\"%g\" text-anchor=\"end\">%.0f s</text>\n", left + pw, y0 + ph + 12, t_max);
    for (std::size_t i = 0; i < runs.size(); ++i) {
      std::string points;
      for (const auto& p : runs[i].errors) {
        const double x = left + pw * p.t / t_max;
        const double y = y0 + ph / 2 - (ph / 2) * (p.*panel.field) / span;
        points += fmt("%.1f,%.1f ", x, y);
      }
      out << "<polyline fill=\"none\" stroke-width=\"1.2\" stroke=\"" << kColours[i % std::size(kColours)]
          << "\" points=\"" << points << "\"/>\n";
    }
  }
  double y = top + 6 * (ph + gap);
  for (std::size_t i = 0; i < runs.size(); ++i, y += 20) {
    const auto& r = runs[i];
    out << "<text x=\"" << left << "\" y=\"" << y << "\" fill=\"" << kColours[i % std::size(kColours)] << "\">"
        << r.grade << ", " << fmt("%.0f Hz", r.rate_hz) << (r.with_depth ? ", with depth" : ", no depth")
        << fmt(", seed %.0f", static_cast<double>(r.seed)) << "</text>\n";
  }
  out << "</svg>\n";
}

}  // namespace plumb::compare
