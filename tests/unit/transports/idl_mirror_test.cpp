// messages.hpp mirrors idl/*.idl by hand; this test parses the IDL and checks, struct by struct,
// that visit_fields walks the same fields in the same order with the same types, array sizes,
// string and sequence bounds, and that the flag constants have the same values.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <type_traits>

#include "idl_parser.hpp"
#include "plumb/transport/messages.hpp"

namespace {

using namespace plumb;
using test::IdlFile;
using test::IdlMember;

template <class T> struct IdlName;
template <> struct IdlName<topics::SensorSample> { static constexpr const char* value = "SensorSample"; };
template <> struct IdlName<topics::SensorBatch> { static constexpr const char* value = "SensorBatch"; };
template <> struct IdlName<topics::Attitude> { static constexpr const char* value = "Attitude"; };
template <> struct IdlName<topics::TriadCalibration> { static constexpr const char* value = "TriadCalibration"; };
template <> struct IdlName<topics::CalibrationCoefficients> { static constexpr const char* value = "CalibrationCoefficients"; };
template <> struct IdlName<topics::Counter> { static constexpr const char* value = "Counter"; };
template <> struct IdlName<topics::ComponentStatus> { static constexpr const char* value = "ComponentStatus"; };
template <> struct IdlName<topics::Truth> { static constexpr const char* value = "Truth"; };

template <class T> struct IsArray : std::false_type {};
template <class E, std::size_t N> struct IsArray<std::array<E, N>> : std::true_type {
  using element = E;
  static constexpr std::size_t size = N;
};
template <class T> struct IsVector : std::false_type {};
template <class E> struct IsVector<std::vector<E>> : std::true_type { using element = E; };

template <class T> std::string type_of() {
  if constexpr (std::is_same_v<T, double>) return "double";
  else if constexpr (std::is_same_v<T, std::int64_t>) return "int64";
  else if constexpr (std::is_same_v<T, std::uint64_t>) return "uint64";
  else if constexpr (std::is_same_v<T, std::uint32_t>) return "uint32";
  else if constexpr (std::is_same_v<T, std::int32_t>) return "int32";
  else if constexpr (std::is_same_v<T, std::string>) return "string";
  else if constexpr (IsVector<T>::value) return "sequence";
  else return IdlName<T>::value;
}

// The C++ side in the parser's terms (bounds are checked separately against the k*Max tables).
template <class M> std::vector<IdlMember> cpp_members() {
  M message{};
  std::vector<IdlMember> members;
  topics::visit_fields(message, [&](const char* name, const auto& field) {
    using F = std::remove_cvref_t<decltype(field)>;
    IdlMember m;
    m.name = name;
    if constexpr (IsArray<F>::value) {
      m.type = type_of<typename IsArray<F>::element>();
      m.array = IsArray<F>::size;
    } else if constexpr (IsVector<F>::value) {
      m.type = "sequence";
      m.element = type_of<typename IsVector<F>::element>();
    } else {
      m.type = type_of<F>();
    }
    members.push_back(m);
  });
  return members;
}

const std::map<std::string, std::vector<IdlMember>>& cpp_structs() {
  static const std::map<std::string, std::vector<IdlMember>> structs = {
      {"SensorSample", cpp_members<topics::SensorSample>()},
      {"SensorBatch", cpp_members<topics::SensorBatch>()},
      {"Attitude", cpp_members<topics::Attitude>()},
      {"TriadCalibration", cpp_members<topics::TriadCalibration>()},
      {"CalibrationCoefficients", cpp_members<topics::CalibrationCoefficients>()},
      {"Counter", cpp_members<topics::Counter>()},
      {"ComponentStatus", cpp_members<topics::ComponentStatus>()},
      {"Truth", cpp_members<topics::Truth>()},
  };
  return structs;
}

// Where messages.hpp states each IDL bound.
const std::map<std::string, std::size_t> kStringBounds = {
    {"SensorBatch.tool_id", topics::kToolIdMax},
    {"SensorBatch.calibration_id", topics::kIdMax},
    {"Attitude.tool_id", topics::kToolIdMax},
    {"Attitude.estimator", topics::kNameMax},
    {"Attitude.reason", topics::kReasonMax},
    {"CalibrationCoefficients.tool_id", topics::kToolIdMax},
    {"CalibrationCoefficients.calibration_id", topics::kIdMax},
    {"Counter.name", topics::kNameMax},
    {"ComponentStatus.component", topics::kComponentMax},
    {"ComponentStatus.host", topics::kHostMax},
    {"ComponentStatus.state", topics::kStateMax},
    {"ComponentStatus.last_error", topics::kErrorMax},
    {"Truth.tool_id", topics::kToolIdMax},
};
const std::map<std::string, std::size_t> kSequenceBounds = {
    {"SensorBatch.samples", topics::kMaxSamplesPerBatch},
    {"ComponentStatus.counters", topics::kMaxCountersPerStatus},
};
const std::map<std::string, long long> kConstants = {
    {"MAX_SAMPLES_PER_BATCH", topics::kMaxSamplesPerBatch},
    {"SAMPLE_ACCEL_SATURATED", topics::sample_flags::kAccelSaturated},
    {"SAMPLE_MAG_SATURATED", topics::sample_flags::kMagSaturated},
    {"SAMPLE_GYRO_SATURATED", topics::sample_flags::kGyroSaturated},
    {"SAMPLE_OUT_OF_RANGE", topics::sample_flags::kOutOfRange},
    {"SAMPLE_NOT_FINITE", topics::sample_flags::kNotFinite},
    {"SAMPLE_GAP_BEFORE", topics::sample_flags::kGapBefore},
    {"SAMPLE_TIME_BACKWARDS", topics::sample_flags::kTimeBackwards},
    {"SAMPLE_HAS_GYRO", topics::sample_flags::kHasGyro},
    {"SAMPLE_HAS_TEMPERATURE", topics::sample_flags::kHasTemperature},
    {"SAMPLE_CALIBRATED", topics::sample_flags::kCalibrated},
    {"SAMPLE_TEMPERATURE_OUT_OF_RANGE", topics::sample_flags::kTemperatureOutOfRange},
    {"ATTITUDE_VALID", topics::attitude_flags::kValid},
    {"ATTITUDE_AZIMUTH_VALID", topics::attitude_flags::kAzimuthValid},
    {"ATTITUDE_TOOLFACE_VALID", topics::attitude_flags::kToolfaceValid},
    {"ATTITUDE_ROTATING", topics::attitude_flags::kRotating},
    {"ATTITUDE_PARTIAL_WINDOW", topics::attitude_flags::kPartialWindow},
};

// Every way the IDL and the C++ mirror disagree, one line each.
std::vector<std::string> differences(const IdlFile& idl) {
  std::vector<std::string> out;
  std::map<std::string, const test::IdlStruct*> idl_structs;
  for (const auto& s : idl.structs) idl_structs[s.name] = &s;
  for (const auto& [name, s] : idl_structs) {
    if (!cpp_structs().count(name)) out.push_back("IDL struct " + name + " has no C++ mirror");
  }
  for (const auto& [name, cpp] : cpp_structs()) {
    const auto it = idl_structs.find(name);
    if (it == idl_structs.end()) {
      out.push_back("C++ struct " + name + " is not in the IDL");
      continue;
    }
    const auto& members = it->second->members;
    if (members.size() != cpp.size()) {
      out.push_back(name + ": IDL has " + std::to_string(members.size()) + " fields, C++ " + std::to_string(cpp.size()));
    }
    for (std::size_t i = 0; i < std::min(members.size(), cpp.size()); ++i) {
      const IdlMember& m = members[i];
      const IdlMember& c = cpp[i];
      const std::string where = name + "." + m.name;
      if (m.name != c.name) out.push_back(name + " field " + std::to_string(i) + ": IDL " + m.name + ", C++ " + c.name);
      if (m.type != c.type) out.push_back(where + ": IDL type " + m.type + ", C++ " + c.type);
      if (m.array != c.array) out.push_back(where + ": IDL array size " + std::to_string(m.array) + ", C++ " + std::to_string(c.array));
      if (m.element != c.element) out.push_back(where + ": IDL sequence of " + m.element + ", C++ of " + c.element);
      if (m.type == "string") {
        const auto bound = kStringBounds.find(where);
        if (bound == kStringBounds.end()) out.push_back(where + ": string without a k*Max constant");
        else if (bound->second != m.bound) out.push_back(where + ": IDL bound " + std::to_string(m.bound) + ", C++ " + std::to_string(bound->second));
      }
      if (m.type == "sequence") {
        const auto bound = kSequenceBounds.find(where);
        if (bound == kSequenceBounds.end()) out.push_back(where + ": sequence without a C++ bound constant");
        else if (bound->second != m.bound) out.push_back(where + ": IDL bound " + std::to_string(m.bound) + ", C++ " + std::to_string(bound->second));
      }
    }
  }
  for (const auto& [name, value] : idl.constants) {
    const auto it = kConstants.find(name);
    if (it == kConstants.end()) out.push_back("IDL constant " + name + " has no C++ mirror");
    else if (it->second != value) out.push_back(name + ": IDL " + std::to_string(value) + ", C++ " + std::to_string(it->second));
  }
  for (const auto& [name, value] : kConstants) {
    if (!idl.constants.count(name)) out.push_back("C++ constant for " + name + " is not in the IDL");
  }
  return out;
}

std::string read_idl_dir() {
  std::string all;
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(PLUMB_IDL_DIR)) {
    if (entry.path().extension() != ".idl") continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    all += text.str() + "\n";
    ++files;
  }
  EXPECT_GE(files, 5u) << "IDL files in " << PLUMB_IDL_DIR;
  return all;
}

