// How fast a force history is read and reduced to a run.
//
//   BM_ReadOpenFoamForces        read_openfoam_forces on a generated
//                                postProcessing/forces/0 with force.dat and
//                                moment.dat of 10^6 time steps each, written
//                                as OpenFOAM v1912 writes them (the layout of
//                                data/openfoam-sphere: 18-wide time, three
//                                "(x y z)" groups of %.10e), about 180 MB per
//                                file; with the SHA-256 of both files (as an
//                                import needs) and without. Bytes/s counts
//                                both files (goal: >= 500 MB/s). The files
//                                are read from the page cache after the first
//                                iteration.
//   BM_ParseOpenFoamForceFile    parse_openfoam_force_file on one file in
//                                memory (no file reading, no digest), on
//                                every core (0) and on one thread (1).
//   BM_AnalyzeHistory/n          analyze_force_history (automatic MSER-5
//                                window, statistics of every component) on an
//                                AR(1) history with a start-up, six totals,
//                                n = 10^5, 10^6, 10^7 samples: the time per
//                                sample should not grow with n (O(n)).
//   BM_AnalyzeHistoryWithParts   the same at 10^6 samples with pressure and
//                                viscous parts (18 series), as an OpenFOAM
//                                history has.
//   BM_SeriesStatistics/n        series_statistics alone on one series,
//                                weakly (phi 0.5) and strongly (phi 0.995)
//                                correlated.
#include <benchmark/benchmark.h>
#include <stdlib.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "importers/openfoam_forces.hpp"
#include "src/history/history_analysis.hpp"
#include "src/history/statistics.hpp"

