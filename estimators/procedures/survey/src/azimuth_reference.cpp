#include "plumb/survey/azimuth_reference.hpp"

#include <stdexcept>

#include "plumb/core/attitude.hpp"

namespace plumb::survey {

std::string to_string(AzimuthReference r) {
  switch (r) {
    case AzimuthReference::Magnetic: return "magnetic";
    case AzimuthReference::True: return "true";
    case AzimuthReference::Grid: return "grid";
  }
  return "magnetic";
}

std::optional<AzimuthReference> parse_azimuth_reference(const std::string& text) {
  if (text == "magnetic") return AzimuthReference::Magnetic;
  if (text == "true") return AzimuthReference::True;
  if (text == "grid") return AzimuthReference::Grid;
  return std::nullopt;
}

double convert_magnetic_azimuth(double magnetic_deg, AzimuthReference to, const NorthCorrections& c) {
  if (to == AzimuthReference::Magnetic) return wrap_deg_360(magnetic_deg);
  if (!c.declination_known) throw std::invalid_argument("a " + to_string(to) + " azimuth needs the declination");
  const double true_deg = magnetic_deg + c.declination_deg;
  if (to == AzimuthReference::True) return wrap_deg_360(true_deg);
  if (!c.convergence_known) throw std::invalid_argument("a grid azimuth needs the grid convergence");
  return wrap_deg_360(true_deg - c.convergence_deg);
}

double true_azimuth_offset_deg(AzimuthReference from, const NorthCorrections& c) {
  switch (from) {
    case AzimuthReference::True: return 0;
    case AzimuthReference::Grid: return c.convergence_deg;
    case AzimuthReference::Magnetic: return c.declination_known ? c.declination_deg : 0;
  }
  return 0;
}

}  // namespace plumb::survey
