// The built-in tool codes. Values: the ISCWSA MWD revision 4 and 5 model
// sheets (error-model-example-mwdrev4-iscwsa-1 and -mwdrev5-iscwsa-1) and the OWSG tool code set A,
// revision 5.1 (codes A001Mc "MWD+SRGM" and A005Mc "MWD+IFR1"), which raised DEC-OH from 0.20 deg
// to 0.21 deg and propagates XYM2 as systematic and XYM4E as random.
#include <stdexcept>

#include "plumb/survey/iscwsa.hpp"

#include "iscwsa_gyro_tool_codes.hpp"

namespace plumb::survey::iscwsa {
namespace {

constexpr Propagation R = Propagation::Random, S = Propagation::Systematic, G = Propagation::Global,
                      W = Propagation::WellByWell;

// Depth and the toolface-independent sensor terms: the same in every MWD code here.
std::vector<Term> depth_and_sensors() {
  return {{"DRFR", "DREF", 0.35, "m", R},          {"DSFS", "DSF", 0.00056, "-", S},
          {"DSTG", "DST", 2.5e-07, "1/m", G},       {"ABXY-TI1S", "ABXY-TI1", 0.004, "m/s2", S},
          {"ABXY-TI2S", "ABXY-TI2", 0.004, "m/s2", S}, {"ABZ", "ABZ", 0.004, "m/s2", S},
          {"ASXY-TI1S", "ASXY-TI1", 0.0005, "-", S}, {"ASXY-TI2S", "ASXY-TI2", 0.0005, "-", S},
          {"ASXY-TI3S", "ASXY-TI3", 0.0005, "-", S}, {"ASZ", "ASZ", 0.0005, "-", S},
          {"MBXY-TI1S", "MBXY-TI1", 70, "nT", S},   {"MBXY-TI2S", "MBXY-TI2", 70, "nT", S},
          {"MBZ", "MBZ", 70, "nT", S},              {"MSXY-TI1S", "MSXY-TI1", 0.0016, "-", S},
          {"MSXY-TI2S", "MSXY-TI2", 0.0016, "-", S}, {"MSXY-TI3S", "MSXY-TI3", 0.0016, "-", S},
          {"MSZ", "MSZ", 0.0016, "-", S}};
}

// Axial interference, sag and misalignment as revision 5 has them: the same in every revision 5 code.
std::vector<Term> revision5_alignment() {
  return {{"AMIL", "AMIL", 220, "nT", S},    {"SAGE", "SAGE", 0.2, "deg", S},  {"XYM1", "XYM1", 0.1, "deg", S},
          {"XYM2", "XYM2", 0.1, "deg", S},   {"XYM3E", "XYM3E", 0.3, "deg", R}, {"XYM4E", "XYM4E", 0.3, "deg", R},
          {"XCLA", "XCLA", 0.167, "-", R},   {"XCLH", "XCLH", 0.167, "-", R}};
}

void append(std::vector<Term>& to, const std::vector<Term>& more) { to.insert(to.end(), more.begin(), more.end()); }

ToolCode rev4() {
  ToolCode t{"MWD:rev4 (ISCWSA MWD revision 4)", 4, 0, depth_and_sensors()};
  append(t.terms, {{"DECG", "AZ", 0.36, "deg", G},
                   {"DECR", "AZ", 0.1, "deg", R},
                   {"DBHG", "DBH", 5000, "deg.nT", G},
                   {"DBHR", "DBH", 3000, "deg.nT", R},
                   {"AMIL", "AMIL", 220, "nT", S},
                   {"SAG", "SAG", 0.2, "deg", S},
                   {"XYM1", "XYM1", 0.1, "deg", S},
                   {"XYM2", "XYM2", 0.1, "deg", S},
                   {"XYM3", "XYM3", 0.1, "deg", S},
                   {"XYM4", "XYM4", 0.1, "deg", S}});
  return t;
}

// Revision 5: the example workbooks (DEC-OH 0.20 deg), or OWSG 5.1 (0.21 deg).
ToolCode rev5(bool owsg) {
  ToolCode t{owsg ? "MWD (OWSG MWD+SRGM A001Mc revision 5.1)" : "MWD:rev5 (ISCWSA MWD revision 5)", 5, 0.000572615,
             depth_and_sensors()};
  append(t.terms, {{"DEC-U", "AZ", 0.16, "deg", owsg ? W : G},
                   {"DEC-OS", "AZ", 0.24, "deg", G},
                   {"DEC-OH", "AZ", owsg ? 0.21 : 0.20, "deg", G},
                   {"DEC-OI", "AZ", 0.05, "deg", G},
                   {"DECR", "AZ", 0.1, "deg", R},
                   {"DBH-U", "DBH", 2350, "deg.nT", owsg ? W : G},
                   {"DBH-OS", "DBH", 3359, "deg.nT", G},
                   {"DBH-OH", "DBH", 2840, "deg.nT", G},
                   {"DBH-OI", "DBH", 356, "deg.nT", G},
                   {"DBHR", "DBH", 3000, "deg.nT", R}});
  append(t.terms, revision5_alignment());
  return t;
}

ToolCode ifr1() {
  ToolCode t{"MWD+IFR1 (OWSG A005Mc revision 5.1)", 5, 0.000572615, depth_and_sensors()};
  append(t.terms, {{"DEC-U", "AZ", 0.11, "deg", W},
                   {"DEC-CI", "AZ", 0.09, "deg", G},
                   {"DEC-OI", "AZ", 0.05, "deg", G},
                   {"DECR", "AZ", 0.1, "deg", R},
                   {"DBH-U", "DBH", 1271, "deg.nT", W},
                   {"DBH-CI", "DBH", 712, "deg.nT", G},
                   {"DBH-OI", "DBH", 356, "deg.nT", G},
                   {"DBHR", "DBH", 3000, "deg.nT", R}});
  append(t.terms, revision5_alignment());
  return t;
}

}  // namespace

std::vector<std::string> builtin_tool_codes() {
  std::vector<std::string> names{"MWD", "MWD:rev5.1", "MWD:rev5", "MWD:rev4", "MWD+IFR1"};
  for (const auto& g : detail::gyro_tool_code_names()) names.push_back(g);
  return names;
}

ToolCode builtin_tool_code(const std::string& name) {
  if (name == "MWD" || name == "MWD:rev5.1") return rev5(true);
  if (name == "MWD:rev5") return rev5(false);
  if (name == "MWD:rev4") return rev4();
  if (name == "MWD+IFR1") return ifr1();
  if (auto gyro = detail::builtin_gyro_tool_code(name)) return *gyro;
  std::string names;
  for (const auto& n : builtin_tool_codes()) names += (names.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown tool code '" + name + "' (built in: " + names + "; or a tool code file)");
}

}  // namespace plumb::survey::iscwsa
