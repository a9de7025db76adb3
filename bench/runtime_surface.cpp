// libhydrocoef_runtime's surfaces: one evaluation of six outputs on a 4-D
// PCHIP surface (10 x 10 x 10 x 10 nodes) through the C API
// (hc_runtime_evaluate), values alone and with gradients and sigma; and
// opening a runtime file of 10^6 nodes from disk (hc_runtime_open: read,
// size, count, breakpoint and NaN checks, the XXH64 of the whole file), for a
// linear 2-D table (1000 x 1000, one output: 8 MB) and a PCHIP 3-D table
// (100^3, one output: its value and 7 mixed derivatives a node, 64 MB).
// Goals (issue 37): <= 300 ns an evaluation; <= 50 ms to load 10^6 nodes.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "hydrocoef/runtime.h"
#include "src/export/runtime_export.hpp"
#include "src/surface/coefficient_surface.hpp"
#include "src/surface/grid_table.hpp"

namespace hydrocoef {
namespace {

struct Closer {
  void operator()(hc_runtime_model* model) const { hc_runtime_close(model); }
};
using Runtime = std::unique_ptr<hc_runtime_model, Closer>;

// A smooth table over `axes` axes of `count` even breakpoints on [-1, 1].
GridTable smooth_table(std::size_t axes, std::size_t count, std::size_t outputs, Interpolation method) {
  std::vector<GridAxis> grid;
  const char* names[] = {"u", "v", "w", "r"};
  for (std::size_t a = 0; a < axes; ++a) {
    std::vector<double> b(count);
    for (std::size_t i = 0; i < count; ++i) b[i] = -1.0 + 2.0 * static_cast<double>(i) / static_cast<double>(count - 1);
    grid.push_back({names[a], b, Extrapolation::Clamp});
  }
  std::size_t nodes = 1;
  for (std::size_t a = 0; a < axes; ++a) nodes *= count;
  std::vector<double> values(nodes * outputs);
  for (std::size_t n = 0; n < nodes; ++n) {
    double sum = 0.0;
    std::size_t rest = n;
    for (std::size_t a = 0; a < axes; ++a) {
      const double x = grid[a].breakpoints[rest % count];
      rest /= count;
      sum += (0.5 + static_cast<double>(a)) * x * std::abs(x);
    }
    for (std::size_t k = 0; k < outputs; ++k) values[n * outputs + k] = sum / static_cast<double>(k + 1);
  }
  std::vector<std::string> output_names;
  for (std::size_t k = 0; k < outputs; ++k) output_names.push_back("F" + std::to_string(k));
  return GridTable(std::move(grid), std::move(output_names), std::move(values), method);
}

std::string runtime_bytes(const GridTable& table) {
  const CoefficientSurface surface(table);
  return runtime_file_bytes(runtime_model_texts({}), {runtime_surface("s", surface, {})});
}

Runtime open_memory(const std::string& bytes) {
  hc_runtime_model* model = nullptr;
  char err[256];
  if (hc_runtime_open_memory(bytes.data(), bytes.size(), &model, err, sizeof err) != HC_RUNTIME_OK)
    throw std::runtime_error(err);
  return Runtime(model);
}

void evaluate(benchmark::State& state, bool with_gradients) {
  const GridTable table = smooth_table(4, 10, 6, Interpolation::Pchip);
  const Runtime model = open_memory(runtime_bytes(table));
  constexpr std::size_t kPoints = 1024;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> points(kPoints * 4);
  for (double& p : points) p = u(rng);
  double values[6], gradients[24];
  std::size_t q = 0;
  for (auto _ : state) {
    const int status = hc_runtime_evaluate(model.get(), 0, points.data() + 4 * q, values,
                                           with_gradients ? gradients : nullptr, nullptr);
    benchmark::DoNotOptimize(status);
    benchmark::DoNotOptimize(values);
    q = (q + 1) & (kPoints - 1);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

void BM_RuntimeEvaluate4DPchipSixOutputs(benchmark::State& state) { evaluate(state, false); }
void BM_RuntimeEvaluate4DPchipSixOutputsWithGradients(benchmark::State& state) { evaluate(state, true); }

// Opening a file of 10^6 nodes from disk (the page cache after the first run).
void load(benchmark::State& state, std::size_t axes, std::size_t count, Interpolation method) {
  const std::string bytes = runtime_bytes(smooth_table(axes, count, 1, method));
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("hydrocoef_bench_runtime_" + std::to_string(axes) + ".hcrt");
  {
    std::ofstream out(file, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  for (auto _ : state) {
    hc_runtime_model* model = nullptr;
    char err[256];
    if (hc_runtime_open(file.c_str(), &model, err, sizeof err) != HC_RUNTIME_OK) {
      state.SkipWithError(err);
      break;
    }
    hc_runtime_close(model);
  }
  std::filesystem::remove(file);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(bytes.size()));
  state.counters["file_MB"] = static_cast<double>(bytes.size()) / 1e6;
}

void BM_RuntimeOpenMillionNodesLinear2D(benchmark::State& state) { load(state, 2, 1000, Interpolation::Linear); }
void BM_RuntimeOpenMillionNodesPchip3D(benchmark::State& state) { load(state, 3, 100, Interpolation::Pchip); }

}  // namespace
}  // namespace hydrocoef

BENCHMARK(hydrocoef::BM_RuntimeEvaluate4DPchipSixOutputs);
BENCHMARK(hydrocoef::BM_RuntimeEvaluate4DPchipSixOutputsWithGradients);
BENCHMARK(hydrocoef::BM_RuntimeOpenMillionNodesLinear2D)->Unit(benchmark::kMillisecond);
BENCHMARK(hydrocoef::BM_RuntimeOpenMillionNodesPchip3D)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
