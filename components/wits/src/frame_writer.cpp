#include "plumb/wits/frame_writer.hpp"

#include <cstdio>

namespace plumb::wits {

std::string record01_frame(double bit_depth_m, double hole_depth_m, double unit_m, std::time_t now) {
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  char text[160];
  std::snprintf(text, sizeof text, "&&\r\n0105%02d%02d%02d\r\n0106%02d%02d%02d\r\n0108%.2f\r\n0110%.2f\r\n!!\r\n",
                utc.tm_year % 100, utc.tm_mon + 1, utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec,
                bit_depth_m / unit_m, hole_depth_m / unit_m);
  return text;
}

}  // namespace plumb::wits