namespace {

namespace fs = std::filesystem;
using namespace hydrocoef;

constexpr std::size_t kSteps = 1000000;

// A smooth, noisy force: enough digits to cost what real ones cost.
std::string make_file(bool moment) {
  std::string text;
  text.reserve(185 * kSteps);
  text += moment ? "# Moment          \n" : "# Force           \n";
  text += "# CofR            : (0.0000000000e+00 0.0000000000e+00 0.0000000000e+00)\n#\n";
  text +=
      "# Time            \t(total_x total_y total_z)\t(pressure_x pressure_y pressure_z)\t(viscous_x viscous_y "
      "viscous_z)\n";
  std::mt19937_64 random(moment ? 2 : 1);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double scale = moment ? 1e-5 : 0.1;
  double e = 0.0;
  char line[256];
  for (std::size_t i = 1; i <= kSteps; ++i) {
    e = 0.9 * e + 0.05 * normal(random);
    const double p[3] = {scale * (0.8 + e), scale * (0.1 * e - 0.02), scale * (0.03 + 0.5 * e)};
    const double v[3] = {scale * 0.1 * (1 + 0.1 * e), scale * 1e-3 * e, -scale * 4e-3 * e};
    const int n =
        std::snprintf(line, sizeof line, "%-18zu\t(%.10e %.10e %.10e)\t(%.10e %.10e %.10e)\t(%.10e %.10e %.10e)\n", i,
                      p[0] + v[0], p[1] + v[1], p[2] + v[2], p[0], p[1], p[2], v[0], v[1], v[2]);
    text.append(line, static_cast<std::size_t>(n));
  }
  return text;
}

// The generated case, written once into a temporary folder and removed at exit.
struct GeneratedCase {
  fs::path root;
  std::uint64_t bytes = 0;
  GeneratedCase() {
    std::string pattern = (fs::temp_directory_path() / "hydrocoef-bench-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    root = pattern;
    fs::create_directories(root / "forces" / "0");
    for (const bool moment : {false, true}) {
      const std::string text = make_file(moment);
      std::ofstream(root / "forces" / "0" / (moment ? "moment.dat" : "force.dat"), std::ios::binary) << text;
      bytes += text.size();
    }
  }
  ~GeneratedCase() {
    std::error_code ec;
    fs::remove_all(root, ec);
  }
};

const GeneratedCase& generated() {
  static const GeneratedCase instance;
  return instance;
}

void BM_ReadOpenFoamForces(benchmark::State& state) {
  const GeneratedCase& files = generated();
  OpenFoamForcesOptions options;
  options.compute_sha256 = state.range(0) != 0;
  for (auto _ : state) {
    ForceHistory history = read_openfoam_forces(files.root / "forces", options);
    if (history.size() != kSteps) state.SkipWithError("wrong number of samples");
    benchmark::DoNotOptimize(history);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * files.bytes));
  state.counters["MB"] = static_cast<double>(files.bytes) / 1e6;
  state.SetLabel(options.compute_sha256 ? "with SHA-256" : "no digest");
}
BENCHMARK(BM_ReadOpenFoamForces)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->MinTime(3.0)->UseRealTime();

void BM_ParseOpenFoamForceFile(benchmark::State& state) {
  static const std::string text = make_file(false);
  OpenFoamForcesOptions options;
  options.threads = static_cast<unsigned>(state.range(0));
  for (auto _ : state) {
    ForceHistory history = parse_openfoam_force_file(text, "force.dat", options);
    benchmark::DoNotOptimize(history);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
  state.SetLabel(options.threads == 0 ? "every core" : "one thread");
}
BENCHMARK(BM_ParseOpenFoamForceFile)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(3.0)->UseRealTime();

ForceHistory synthetic_history(std::size_t n, bool parts) {
  ForceHistory h;
  h.abscissa = HistoryAbscissa::Time;
  h.abscissa_values.resize(n);
  for (std::size_t i = 0; i < n; ++i) h.abscissa_values[i] = 1e-3 * static_cast<double>(i + 1);
  std::mt19937_64 random(n);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (std::size_t c = 0; c < kHistoryComponents; ++c) {
    auto& total = h.values(ForcePart::Total, static_cast<HistoryComponent>(c));
    total.resize(n);
    double e = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      e = 0.8 * e + normal(random);
      total[i] = 1.0 + static_cast<double>(c) +
                 20.0 * std::exp(-static_cast<double>(i) / (0.01 * static_cast<double>(n))) + 0.1 * e;
    }
    if (parts) {
      auto& pressure = h.values(ForcePart::Pressure, static_cast<HistoryComponent>(c));
      auto& viscous = h.values(ForcePart::Viscous, static_cast<HistoryComponent>(c));
      pressure.resize(n);
      viscous.resize(n);
      for (std::size_t i = 0; i < n; ++i) {
        viscous[i] = 0.1 * total[i] + 1e-3 * normal(random);
        pressure[i] = total[i] - viscous[i];
      }
    }
  }
  return h;
}

void BM_AnalyzeHistory(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const ForceHistory history = synthetic_history(n, false);
  for (auto _ : state) {
    HistoryAnalysis analysis = analyze_force_history(history);
    benchmark::DoNotOptimize(analysis);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
  state.SetComplexityN(static_cast<std::int64_t>(n));
  state.counters["ns/sample"] = benchmark::Counter(
      static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_AnalyzeHistory)
    ->Arg(100000)
    ->Arg(1000000)
    ->Arg(10000000)
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oN)
    ->UseRealTime();

void BM_AnalyzeHistoryWithParts(benchmark::State& state) {
  const ForceHistory history = synthetic_history(kSteps, true);
  for (auto _ : state) {
    HistoryAnalysis analysis = analyze_force_history(history);
    benchmark::DoNotOptimize(analysis);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kSteps));
}
BENCHMARK(BM_AnalyzeHistoryWithParts)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SeriesStatistics(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const double phi = static_cast<double>(state.range(1)) / 1000.0;
  std::vector<double> x(n), t(n);
  std::mt19937_64 random(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  double e = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    e = phi * e + normal(random);
    x[i] = e;
    t[i] = static_cast<double>(i);
  }
  SeriesStatistics s;
  for (auto _ : state) {
    s = series_statistics(x, t);
    benchmark::DoNotOptimize(s);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
  state.SetComplexityN(static_cast<std::int64_t>(n));
  state.counters["tau"] = s.autocorrelation_time;
  state.counters["block"] = static_cast<double>(s.block_size);
}
BENCHMARK(BM_SeriesStatistics)
    ->ArgsProduct({{100000, 1000000, 10000000}, {500, 995}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
