// A tool's lateral vibration and shocks, shared by the platform and drilling simulators: the
// scenario's description, and the tones that make the vibration (random phases, on x and y). By
// default a few tones evenly spread over 0.75..1.25 of the centre frequency; with a band
// (Vibration::band_hz) many tones at random frequencies across it, as a bit's broadband excitation:
// a tool sampling below the band reads its aliases as slow motion, which a few fixed tones near one
// frequency do not show. Each tone of amplitude a carries a^2/2, so the rms is exact over long records.
#pragma once

#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace plumb::sim {

struct Vibration {
  double lateral_rms = 0;     // m/s^2 rms on each of x and y: band-limited lateral vibration added to f
  double frequency_hz = 15;   // centre frequency
  // 0: four tones over 0.75..1.25 of the centre frequency; > 0: broadband, 64 tones spread over
  // frequency_hz +- band_hz / 2 (a bit's excitation, 8-40 Hz say: frequency_hz 24, band_hz 32).
  double band_hz = 0;
  double shock_rate_hz = 0;   // mean rate of shocks (Poisson)
  double shock_peak = 0;      // m/s^2, half-sine shocks of 2 ms
  // Shock length; the sampled shock is never shorter than two sample periods (the sensor's
  // anti-alias filter spreads it), so every shock shows in the samples.
  double shock_duration_s = 0.002;
  // A shock that rebounds: the tool struck out to the wall and back, a displacement that ends where
  // it began (no net change of velocity nor of position: the truth's path does not carry shocks),
  // instead of a half-sine (a net change of velocity of 2 peak duration / pi that the truth does not
  // have). Sampled over at least four sample periods. Off: the half-sine, as before.
  bool shock_rebounds = false;
};

class VibrationTones {
 public:
  static constexpr int kNarrowTones = 4;      // per axis, without a band
  static constexpr int kBroadbandTones = 64;  // per axis, across a band

  VibrationTones() = default;
  // Draws the phases (and, across a band, the frequencies) from rng.
  VibrationTones(const Vibration& vibration, std::mt19937_64& rng);
  // m/s^2 on the tool's x and y at time t (s).
  Eigen::Vector2d at(double t) const;
  bool active() const { return amplitude_ > 0; }

 private:
  std::vector<double> frequency_[2], phase_[2];
  double amplitude_ = 0;
};

// Why a vibration cannot be simulated (empty when it can): the checks both simulators share.
std::string vibration_problem(const Vibration& vibration);
// "0.5 m/s2 rms at 15 Hz" or "3 m/s2 rms over 8-40 Hz".
std::string describe(const Vibration& vibration);

}  // namespace plumb::sim
