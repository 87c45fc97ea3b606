// The ISCWSA MWD error model against ISCWSA's own example workbooks (tests/data/iscwsa, extracted
// from error-model-example-mwdrev4-iscwsa-1, -mwdrev5-iscwsa-1 and -mwdrev5-iscwsa-2): the wells'
// stations, field and term values in; every term's covariance (NN, EE, VV, NE, NV, EV) at each
// diagnostic depth must match the workbook's within 0.1 %, from the whole well and from a survey
// that ends at that depth (as a live survey does); and a station's values must not depend on the
// stations after it.
#include <cmath>
#include <cstddef>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "plumb/csv/files.hpp"
#include "plumb/survey/iscwsa.hpp"
#include "plumb/survey/minimum_curvature.hpp"
#include "plumb/survey/tool_code_file.hpp"
#include "data_rows.hpp"

namespace plumb::survey::iscwsa {
namespace {

const std::string kWorkbooks = PLUMB_ISCWSA_DATA;

struct Example {
  std::vector<Station> stations;
  Field field;
  ToolCode tool;
  double depth_unit_m = 1;
};

Example load(const std::string& name) {
  Example ex;
  std::ifstream f(kWorkbooks + "/" + name + ".field.txt");
  std::map<std::string, std::string> kv;
  for (std::string key, value; f >> key;) {
    if (key[0] == '#') {
      std::getline(f, value);
      continue;
    }
    f >> value;
    kv[key] = value;
  }
  ex.field.gravity_mps2 = std::stod(kv.at("gravity_mps2"));
  ex.field.total_b_nT = std::stod(kv.at("total_b_nT"));
  ex.field.dip_deg = std::stod(kv.at("dip_deg"));
  ex.field.vertical_inc_limit_deg = std::stod(kv.at("vertical_inc_limit_deg"));
  const double declination = std::stod(kv.at("declination_deg"));
  ex.depth_unit_m = kv.at("depth_unit") == "ft" ? kFootM : 1.0;
  std::vector<StationGeometry> geometry;
  for (const auto& r : test::data_rows(kWorkbooks + "/" + name + ".wellpath.csv"))
    geometry.push_back({std::stod(r[0]) * ex.depth_unit_m, std::stod(r[1]), std::stod(r[2])});
  const auto path = minimum_curvature(geometry);
  for (std::size_t k = 0; k < geometry.size(); ++k)
    ex.stations.push_back({geometry[k].md_m, geometry[k].inclination_deg, geometry[k].azimuth_deg,
                           geometry[k].azimuth_deg - declination, path[k].tvd_m});
  std::ifstream tool(kWorkbooks + "/" + name + ".tool.csv");
  ex.tool = read_tool_code(tool, name + ".tool.csv");
  if (name.find("rev4") != std::string::npos) ex.tool.revision = 4;
  return ex;
}

// One diagnostic value: 0.1 % of the workbook's; a value the workbook gives as 0 must be 0 to
// round-off.
void expect_cell(double ours, const std::string& theirs_text, const std::string& what) {
  const double theirs = std::stod(theirs_text);
  EXPECT_NEAR(ours, theirs, 1e-3 * std::abs(theirs) + 1e-10) << what;
}

// How the well is run through the model: whole, or ending at each diagnostic depth, as a live
// survey is when that station is its newest.
enum class Run { WholeWell, EndingAtEachDepth };

// Every term at every diagnostic depth; returns the number of values compared.
int compare(const std::string& name, Run run) {
  const Example ex = load(name);
  const Result whole = propagate(ex.stations, ex.tool, ex.field);
  std::map<std::size_t, Result> ending;  // by the index of the last station
  std::map<std::string, std::size_t> term;
  for (std::size_t i = 0; i < whole.codes.size(); ++i) term[whole.codes[i]] = i;
  int compared = 0;
  for (const auto& row : test::data_rows(kWorkbooks + "/" + name + ".expected.csv")) {
    const double md = std::stod(row[0]) * ex.depth_unit_m;
    const std::string& code = row[1];
    std::size_t k = 0;
    while (k < ex.stations.size() && std::abs(ex.stations[k].md_m - md) > 1e-6) ++k;
    if (k == ex.stations.size()) {
      ADD_FAILURE() << name << ": no station at MD " << row[0];
      continue;
    }
    if (run == Run::EndingAtEachDepth && !ending.count(k)) {
      const std::vector<Station> above(ex.stations.begin(), ex.stations.begin() + static_cast<std::ptrdiff_t>(k + 1));
      ending.emplace(k, propagate(above, ex.tool, ex.field));
    }
    const Result& r = run == Run::WholeWell ? whole : ending.at(k);
    Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
    if (code == "TOTAL") {
      c = r.total[k];
    } else if (term.count(code)) {
      c = r.per_term[term[code]][k];
    } else {
      ADD_FAILURE() << name << ": term " << code << " missing from the model";
      continue;
    }
    const double ours[6] = {c(0, 0), c(1, 1), c(2, 2), c(0, 1), c(0, 2), c(1, 2)};
    const char* names[6] = {"NN", "EE", "VV", "NE", "NV", "EV"};
    for (std::size_t i = 0; i < 6; ++i) {
      expect_cell(ours[i], row[2 + i],
                  name + (run == Run::WholeWell ? "" : " ending") + " MD " + row[0] + " " + code + " " + names[i]);
      ++compared;
    }
  }
  return compared;
}

TEST(IscwsaWorkbook, MwdRevision4Example1) { EXPECT_EQ(compare("mwdrev4-iscwsa-1", Run::WholeWell), 4 * 28 * 6); }
TEST(IscwsaWorkbook, MwdRevision5Example1) { EXPECT_EQ(compare("mwdrev5-iscwsa-1", Run::WholeWell), 4 * 36 * 6); }
TEST(IscwsaWorkbook, MwdRevision5Example2) { EXPECT_EQ(compare("mwdrev5-iscwsa-2", Run::WholeWell), 7 * 36 * 6); }

// The same cells from a survey that ends at the diagnostic depth: the first depth of each well is
// the end of its vertical section, where the vertical form once left out the newest station's own
// course (revision 4 well 1 at 1200 m: NN 4.404, EE 4.398 against 4.5111).
TEST(IscwsaWorkbook, MwdRevision4Example1EndingAtEachDepth) {
  EXPECT_EQ(compare("mwdrev4-iscwsa-1", Run::EndingAtEachDepth), 4 * 28 * 6);
}
TEST(IscwsaWorkbook, MwdRevision5Example1EndingAtEachDepth) {
  EXPECT_EQ(compare("mwdrev5-iscwsa-1", Run::EndingAtEachDepth), 4 * 36 * 6);
}
TEST(IscwsaWorkbook, MwdRevision5Example2EndingAtEachDepth) {
  EXPECT_EQ(compare("mwdrev5-iscwsa-2", Run::EndingAtEachDepth), 7 * 36 * 6);
}

// A station's covariance depends on the stations above it only (survey.hpp: rows never change once
// added): every term at every station of each well, the well ending there against the whole well.
TEST(IscwsaWorkbook, AStationDoesNotDependOnTheStationsAfterIt) {
  for (const std::string name : {"mwdrev4-iscwsa-1", "mwdrev5-iscwsa-1", "mwdrev5-iscwsa-2"}) {
    const Example ex = load(name);
    const Result whole = propagate(ex.stations, ex.tool, ex.field);
    int differ = 0;
    std::string first;
    for (std::size_t k = 1; k < ex.stations.size(); ++k) {
      const std::vector<Station> above(ex.stations.begin(), ex.stations.begin() + static_cast<std::ptrdiff_t>(k + 1));
      const Result ending = propagate(above, ex.tool, ex.field);
      for (std::size_t t = 0; t < whole.codes.size(); ++t) {
        const Eigen::Matrix3d& a = ending.per_term[t][k];
        const Eigen::Matrix3d& b = whole.per_term[t][k];
        if ((a - b).cwiseAbs().maxCoeff() > 1e-9 * (1 + b.cwiseAbs().maxCoeff())) {
          if (differ++ == 0) first = whole.codes[t] + " at MD " + std::to_string(ex.stations[k].md_m);
        }
      }
    }
    EXPECT_EQ(differ, 0) << name << ": first " << first;
  }
}

}  // namespace
}  // namespace plumb::survey::iscwsa

