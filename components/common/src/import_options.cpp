#include "plumb/components/import_options.hpp"

namespace plumb::components {

void add_import_options(CLI::App& app, ImportOptions& o) {
  // No CLI11 delimiter: header texts may hold spaces, parentheses and commas of their own.
  app.add_option("--column", o.columns,
                 "NAME=HEADER: read plumb column NAME (t, seq, fx, fy, fz, bx, by, bz, wx, wy, wz, temp_c, depth_m) "
                 "from the file's column HEADER, e.g. wx=\"Gyroscope X (deg/s)\"; repeat for each column "
                 "(unmapped ones are looked up under their plumb name; docs/import.md)")
      ->option_text("NAME=HEADER ...");
  app.add_option("--units", o.units,
                 "the file's units, GROUP=UNIT[,...]: accel m/s2|g|mg, gyro rad/s|deg/s, mag uT|nT|mT|gauss, "
                 "time s|ms|us|ns, depth m|ft (default: m/s2, rad/s, uT, s, m), e.g. accel=g,gyro=deg/s,mag=gauss")
      ->option_text("GROUP=UNIT,...");
  app.add_option("--axes", o.axes,
                 "the sensor axes in the tool frame (docs/conventions.md: z down-hole, right-handed), for f, b and w: "
                 "a signed permutation such as x,-y,-z (tool x = sensor x, tool y = -sensor y, tool z = -sensor z) "
                 "or the rotation's nine numbers \"r11 r12 r13 r21 r22 r23 r31 r32 r33\" (tool = R sensor); "
                 "default x,y,z")
      ->option_text("AXES");
}

}  // namespace plumb::components
