#include "plumb/estimators/window.hpp"

namespace plumb::estimators {

void WindowData::clear() {
  for (auto* column : {&t, &gx, &gy, &gz, &bx, &by, &bz}) column->clear();
}

void WindowData::reserve(std::size_t n) {
  for (auto* column : {&t, &gx, &gy, &gz, &bx, &by, &bz}) column->reserve(n);
}

}  // namespace plumb::estimators
