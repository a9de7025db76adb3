// How long a damping-law fit takes: on the 20-run ASR-V surge table (the size
// of a typical CFD campaign) and on 1000 synthetic runs, with ordinary and
// robust losses. Items are runs (observations) fitted.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "src/fit/damping_law.hpp"

namespace {

// examples/asr-v/asr-v-surge-damping.csv: u [m/s], X [N] (positive opposes motion).
const std::vector<double> kSurgeU = {0.00, 0.02, 0.04, 0.06, 0.08, 0.10, 0.12, 0.14, 0.16, 0.18,
                                     0.20, 0.22, 0.24, 0.26, 0.28, 0.30, 0.32, 0.34, 0.36, 0.38};
const std::vector<double> kSurgeX = {-0.00020, 0.00544, 0.01928, 0.04186, 0.07293, 0.11278, 0.16119,
                                     0.21879,  0.28528, 0.36097, 0.44516, 0.53802, 0.63986, 0.75051,
                                     0.87046,  0.99881, 1.13579, 1.28167, 1.43652, 1.60013};

struct Samples {
  std::vector<double> u;
  std::vector<double> force;
};

// A surge-like law over ahead and astern speeds with deterministic noise.
Samples synthetic_samples(int count) {
  Samples samples;
  for (int i = 0; i < count; ++i) {
    const double u = -2.0 + 4.0 * i / (count - 1);
    samples.u.push_back(u);
    samples.force.push_back(0.01 + 0.5 * u + 11.0 * u * std::abs(u) + 0.01 * std::sin(13.0 * i));
  }
  return samples;
}

void fit_and_count(benchmark::State& state, const char* terms, const std::vector<double>& u,
                   const std::vector<double>& force, const char* loss) {
  const hydrocoef::DampingLawSpec spec = hydrocoef::parse_damping_terms(terms);
  const hydrocoef::LossOptions options = hydrocoef::parse_loss(loss);
  for (auto _ : state) {
    (void)_;
    hydrocoef::DampingLawFit fit = hydrocoef::fit_damping_law(spec, u, force, options);
    benchmark::DoNotOptimize(fit.coefficients.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<benchmark::IterationCount>(u.size()));
}

void BM_FitSurgeTable(benchmark::State& state) { fit_and_count(state, "1,u,u|u|", kSurgeU, kSurgeX, "squared"); }
BENCHMARK(BM_FitSurgeTable);

void BM_FitSurgeTableHuber(benchmark::State& state) {
  fit_and_count(state, "1,u,u|u|", kSurgeU, kSurgeX, "huber:0.01");
}
BENCHMARK(BM_FitSurgeTableHuber);

void BM_FitSynthetic1000(benchmark::State& state) {
  const Samples samples = synthetic_samples(1000);
  fit_and_count(state, "1,u,u|u|", samples.u, samples.force, "squared");
}
BENCHMARK(BM_FitSynthetic1000);

void BM_FitSynthetic1000Huber(benchmark::State& state) {
  const Samples samples = synthetic_samples(1000);
  fit_and_count(state, "1,u,u|u|", samples.u, samples.force, "huber:0.01");
}
BENCHMARK(BM_FitSynthetic1000Huber);

}  // namespace

BENCHMARK_MAIN();
