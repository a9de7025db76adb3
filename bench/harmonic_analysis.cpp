// How long the harmonic analysis of a forced-oscillation run takes: a
// history of 10^6 samples (goal: <= 50 ms), with one force component and
// with all six, one and three harmonics, the start-up found by MSER.
// Items are samples analysed.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "src/pmm/harmonic_analysis.hpp"

namespace {

struct History {
  std::vector<double> t;
  std::array<std::vector<double>, 6> f;
};

History make_history(std::size_t samples, std::size_t components, const hydrocoef::HarmonicMotion& motion) {
  History h;
  h.t.resize(samples);
  for (std::size_t c = 0; c < components; ++c) h.f[c].resize(samples);
  const double dt = 200.0 * motion.period() / static_cast<double>(samples);
  for (std::size_t i = 0; i < samples; ++i) {
    const double t = dt * static_cast<double>(i);
    h.t[i] = t;
    for (std::size_t c = 0; c < components; ++c)
      h.f[c][i] = -(3.0 + static_cast<double>(c)) * motion.acceleration(t) - 0.5 * motion.velocity(t) + std::exp(-t) +
                  0.01 * std::sin(37.0 * t);
  }
  return h;
}

void BM_HarmonicAnalysis(benchmark::State& state) {
  const auto samples = static_cast<std::size_t>(state.range(0));
  const auto components = static_cast<std::size_t>(state.range(1));
  const int harmonics = static_cast<int>(state.range(2));
  const hydrocoef::HarmonicMotion motion{0, 0.03, 2.0 * std::numbers::pi / 2.0, 0.0};
  const History h = make_history(samples, components, motion);
  std::array<std::span<const double>, 6> spans;
  for (std::size_t c = 0; c < 6; ++c) spans[c] = h.f[c];
  for (auto _ : state) {
    auto result = hydrocoef::analyse_forced_oscillation(h.t, spans, motion, {.harmonics = harmonics});
    benchmark::DoNotOptimize(result);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(samples));
}

BENCHMARK(BM_HarmonicAnalysis)
    ->Args({1000000, 1, 1})
    ->Args({1000000, 1, 3})
    ->Args({1000000, 6, 1})
    ->Args({100000, 1, 1})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
