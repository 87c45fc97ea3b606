#include "plumb/survey/quality.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "plumb/core/number.hpp"

namespace plumb::survey {

ReferenceField read_reference_file(std::istream& in, const std::string& source) {
  ReferenceField r;
  std::string line;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] == '#') continue;
    std::istringstream words(line);
    std::string key, value, extra;
    words >> key >> value;
    const auto v = parse_number(value);
    const auto where = source + ":" + std::to_string(n) + ": ";
    if (!v || (words >> extra)) throw std::runtime_error(where + "expected `KEY NUMBER`, got '" + line + "'");
    if (key == "gravity_mps2") r.gravity_mps2 = *v;
    else if (key == "total_b_uT") r.total_b_uT = *v;
    else if (key == "dip_deg") r.dip_deg = *v;
    else if (key == "declination_deg") r.declination_deg = *v;
    else throw std::runtime_error(where + "unknown key '" + key + "' (gravity_mps2, total_b_uT, dip_deg, declination_deg)");
  }
  if (r.gravity_mps2 && !(*r.gravity_mps2 > 0)) throw std::runtime_error(source + ": gravity_mps2 must be > 0");
  if (r.total_b_uT && !(*r.total_b_uT > 0)) throw std::runtime_error(source + ": total_b_uT must be > 0");
  if (r.dip_deg && std::abs(*r.dip_deg) > 90) throw std::runtime_error(source + ": dip_deg must be within [-90, 90]");
  return r;
}

namespace {

void append(std::string& reason, const std::string& what) { reason += (reason.empty() ? "" : "; ") + what; }

std::string fixed(double v, int digits) {
  std::ostringstream o;
  o.setf(std::ios::fixed);
  o.precision(digits);
  o << v;
  return o.str();
}

// One check: measured against reference within tolerance, with what went wrong said in `r.reason`.
void check_one(bool enabled, double measured, bool measured_ok, const std::optional<double>& reference, double tolerance,
               const char* name, const char* unit, int digits, double& residual, bool& checked, QcResult& r) {
  if (!enabled) return;
  if (!reference) {
    r.pass = false;
    append(r.reason, std::string("no reference ") + name);
    return;
  }
  if (!measured_ok) {
    r.pass = false;
    append(r.reason, std::string("no ") + name + " measured");
    return;
  }
  checked = true;
  residual = measured - *reference;
  if (std::abs(residual) > tolerance) {
    r.pass = false;
    append(r.reason, std::string(name) + " off by " + fixed(residual, digits) + " " + unit + " (tolerance " +
                         fixed(tolerance, digits) + ")");
  }
}

}  // namespace

QcResult check_station(double total_g, double total_b, double dip, const ReferenceField& ref, const QcTolerances& tol,
                       const QcChecks& checks) {
  QcResult r;
  check_one(checks.gravity, total_g, std::isfinite(total_g) && total_g > 0, ref.gravity_mps2, tol.gravity_mps2, "|G|",
            "m/s^2", 4, r.gravity_residual_mps2, r.gravity_checked, r);
  check_one(checks.total_b, total_b, std::isfinite(total_b) && total_b > 0, ref.total_b_uT, tol.total_b_uT, "|B|", "uT",
            3, r.total_b_residual_uT, r.total_b_checked, r);
  check_one(checks.dip, dip, std::isfinite(dip) && std::isfinite(total_b) && total_b > 0, ref.dip_deg, tol.dip_deg, "dip",
            "deg", 3, r.dip_residual_deg, r.dip_checked, r);
  return r;
}

}  // namespace plumb::survey
