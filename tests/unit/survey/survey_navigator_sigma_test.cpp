// A navigator's station sigma against the gyro model of its own figures
// (SurveyOptions::station_sigma_beyond_model): counted by its excess over the model's angle sigma
// at that station only, never twice, and never narrower than either says.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>

#include "plumb/strapdown/parameters.hpp"
#include "plumb/survey/navigator_tool_code.hpp"
#include "plumb/survey/survey.hpp"

namespace plumb::survey {
namespace {

iscwsa::ToolCode navigator_code() {
  iscwsa::NavigatorParameters p;
  for (const auto& spec : strapdown::parameter_specs()) p[spec.name] = spec.default_value;
  return iscwsa::navigator_tool_code(p).tool;
}

SurveyOptions navigator_options(bool beyond_model) {
  SurveyOptions o;
  o.checks = {false, false, false};
  o.tool_code = navigator_code();
  o.station_sigma_beyond_model = beyond_model;
  return o;
}

// A build and turn drilled over six hours, stations 30 m apart, each with the given angle sigmas.
Survey navigator_survey(const SurveyOptions& o, const std::vector<double>& inc_sd, const std::vector<double>& azi_sd) {
  Survey s(o);
  for (std::size_t k = 0; k < inc_sd.size(); ++k) {
    Station st;
    st.t_s = 2400.0 * static_cast<double>(k);
    st.md_m = 300 + 30 * static_cast<double>(k);
    st.md_sd_m = 0.05;
    st.inclination_deg = 5 + 6 * static_cast<double>(k);
    st.magnetic_azimuth_deg = 40 + 4 * static_cast<double>(k);
    st.inclination_sd_deg = inc_sd[k];
    st.azimuth_sd_deg = azi_sd[k];
    s.add(st);
  }
  return s;
}

constexpr std::size_t kStations = 10;

// Within `relative` of each station's largest term.
void expect_same_covariances(const Survey& a, const Survey& b, double relative) {
  ASSERT_EQ(a.rows().size(), b.rows().size());
  for (std::size_t k = 0; k < a.rows().size(); ++k) {
    const Eigen::Matrix3d& ca = a.rows()[k].uncertainty.covariance;
    const Eigen::Matrix3d& cb = b.rows()[k].uncertainty.covariance;
    EXPECT_LE((ca - cb).cwiseAbs().maxCoeff(), relative * (1e-9 + cb.cwiseAbs().maxCoeff())) << "station " << k;
    EXPECT_LE((a.rows()[k].random_uncertainty.covariance - b.rows()[k].random_uncertainty.covariance).cwiseAbs().maxCoeff(),
              relative * (1e-9 + cb.cwiseAbs().maxCoeff()))
        << "station " << k;
  }
}

TEST(NavigatorSigma, AStationWithinTheModelsSigmaAddsNothing) {
  // The model's own angle sigma at each station: a survey whose stations carry none.
  const std::vector<double> none(kStations, 0.0);
  const Survey model_only = navigator_survey(navigator_options(false), none, none);
  // Navigator sigmas at 0.9 of the model's: already held by the model's terms.
  std::vector<double> inc, azi;
  for (const auto& r : model_only.rows()) {
    inc.push_back(0.9 * r.inclination_total_sd_deg);
    azi.push_back(0.9 * r.azimuth_total_sd_deg);
  }
  const Survey navigator = navigator_survey(navigator_options(true), inc, azi);
  expect_same_covariances(navigator, model_only, 1e-12);
  for (std::size_t k = 0; k < kStations; ++k) {
    EXPECT_NEAR(navigator.rows()[k].azimuth_total_sd_deg, model_only.rows()[k].azimuth_total_sd_deg, 1e-12);
    // The station's own sigma as measured stays in its column (to its 3 significant digits).
    EXPECT_NEAR(navigator.rows()[k].station.azimuth_sd_deg, azi[k], 5e-3 * azi[k] + 1e-9);
  }
  // Counted twice (the rule off), the same sigmas would widen every station beyond the model.
  const Survey twice = navigator_survey(navigator_options(false), inc, azi);
  EXPECT_GT(twice.rows().back().uncertainty.major_sd_m, 1.01 * model_only.rows().back().uncertainty.major_sd_m);
}

TEST(NavigatorSigma, AStationBeyondTheModelsSigmaAddsItsExcess) {
  const std::vector<double> none(kStations, 0.0);
  const Survey model_only = navigator_survey(navigator_options(false), none, none);
  // Station 4 blind (a gap, no depth): 6 deg of azimuth, or 1 deg of inclination, far beyond the
  // model's; every other station's sigma 0.
  constexpr std::size_t kBlind = 4;
  for (const bool azimuth : {true, false}) {
    const double sd = azimuth ? 6.0 : 1.0;
    std::vector<double> inc(kStations, 0.0), azi(kStations, 0.0);
    (azimuth ? azi : inc)[kBlind] = sd;
    const Survey navigator = navigator_survey(navigator_options(true), inc, azi);
    // The whole sigma counted beside the model, the rule off: a station's noise adds its variance
    // times a fixed propagation, so the excess adds (1 - model^2 / sd^2) of what the whole adds.
    const Survey whole = navigator_survey(navigator_options(false), inc, azi);
    const SurveyRow& m = model_only.rows()[kBlind];
    const double model_sd = azimuth ? m.azimuth_total_sd_deg : m.inclination_total_sd_deg;
    const double share = 1 - model_sd * model_sd / (sd * sd);
    ASSERT_GT(share, 0.1);
    ASSERT_LT(share, 0.99);
    for (std::size_t k = 0; k < kStations; ++k) {
      const Eigen::Matrix3d& base = model_only.rows()[k].uncertainty.covariance;
      const Eigen::Matrix3d added_whole = whole.rows()[k].uncertainty.covariance - base;
      const Eigen::Matrix3d added = navigator.rows()[k].uncertainty.covariance - base;
      EXPECT_LE((added - share * added_whole).cwiseAbs().maxCoeff(), 1e-9 * (1e-9 + base.cwiseAbs().maxCoeff()))
          << (azimuth ? "azimuth" : "inclination") << ", station " << k;
      if (k >= kBlind) {
        EXPECT_GT(added_whole.trace(), 0.0) << k;  // the blind station moved what lies below it
      }
    }
    // The blind station keeps the navigator's width: its angle's total sigma is the navigator's.
    const SurveyRow& blind = navigator.rows()[kBlind];
    EXPECT_NEAR(azimuth ? blind.azimuth_total_sd_deg : blind.inclination_total_sd_deg, sd, 1e-9);
    EXPECT_GT(navigator.rows().back().uncertainty.covariance.trace(), model_only.rows().back().uncertainty.covariance.trace());
  }
}

TEST(NavigatorSigma, CovariancesStaySymmetricPositiveSemiDefinite) {
  // Sigmas around the model's, some below and some above, every station.
  std::vector<double> inc, azi;
  for (std::size_t k = 0; k < kStations; ++k) {
    inc.push_back(k % 2 ? 0.02 : 0.8);
    azi.push_back(k % 3 ? 0.05 : 9.0);
  }
  const Survey navigator = navigator_survey(navigator_options(true), inc, azi);
  for (const auto& row : navigator.rows())
    for (const Eigen::Matrix3d* c : {&row.uncertainty.covariance, &row.random_uncertainty.covariance}) {
      EXPECT_LE((*c - c->transpose()).cwiseAbs().maxCoeff(), 1e-12 * (1 + c->cwiseAbs().maxCoeff()));
      const Eigen::Vector3d eig = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(*c).eigenvalues();
      EXPECT_GE(eig.minCoeff(), -1e-12 * (1 + eig.maxCoeff())) << "station " << row.index;
      // Never narrower than the navigator says of its own angles, nor than the model.
      EXPECT_GE(row.azimuth_total_sd_deg + 1e-12, row.station.azimuth_sd_deg * (1 - 1e-3));
    }
}

}  // namespace
}  // namespace plumb::survey
