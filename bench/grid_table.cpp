// Single-point GridTable queries, the way a dynamics model calls them: one
// point per call, at random points in random order (a precomputed array of
// 4096 points, cycled through), so neither the branch predictor nor the cache
// sees a pattern a real trajectory would not give. Tables: 2-D 20 x 20 (u, r,
// evenly spaced, and an unevenly spaced variant that takes the binary search)
// and 4-D 10 x 10 x 10 x 10, for every method, with one output and with six
// (X, Y, Z, K, M, N) evaluated at once. One iteration is one query: the time
// reported is ns per query.
//
// Goals (Release): 2-D linear <= 20 ns, 2-D pchip <= 60 ns, six outputs at
// once <= 2x one output.
#include "src/surface/grid_table.hpp"

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <random>
#include <string>
#include <vector>

namespace {

using hydrocoef::GridAxis;
using hydrocoef::GridTable;
using hydrocoef::Interpolation;

constexpr std::size_t kQueries = 4096;  // a power of two: the cycle is a mask

std::vector<double> breakpoints(double lo, double hi, std::size_t count, bool even) {
  std::vector<double> x(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double s = static_cast<double>(i) / static_cast<double>(count - 1);
    // Uneven: denser near lo, as CFD campaigns often are near zero speed.
    x[i] = lo + (hi - lo) * (even ? s : s * (0.5 + 0.5 * s));
  }
  return x;
}

struct Setup {
  GridTable table;
  std::vector<double> points;  // kQueries x axis_count
};

Setup make_setup(std::size_t axes, std::size_t count, std::size_t outputs, Interpolation method, bool even) {
  const std::array<const char*, 4> names = {"u", "v", "r", "delta"};
  std::vector<GridAxis> grid;
  std::size_t nodes = 1;
  for (std::size_t a = 0; a < axes; ++a) {
    grid.push_back({names[a], breakpoints(-1.0, 1.0 + 0.5 * static_cast<double>(a), count, even)});
    nodes *= count;
  }
  std::vector<std::string> output_names;
  for (std::size_t k = 0; k < outputs; ++k) output_names.push_back("C" + std::to_string(k));
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<double> values(nodes * outputs);
  for (double& v : values) v = value(rng);
  std::vector<double> points(kQueries * axes);
  for (std::size_t q = 0; q < kQueries; ++q) {
    for (std::size_t a = 0; a < axes; ++a) {
      points[q * axes + a] =
          std::uniform_real_distribution<double>(grid[a].breakpoints.front(), grid[a].breakpoints.back())(rng);
    }
  }
  return {GridTable(std::move(grid), std::move(output_names), std::move(values), method), std::move(points)};
}

void query(benchmark::State& state, std::size_t axes, std::size_t count, std::size_t outputs, Interpolation method,
           bool even, bool gradient) {
  const Setup setup = make_setup(axes, count, outputs, method, even);
  std::vector<double> out(outputs);
  std::vector<double> grad(outputs * axes);
  std::size_t q = 0;
  for (auto _ : state) {
    (void)_;
    const std::span<const double> point(setup.points.data() + q * axes, axes);
    if (gradient) {
      setup.table.evaluate_with_gradient(point, out, grad);
      benchmark::DoNotOptimize(grad.data());
    } else {
      setup.table.evaluate(point, out);
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
    q = (q + 1) & (kQueries - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

void register_all() {
  const std::array<Interpolation, 5> methods = {Interpolation::Nearest, Interpolation::Linear, Interpolation::Pchip,
                                                Interpolation::Akima, Interpolation::NaturalSpline};
  struct Shape {
    const char* name;
    std::size_t axes;
    std::size_t count;
    bool even;
  };
  const std::array<Shape, 3> shapes = {Shape{"2D_20x20", 2, 20, true}, Shape{"2D_20x20_uneven", 2, 20, false},
                                       Shape{"4D_10^4", 4, 10, true}};
  for (const Shape& shape : shapes) {
    for (Interpolation method : methods) {
      for (std::size_t outputs : {std::size_t{1}, std::size_t{6}}) {
        const std::string name = std::string("GridTable/") + shape.name + "/" +
                                 std::string(hydrocoef::interpolation_name(method)) + "/" + std::to_string(outputs) +
                                 "out";
        benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
          query(state, shape.axes, shape.count, outputs, method, shape.even, false);
        });
      }
    }
  }
  // The gradient costs (axes + 1) sums; shown for the common cases.
  for (Interpolation method : {Interpolation::Linear, Interpolation::Pchip}) {
    for (const Shape& shape : {shapes[0], shapes[2]}) {
      const std::string name = std::string("GridTableGradient/") + shape.name + "/" +
                               std::string(hydrocoef::interpolation_name(method)) + "/6out";
      benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
        query(state, shape.axes, shape.count, 6, method, shape.even, true);
      });
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
