#include "procedure_common.hpp"

#include <algorithm>
#include <map>
#include <utility>
#include <cmath>
#include <sstream>

#include <Eigen/Geometry>

#include "plumb/calibration/triad_fit.hpp"
#include "plumb/core/attitude.hpp"

namespace plumb::calibration::detail {

Outcome run_guarded(const std::function<Result(std::vector<std::string>& warnings)>& body) {
  Outcome out;
  try {
    Result r = body(out.warnings);
    r.warnings = out.warnings;
    out.result = std::move(r);
  } catch (const std::exception& e) {
    out.error = e.what();
    out.result.reset();
  }
  return out;
}

void add_parameters(std::vector<Parameter>& out, const std::string& prefix, const std::vector<std::string>& names,
                    const Eigen::VectorXd& values, const Eigen::MatrixXd& covariance, const std::string& unit) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    out.push_back({prefix + names[i], values[k], std::sqrt(std::max(0.0, covariance(k, k))), unit});
  }
}

double station_dT(const CalibrationModel& m, const StationAverage& s) {
  if (!s.has_temperature) return 0;
  return m.corrected_temperature(s.raw_temp_c) - m.reference_temp_c;
}

std::vector<StationResidual> accel_residuals(const CalibrationModel& model, const CalibrationModel& nominal,
                                             const std::vector<StationAverage>& stations, double g, double warn_deg,
                                             std::vector<std::string>& warnings) {
  std::vector<StationResidual> out;
  for (const auto& s : stations) {
    StationResidual r;
    r.station = s.station.name;
    const Eigen::Vector3d f = model.accelerometer.apply(s.accel, station_dT(model, s));
    r.norm_error = f.norm() - g;
    const Orientation& o = s.station.orientation;
    if (o.known()) {
      const Eigen::Vector3d up = o.up();
      r.direction_error_deg = std::acos(std::clamp(f.normalized().dot(up), -1.0, 1.0)) / kDeg;
      const double truth = inclination_of_specific_force(up);
      const Eigen::Vector3d f0 = nominal.accelerometer.apply(s.accel, station_dT(nominal, s));
      r.inclination_before_deg = std::abs(inclination_of_specific_force(f0) - truth);
      r.inclination_after_deg = std::abs(inclination_of_specific_force(f) - truth);
      if (r.direction_error_deg > warn_deg)
        warnings.push_back("station '" + s.station.name + "' (" + o.label() + "): calibrated reading is " +
                           format(r.direction_error_deg) + " deg from its nominal orientation");
    }
    out.push_back(r);
  }
  return out;
}

ResidualSplit split_residuals(const CalibrationModel& model, const std::vector<StationAverage>& stations) {
  ResidualSplit out;
  std::map<std::pair<std::string, int>, std::vector<std::pair<const StationAverage*, Eigen::Vector3d>>> faces;
  for (const auto& s : stations) {
    const Orientation& o = s.station.orientation;
    if (!o.known()) continue;
    const Eigen::Vector3d f = model.accelerometer.apply(s.accel, station_dT(model, s)).normalized();
    faces[{s.station.run, o.face()}].emplace_back(&s, f);
  }
  const auto angle = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::atan2(a.cross(b).norm(), a.dot(b)) / kDeg;
  };
  for (const auto& [key, members] : faces) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& m : members) mean += m.second;
    mean.normalize();
    out.sensor_deg = std::max(out.sensor_deg, angle(mean, members.front().first->station.orientation.up()));
    // One station per face (6-position): nothing tells its orientation from the sensors' errors.
    if (members.size() < 2) continue;
    out.valid = true;
    for (const auto& m : members) {
      const double a = angle(m.second, mean);
      if (a > out.orientation_deg) {
        out.orientation_deg = a;
        out.worst_station = m.first->station.name;
      }
    }
  }
  return out;
}

void fill_identity(Result& r, const CommonOptions& o) {
  r.model = o.base;
  r.model.tool_id = o.tool_id.empty() ? o.base.tool_id : o.tool_id;
  r.model.calibration_id = o.calibration_id.empty() ? o.base.calibration_id : o.calibration_id;
  r.model.stamp_s = o.stamp_s;
}

std::string format(double x, int precision) {
  std::ostringstream s;
  s.precision(precision);
  s << x;
  return s.str();
}

}  // namespace plumb::calibration::detail
