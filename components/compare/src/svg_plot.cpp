// Hand-written SVG: one panel per inclination, mean error versus azimuth per plugin, the
// +-Cramer-Rao band in grey. No plotting library needed for lines and ticks.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "plumb/compare/compare.hpp"

namespace plumb::compare {

namespace {

constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};

std::string fmt(const char* f, auto... args) {
  char text[256];
  std::snprintf(text, sizeof text, f, args...);
  return text;
}

double value(const AzimuthPoint& p, bool inclination) {
  return inclination ? p.mean_inclination_error_deg : p.mean_azimuth_error_deg;
}

// A "nice" tick step for a range.
double tick_step(double range) {
  const double raw = range / 5;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (raw <= m * mag) return m * mag;
  }
  return 10 * mag;
}

}  // namespace

void write_svg_plot(std::ostream& out, const CompareResult& result, const PlotSelection& sel) {
  std::vector<const CaseResult*> panels;
  for (const auto& c : result.cases) {
    if (std::abs(c.rpm - sel.rpm) < 1e-9 && std::abs(c.snr_accel_db - sel.snr_accel_db) < 1e-9) panels.push_back(&c);
  }
  const double panel_w = 420, panel_h = 300, margin_l = 60, margin_b = 45, margin_t = 40, legend_h = 30;
  const double width = std::max<std::size_t>(1, panels.size()) * panel_w;
  const double height = panel_h + legend_h;
  out << fmt("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" font-family=\"sans-serif\" "
             "font-size=\"12\">\n",
             width, height);
  out << fmt("<rect width=\"%.0f\" height=\"%.0f\" fill=\"white\"/>\n", width, height);
  if (panels.empty()) {
    out << fmt("<text x=\"10\" y=\"30\">no case with %.0f rpm and SNR_a %.0f dB</text>\n</svg>\n", sel.rpm,
               sel.snr_accel_db);
    return;
  }
  const char* quantity = sel.inclination_errors ? "inclination" : "azimuth";
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const CaseResult& c = *panels[i];
    const double x0 = static_cast<double>(i) * panel_w + margin_l, x1 = x0 + panel_w - margin_l - 20;
    const double y0 = margin_t, y1 = panel_h - margin_b;
    double lo = 0, hi = 0;
    for (const auto& p : c.plugins) {
      for (const auto& pt : p.by_azimuth) {
        if (pt.valid == 0) continue;
        lo = std::min(lo, value(pt, sel.inclination_errors));
        hi = std::max(hi, value(pt, sel.inclination_errors));
      }
    }
    const double crb = sel.inclination_errors ? c.crb_inclination_deg : c.crb_azimuth_deg;
    lo = std::min(lo, -crb), hi = std::max(hi, crb);
    if (hi - lo < 1e-9) hi = lo + 1;
    const double pad = 0.08 * (hi - lo);
    lo -= pad, hi += pad;
    auto sx = [&](double az) { return x0 + (x1 - x0) * az / 360.0; };
    auto sy = [&](double v) { return y1 - (y1 - y0) * (v - lo) / (hi - lo); };
    out << fmt("<text x=\"%.1f\" y=\"20\" text-anchor=\"middle\" font-weight=\"bold\">I = %g deg, %g rpm, SNR_a %g dB</text>\n",
               0.5 * (x0 + x1), c.inclination_deg, c.rpm, c.snr_accel_db);
    out << fmt("<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"#eeeeee\"/>\n", x0, sy(crb), x1 - x0,
               sy(-crb) - sy(crb));
    out << fmt("<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" stroke=\"black\"/>\n", x0, y0,
               x1 - x0, y1 - y0);
    for (int az = 0; az <= 360; az += 90) {
      out << fmt("<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#bbbbbb\"/>\n", sx(az), y0, sx(az), y1);
      out << fmt("<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">%d</text>\n", sx(az), y1 + 15, az);
    }
    const double step = tick_step(hi - lo);
    for (double v = std::ceil(lo / step) * step; v <= hi; v += step) {
      out << fmt("<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#dddddd\"/>\n", x0, sy(v), x1, sy(v));
      out << fmt("<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">%.3g</text>\n", x0 - 4, sy(v) + 4,
                 std::abs(v) < 1e-12 ? 0.0 : v);
    }
    out << fmt("<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">azimuth (deg)</text>\n", 0.5 * (x0 + x1), y1 + 32);
    out << fmt("<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" transform=\"rotate(-90 %.1f %.1f)\">mean %s error "
               "(deg)</text>\n",
               x0 - 45, 0.5 * (y0 + y1), x0 - 45, 0.5 * (y0 + y1), quantity);
    for (std::size_t p = 0; p < c.plugins.size(); ++p) {
      std::string points;
      for (const auto& pt : c.plugins[p].by_azimuth) {
        if (pt.valid == 0) continue;
        points += fmt("%.1f,%.1f ", sx(pt.azimuth_deg), sy(value(pt, sel.inclination_errors)));
      }
      if (points.empty()) continue;
      const char* colour = kColours[p % 6];
      out << fmt("<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\" points=\"", colour) << points << "\"/>\n";
    }
  }
  // Legend.
  double lx = 10;
  const double ly = panel_h + 15;
  const auto& plugins = panels.front()->plugins;
  for (std::size_t p = 0; p < plugins.size(); ++p) {
    out << fmt("<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"3\"/>\n", lx, ly,
               lx + 25, ly, kColours[p % 6]);
    out << fmt("<text x=\"%.1f\" y=\"%.1f\">%s</text>\n", lx + 30, ly + 4, plugins[p].plugin.c_str());
    lx += 40 + 8.0 * static_cast<double>(plugins[p].plugin.size());
  }
  out << fmt("<rect x=\"%.1f\" y=\"%.1f\" width=\"20\" height=\"10\" fill=\"#eeeeee\" stroke=\"#999999\"/>\n", lx,
             ly - 5);
  out << fmt("<text x=\"%.1f\" y=\"%.1f\">+-Cramer-Rao bound (one sigma); plugins with no valid estimate are not "
             "drawn</text>\n",
             lx + 25, ly + 4);
  out << "</svg>\n";
}

}  // namespace plumb::compare
