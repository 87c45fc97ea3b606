#include "plumb/windowed/window.hpp"

namespace plumb::windowed {

void WindowData::clear() {
  for (auto* column : {&t, &gx, &gy, &gz, &bx, &by, &bz}) column->clear();
}

}  // namespace plumb::windowed
