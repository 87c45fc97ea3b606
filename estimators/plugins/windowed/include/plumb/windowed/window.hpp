// The samples of one estimation window, column by column, in the quantities the formulas use:
// gravity G = -f (docs/conventions.md) and the field B, tool frame.
#pragma once

#include <cstddef>
#include <vector>

namespace plumb::windowed {

struct WindowData {
  std::vector<double> t;
  std::vector<double> gx, gy, gz;
  std::vector<double> bx, by, bz;
  double nominal_dt = 0;  // typical sample spacing, s (0 when unknown)

  std::size_t size() const { return t.size(); }
  bool empty() const { return t.empty(); }
  void clear();
};

}  // namespace plumb::windowed
