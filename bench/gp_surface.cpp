// Gaussian-process surfaces: one evaluation of a 2-D surface of 200 runs with
// and without its standard deviation (goal: <= 2 us with it), the fit with
// hyperparameter estimation, and suggesting 10 runs on it (goal: <= 1 s):
// the design alone, and `hydrocoef suggest`'s whole path (rounded keys, the
// mirror's fundamental domain, each run counted with its image).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "src/pipeline/next_runs.hpp"
#include "src/surface/gp_design.hpp"
#include "src/surface/gp_surface.hpp"

namespace {

struct Runs {
  std::vector<double> x, y;
};

Runs runs(std::size_t n) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Runs out;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = u(random), b = u(random);
    out.x.push_back(a), out.x.push_back(b);
    out.y.push_back(std::sin(3.0 * a) * std::cos(2.0 * b) + a * b);
  }
  return out;
}

const hydrocoef::GpSurface& surface() {
  static const hydrocoef::GpSurface gp = [] {
    const Runs r = runs(200);
    return hydrocoef::GpSurface::fit(r.x, 2, r.y, {}, {.starts = 3});
  }();
  return gp;
}

void BM_GpEvaluate(benchmark::State& state) {
  const auto& gp = surface();
  hydrocoef::GpSurface::Workspace ws(gp);
  const bool with_sd = state.range(0) != 0;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> points(2 * 1024);
  for (auto& p : points) p = u(random);
  std::size_t i = 0;
  for (auto _ : state) {
    double sd = 0.0;
    const double mean = gp.evaluate(&points[2 * (i++ & 1023)], ws, with_sd ? &sd : nullptr);
    benchmark::DoNotOptimize(mean);
    benchmark::DoNotOptimize(sd);
  }
  state.SetLabel(with_sd ? "mean and standard deviation" : "mean");
}
BENCHMARK(BM_GpEvaluate)->Arg(0)->Arg(1);

void BM_GpFit(benchmark::State& state) {
  const Runs r = runs(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    auto gp = hydrocoef::GpSurface::fit(r.x, 2, r.y, {}, {.starts = 3});
    benchmark::DoNotOptimize(gp);
  }
}
BENCHMARK(BM_GpFit)->Arg(50)->Arg(200)->Unit(benchmark::kMillisecond);

void BM_GpSuggest(benchmark::State& state) {
  const auto& gp = surface();
  for (auto _ : state) {
    auto suggested = hydrocoef::suggest_gp_runs(gp, {-1.0, -1.0}, {1.0, 1.0}, 10);
    benchmark::DoNotOptimize(suggested);
  }
}
BENCHMARK(BM_GpSuggest)->Unit(benchmark::kMillisecond);

void BM_SuggestRoundedMirroredKeys(benchmark::State& state) {
  using hydrocoef::RbfOutOfRange;
  const hydrocoef::CoefficientSurface gp(hydrocoef::GpSurfaces({surface()}, {-1.0, -1.0}, {1.0, 1.0}, {"u", "v"},
                                                               {RbfOutOfRange::Error, RbfOutOfRange::Error}),
                                         {"u", "v"}, {"X"});
  hydrocoef::NextRunsRequest request;
  request.count = 10;
  request.mirror = hydrocoef::make_mirror_spec({"v"}, {});
  for (auto _ : state) {
    auto next = hydrocoef::suggest_next_runs(gp, request);
    benchmark::DoNotOptimize(next);
  }
}
BENCHMARK(BM_SuggestRoundedMirroredKeys)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
