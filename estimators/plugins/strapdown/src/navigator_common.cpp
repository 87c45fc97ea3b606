#include "plumb/strapdown/navigator_common.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace plumb::strapdown {

std::string format(const char* fmt, double a, double b, double c) {
  char text[200];
  std::snprintf(text, sizeof text, fmt, a, b, c);
  return text;
}

double dip_of(const Eigen::Vector3d& f, const Eigen::Vector3d& b) {
  const double den = f.norm() * b.norm();
  return den > 0 ? std::asin(std::clamp(-f.dot(b) / den, -1.0, 1.0)) : 0.0;
}

}  // namespace plumb::strapdown