namespace plumb::survey::iscwsa {
namespace {

TEST(IscwsaToolCode, FileErrorsNameTheLine) {
  std::istringstream bad("code,weight_function,magnitude,unit,propagation\nABZ,ABZ,0.004,m/s2,S\nXX,NOPE,1,m,R\n");
  try {
    read_tool_code(bad, "mine.csv");
    FAIL() << "an unknown weighting function was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("mine.csv:3: unknown weighting function 'NOPE'"), std::string::npos) << e.what();
  }
  std::istringstream propagation("code,weight_function,magnitude,unit,propagation\nABZ,ABZ,0.004,m/s2,Q\n");
  EXPECT_THROW(read_tool_code(propagation, "p.csv"), std::runtime_error);
  EXPECT_THROW(builtin_tool_code("MWD+XYZ"), std::invalid_argument);
}

// Every built-in term is in its weighting function's model unit (the table the file reader
// converts to); a file in other units of the same quantities gives the same covariances as the
// file in the model's units; a unit of another quantity, or none known, names the line and the
// units accepted.
TEST(IscwsaToolCode, UnitsAreCheckedAndConverted) {
  for (const std::string& name : builtin_tool_codes()) {
    for (const Term& t : builtin_tool_code(name).terms) {
      const std::string unit = t.unit == "deg/sqr(hr)" ? "deg/sqrt(hr)" : t.unit;
      EXPECT_EQ(model_unit(t.weight_function), unit) << name << " " << t.code;
    }
  }
  // And the six example models of SPE 90408 as the paper gives them (read through the same table).
  for (int m = 1; m <= 6; ++m) {
    const std::string file = std::string(PLUMB_SPE90408_DATA) + "/model_" + std::to_string(m) + ".tool.csv";
    std::ifstream in(file);
    EXPECT_NO_THROW(read_tool_code(in, file));
  }
  const std::string header = "code,weight_function,magnitude,unit,propagation\n";
  std::istringstream model_units(header +
                                 "DRFR,DREF,0.35,m,R\nDSTG,DST,2.5e-07,1/m,G\nABZ,ABZ,0.004,m/s2,S\n"
                                 "ASZ,ASZ,0.0005,-,S\nMBZ,MBZ,70,nT,S\nSAG,SAG,0.2,deg,S\n");
  std::istringstream other_units(header +
                                 "DRFR,DREF,1.148293963254593,ft,R\nDSTG,DST,7.62e-08,1/ft,G\n"
                                 "ABZ,ABZ,0.4078864851911713,mg,S\nASZ,ASZ,500,ppm,S\nMBZ,MBZ,0.07,uT,S\n"
                                 "SAG,SAG,0.0034906585039886592,rad,S\n");
  const ToolCode a = read_tool_code(model_units, "model.csv"), b = read_tool_code(other_units, "other.csv");
  ASSERT_EQ(a.terms.size(), b.terms.size());
  for (std::size_t i = 0; i < a.terms.size(); ++i) {
    EXPECT_NEAR(b.terms[i].magnitude, a.terms[i].magnitude, 1e-9 * a.terms[i].magnitude) << a.terms[i].code;
    EXPECT_EQ(b.terms[i].unit, a.terms[i].unit);
  }
  std::vector<Station> path;
  for (int k = 0; k <= 20; ++k) path.push_back(Station{100.0 * k, 3.0 * k, 40.0 + k, 40.0 + k});
  Field field;
  field.total_b_nT = 50000, field.dip_deg = 65;
  const Result ra = propagate(path, a, field), rb = propagate(path, b, field);
  EXPECT_LT((ra.total.back() - rb.total.back()).norm(), 1e-9 * ra.total.back().norm());

  for (const char* row : {"DRFR,DREF,1,furlong,R", "MBZ,MBZ,70,deg,S", "SAG,SAG,0.2,nT,S"}) {
    std::istringstream bad(header + row + "\n");
    try {
      read_tool_code(bad, "units.csv");
      FAIL() << "accepted " << row;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("units.csv:2: term "), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("accepted: "), std::string::npos) << e.what();
    }
  }
}

TEST(IscwsaToolCode, RevisionsDifferWhereTheDocumentsDo) {
  const auto find = [](const ToolCode& t, const std::string& code) {
    for (const auto& term : t.terms)
      if (term.code == code) return term.magnitude;
    return -1.0;
  };
  EXPECT_EQ(find(builtin_tool_code("MWD"), "DEC-OH"), 0.21);
  EXPECT_EQ(find(builtin_tool_code("MWD:rev5"), "DEC-OH"), 0.20);
  EXPECT_EQ(find(builtin_tool_code("MWD:rev4"), "DECG"), 0.36);
  EXPECT_EQ(find(builtin_tool_code("MWD+IFR1"), "DEC-U"), 0.11);
  // The built-in revision 5 is the workbooks' model: the same terms and values.
  std::ifstream in(kWorkbooks + "/mwdrev5-iscwsa-1.tool.csv");
  const ToolCode workbook = read_tool_code(in, "workbook");
  const ToolCode builtin = builtin_tool_code("MWD:rev5");
  ASSERT_EQ(workbook.terms.size(), builtin.terms.size());
  for (const Term& w : workbook.terms) {
    EXPECT_EQ(find(builtin, w.code), w.magnitude) << w.code;
    for (const Term& b : builtin.terms) {
      if (b.code == w.code) {
        EXPECT_EQ(w.propagation == Propagation::Random, b.propagation == Propagation::Random) << w.code;
      }
    }
  }
}

}  // namespace
}  // namespace plumb::survey::iscwsa
