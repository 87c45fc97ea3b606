// plumb-bench-estimators: throughput of each estimator plugin in samples per second on one core,
// fed in 32-sample batches (the sensor topic's batch size) with 10 s windows at 100 Hz, and a
// baseline measured in the same run: a plain loop that only sums every channel of the same
// samples (the least any estimator must do). Goal: >= 20 million samples/s for
// compensated. The strapdown navigator runs a 1-hour drilling run at 400 Hz (tactical gyros) and its
// row gives the real-time factor (goal: > 10,000x for the forward filter); the same run at 100 Hz,
// a common rate of drilling tools, shows how the factor grows when readings are fewer.
// Accepts Google Benchmark's flags (--help lists them).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "plumb/estimator/loader.hpp"
#include "plumb/sim/drilling.hpp"
#include "plumb/sim/platform.hpp"

namespace {

const std::vector<plumb::Sample>& samples() {
  static const std::vector<plumb::Sample> data = [] {
    // 100 windows of the reference case turning at 120 rpm.
    plumb::sim::Scenario s = plumb::sim::Scenario::reference(1.0, 40.0, 120.0, 20.0, 1);
    s.duration_s = 1000;
    plumb::sim::PlatformSimulator simulator(s);
    return simulator.run();
  }();
  return data;
}

constexpr std::size_t kBatch = 32;

void baseline_sum(benchmark::State& state) {
  const auto& data = samples();
  for (auto _ : state) {
    double sum = 0;
    for (const auto& s : data) sum += s.t + s.f.x() + s.f.y() + s.f.z() + s.b.x() + s.b.y() + s.b.z();
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * data.size()));
}

void plugin(benchmark::State& state, const std::string& name) {
  const auto& data = samples();
  auto estimator = plumb::estimator::load_estimator(name);
  std::vector<plumb::Estimate> out;
  out.reserve(256);
  for (auto _ : state) {
    estimator->configure({{"window", "10"}});
    out.clear();
    for (std::size_t i = 0; i < data.size(); i += kBatch) {
      estimator->push(std::span(data).subspan(i, std::min(kBatch, data.size() - i)), out);
    }
    estimator->flush(out);
    benchmark::DoNotOptimize(out.data());
  }
  if (out.size() != 100) state.SkipWithError("unexpected number of estimates");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * data.size()));
}

// One hour (61 min): a 60 s alignment, then 16 cycles of 8 m drilled at 0.05 m/s (sliding and rotary
// in turn) and a 60 s pipe connection, the shape of the reference run made four times longer.
const std::vector<plumb::Sample>& drilling_hour(double rate_hz) {
  static std::map<double, std::vector<plumb::Sample>> runs;
  auto [it, made] = runs.try_emplace(rate_hz);
  if (made) {
    auto s = plumb::sim::DrillingScenario::reference(plumb::sim::ImuGrade::named("tactical"), rate_hz, 1);
    s.plan.segments.clear();
    for (int i = 0; i < 16; ++i) {
      s.plan.segments.push_back(i % 2 ? plumb::sim::DrillSegment::rotary(8, 0.05, 30, 1.0)
                                       : plumb::sim::DrillSegment::drill(8, 0.05, 1.0, 0.5));
      s.plan.segments.push_back(plumb::sim::DrillSegment::stop(60));
    }
    plumb::sim::DrillingSimulator simulator(s);
    it->second = simulator.run();
  }
  return it->second;
}

void strapdown_hour(benchmark::State& state, const std::string& smooth, double rate_hz) {
  const auto& data = drilling_hour(rate_hz);
  auto estimator = plumb::estimator::load_estimator("strapdown");
  std::vector<plumb::Estimate> out;
  for (auto _ : state) {
    estimator->configure({{"latitude_deg", "35"}, {"gravity", "9.80665"}, {"imu_grade", "tactical"}, {"smooth", smooth}});
    out.clear();
    for (std::size_t i = 0; i < data.size(); i += kBatch) {
      estimator->push(std::span(data).subspan(i, std::min(kBatch, data.size() - i)), out);
    }
    estimator->flush(out);
    benchmark::DoNotOptimize(out.data());
  }
  if (out.empty() || !out.back().valid) state.SkipWithError("the navigator gave no valid estimate");
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * data.size()));
  state.counters["run_s"] = static_cast<double>(data.size()) / rate_hz;
  state.counters["rate_hz"] = rate_hz;
}

// Keeps each benchmark's rate to print the ratio table after the usual report.
class RateReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const auto& run : runs) {
      auto it = run.counters.find("items_per_second");
      if (it != run.counters.end() && !run.error_occurred) rates[run.benchmark_name()] = it->second;
      auto hz = run.counters.find("rate_hz");
      if (hz != run.counters.end()) sample_rates[run.benchmark_name()] = hz->second;
    }
  }
  std::map<std::string, double> rates;
  std::map<std::string, double> sample_rates;  // the navigator's runs: their readings per second
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RegisterBenchmark("baseline_sum", baseline_sum)->Unit(benchmark::kMillisecond);
  for (const char* name : {"static", "integral", "compensated"}) {
    benchmark::RegisterBenchmark((std::string("plugin/") + name).c_str(), plugin, std::string(name))
        ->Unit(benchmark::kMillisecond);
  }
  // Forward filter alone, then with the smoother's storage (what `--param smooth=1` adds).
  benchmark::RegisterBenchmark("plugin/strapdown_1h_400Hz", strapdown_hour, std::string("0"), 400.0)
      ->Unit(benchmark::kMillisecond)->Iterations(3);
  benchmark::RegisterBenchmark("plugin/strapdown_1h_400Hz_smooth", strapdown_hour, std::string("1"), 400.0)
      ->Unit(benchmark::kMillisecond)->Iterations(1);
  benchmark::RegisterBenchmark("plugin/strapdown_1h_100Hz", strapdown_hour, std::string("0"), 100.0)
      ->Unit(benchmark::kMillisecond)->Iterations(3);
  RateReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  // With --benchmark_repetitions the names carry _mean, _median, ...: compare like with like.
  auto suffix_of = [](const std::string& name) -> std::string {
    for (const char* s : {"_mean", "_median", "_stddev", "_cv"}) {
      const std::string suffix = s;
      if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) return suffix;
    }
    return {};
  };
  std::printf("\n%-34s %16s %18s %14s %12s\n", "benchmark", "Msamples/s/core", "baseline/plugin", "real time x", "goal");
  for (const auto& [name, rate] : reporter.rates) {
    const std::string suffix = suffix_of(name);
    if (suffix == "_stddev" || suffix == "_cv") continue;
    const auto base = reporter.rates.find("baseline_sum" + suffix);
    const double ratio = base != reporter.rates.end() && rate > 0 ? base->second / rate : 0.0;
    const auto hz = reporter.sample_rates.find(name);
    const bool strapdown = hz != reporter.sample_rates.end();
    const double real_time = strapdown ? rate / hz->second : 0.0;
    const char* goal = "";
    if (name.rfind("plugin/compensated", 0) == 0) goal = rate >= 20e6 ? ">=20 ok" : ">=20 MISS";
    if (name.rfind("plugin/strapdown_1h_400Hz", 0) == 0 && name.find("smooth") == std::string::npos)
      goal = real_time > 1e4 ? ">10000x ok" : ">10000x MISS";
    std::printf("%-34s %16.2f %18.1f %14s %12s\n", name.c_str(), rate / 1e6, ratio,
                strapdown ? std::to_string(static_cast<long>(real_time)).c_str() : "", goal);
  }
  benchmark::Shutdown();
  return 0;
}