std::string join(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

TEST(IdlMirror, MessagesHppMatchesTheIdlFieldByField) {
  const IdlFile idl = test::parse_idl(read_idl_dir());
  EXPECT_EQ(idl.structs.size(), cpp_structs().size());
  const auto diffs = differences(idl);
  EXPECT_TRUE(diffs.empty()) << join(diffs);
}

// The comparison must see a change in the IDL; otherwise the test above could never fail.
TEST(IdlMirror, DetectsSwappedRenamedAndResizedFields) {
  std::string text = read_idl_dir();
  auto mutated = [&](const std::string& from, const std::string& to) {
    std::string copy = text;
    const auto at = copy.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) copy.replace(at, from.size(), to);
    return differences(test::parse_idl(copy));
  };
  EXPECT_FALSE(mutated("double azimuth_deg;", "double azimuth_degrees;").empty());
  EXPECT_FALSE(mutated("double fx; double fy;", "double fy; double fx;").empty());
  EXPECT_FALSE(mutated("double thermometer[4];", "double thermometer[3];").empty());
  EXPECT_FALSE(mutated("string<63> reason;", "string<64> reason;").empty());
  EXPECT_FALSE(mutated("sequence<SensorSample, 32>", "sequence<SensorSample, 16>").empty());
  EXPECT_FALSE(mutated("SAMPLE_HAS_GYRO = 128", "SAMPLE_HAS_GYRO = 129").empty());
  EXPECT_FALSE(mutated("unsigned long samples_used;", "unsigned long long samples_used;").empty());
}

TEST(IdlParser, ReadsTheSubsetPlumbUses) {
  const IdlFile f = test::parse_idl(
      "// comment\nmodule a { module b {\nconst unsigned long K = 7; /* block */\n@final\n"
      "struct S { string<5> s; double d[2]; sequence<T, 3> q; long long t; };\n}; };\n");
  ASSERT_EQ(f.structs.size(), 1u);
  EXPECT_EQ(f.constants.at("K"), 7);
  const auto& m = f.structs[0].members;
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m[0].bound, 5u);
  EXPECT_EQ(m[1].array, 2u);
  EXPECT_EQ(m[2].element, "T");
  EXPECT_EQ(m[2].bound, 3u);
  EXPECT_EQ(m[3].type, "int64");
}

}  // namespace
