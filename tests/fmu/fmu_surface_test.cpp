// A surface FMU driven by the project's FMI host (tests/fmu/fmi_host.hpp):
// exported by `hydrocoef export-fmu`, instantiated, set up, initialised and
// stepped; at 10^3 random inputs per surface (inside and beyond the axes)
// its outputs and standard deviations equal, bit for bit, the runtime
// library's on the FMU's own resource file and the stored surface's as the
// library evaluates it, and at a few points `hydrocoef query --uncertainty
// --json`'s. The outputs are there in initialisation mode already, and a
// reset instance gives the same numbers again.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <random>
#include <span>
#include <thread>

#include "hydrocoef/runtime.h"
#include "src/store/database.hpp"
#include "src/surface/stored_surface.hpp"
#include "tests/fmu/fmi_host.hpp"
#include "tests/fmu/fmu_test_database.hpp"
#include "tests/support/same_bits.hpp"

namespace hydrocoef {
namespace {

using test::FmiHost;
using test::same_bits;
using test::TempDir;

struct ModelCloser {
  void operator()(hc_runtime_model* model) const { hc_runtime_close(model); }
};

struct Case {
  std::string body, surface;
  std::vector<std::pair<double, double>> ranges;  // per axis: random inputs drawn here
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.body << "/" << c.surface; }

class FmuSurface : public ::testing::TestWithParam<Case> {};

TEST_P(FmuSurface, StepsGiveTheRuntimeLibrarysAndQuerysNumbersBitForBit) {
  const Case& c = GetParam();
  TempDir dir;
  test::make_fmu_database(dir);
  test::export_fmu_file(dir, c.body, c.surface, "model.fmu");
  std::filesystem::create_directory(dir / "unzipped");
  FmiHost host(dir / "model.fmu", dir / "unzipped");
  const auto& model = host.model();
  const std::size_t n = c.ranges.size();

  hc_runtime_model* opened = nullptr;
  char err[512] = "";
  ASSERT_EQ(hc_runtime_open((dir / "unzipped/resources/model.hcr").c_str(), &opened, err, sizeof err), HC_RUNTIME_OK)
      << err;
  const std::unique_ptr<hc_runtime_model, ModelCloser> runtime(opened);
  ASSERT_EQ(hc_runtime_surface_count(opened), 1u);
  ASSERT_EQ(hc_runtime_axis_count(opened, 0), n);
  const std::size_t m = hc_runtime_output_count(opened, 0);
  ASSERT_EQ(hc_runtime_surface_has_sigma(opened, 0), 1);
  ASSERT_EQ(model.variables.size(), n + 2 * m);

  std::vector<fmi2ValueReference> inputs, outputs;
  for (std::size_t a = 0; a < n; ++a) {
    EXPECT_EQ(model.variables[a].causality, "input");
    EXPECT_EQ(model.variables[a].name, hc_runtime_axis_name(opened, 0, a));
    inputs.push_back(model.variables[a].value_reference);
  }
  for (std::size_t k = n; k < n + 2 * m; ++k) {
    EXPECT_EQ(model.variables[k].causality, "output");
    outputs.push_back(model.variables[k].value_reference);
  }

  RunDatabase database(dir / "hydrocoef.db");
  const StoredSurface stored = load_surface(database, c.surface);

  ASSERT_EQ(host.instantiate("surface"), fmi2OK);
  ASSERT_EQ(host.setup_experiment(0.0), fmi2OK);
  ASSERT_EQ(host.enter_initialization_mode(), fmi2OK);
  // In initialisation mode the outputs are those of the start values.
  std::vector<double> start, got;
  for (std::size_t a = 0; a < n; ++a) start.push_back(model.variables[a].start.value());
  ASSERT_EQ(host.get_real(outputs, got), fmi2OK);
  std::vector<double> values(m), sigma(m);
  ASSERT_EQ(hc_runtime_evaluate(opened, 0, start.data(), values.data(), nullptr, sigma.data()), HC_RUNTIME_OK);
  for (std::size_t k = 0; k < m; ++k) {
    EXPECT_TRUE(same_bits(got[k], values[k])) << got[k] << " " << values[k];
    EXPECT_TRUE(same_bits(got[m + k], sigma[k]));
  }
  ASSERT_EQ(host.exit_initialization_mode(), fmi2OK);
  // Each start value is 0 clamped into its axis's breakpoints.
  for (std::size_t a = 0; a < n; ++a) {
    std::size_t count = 0;
    const double* breakpoints = hc_runtime_axis_breakpoints(opened, 0, a, &count);
    EXPECT_EQ(start[a], std::min(std::max(0.0, breakpoints[0]), breakpoints[count - 1])) << a;
  }

  std::mt19937_64 random(371);
  std::vector<std::uniform_real_distribution<double>> draw;
  for (const auto& [low, high] : c.ranges) draw.emplace_back(low, high);
  double t = 0.0;
  const double h = 1e-3;
  std::vector<std::vector<double>> points;
  for (int i = 0; i < 1000; ++i) {
    std::vector<double> x(n);
    for (std::size_t a = 0; a < n; ++a) x[a] = draw[a](random);
    ASSERT_EQ(host.set_real(inputs, x), fmi2OK);
    ASSERT_EQ(host.do_step(t, h), fmi2OK) << (host.log().empty() ? "" : host.log().back().message);
    t += h;
    ASSERT_EQ(host.get_real(outputs, got), fmi2OK);
    ASSERT_EQ(hc_runtime_evaluate(opened, 0, x.data(), values.data(), nullptr, sigma.data()), HC_RUNTIME_OK);
    std::vector<double> library(m), library_sigma(m);
    stored.surface.evaluate_with_standard_deviation(std::span<const double>(x), library, library_sigma);
    for (std::size_t k = 0; k < m; ++k) {
      ASSERT_TRUE(same_bits(got[k], values[k]) && same_bits(got[m + k], sigma[k])) << "step " << i << " output " << k;
      ASSERT_TRUE(same_bits(got[k], library[k]) && same_bits(got[m + k], library_sigma[k]))
          << "step " << i << " output " << k;
    }
    if (i % 200 == 0) points.push_back(x);
    if (i % 200 == 0) points.push_back(got);
  }
  double last = 0.0;
  ASSERT_EQ(host.raw().GetRealStatus(host.component(), fmi2LastSuccessfulTime, &last), fmi2OK);
  EXPECT_DOUBLE_EQ(last, t);

  // `hydrocoef query --uncertainty --json` at some of those inputs.
  for (std::size_t p = 0; p < points.size(); p += 2) {
    std::vector<std::string> args{"query", c.surface};
    for (std::size_t a = 0; a < n; ++a) {
      char coordinate[64];
      std::snprintf(coordinate, sizeof coordinate, "%.17g", points[p][a]);
      args.push_back(model.variables[a].name + "=" + coordinate);
    }
    args.insert(args.end(), {"--uncertainty", "--json"});
    const auto queried = test::run_cli(args, dir.path());
    ASSERT_EQ(queried.exit_code, 0) << queried.err;
    const auto json = nlohmann::json::parse(queried.out);
    for (std::size_t k = 0; k < m; ++k) {
      const std::string name = model.variables[n + k].name;
      EXPECT_TRUE(same_bits(points[p + 1][k], json.at("values").at(name).get<double>())) << name;
      EXPECT_TRUE(same_bits(points[p + 1][m + k], json.at("standard_deviation").at(name).get<double>())) << name;
    }
  }

  ASSERT_EQ(host.terminate(), fmi2OK);
  // Reset: instantiated again with the start values; the same numbers after it.
  ASSERT_EQ(host.reset(), fmi2OK);
  ASSERT_EQ(host.setup_experiment(0.0), fmi2OK);
  ASSERT_EQ(host.enter_initialization_mode(), fmi2OK);
  ASSERT_EQ(host.set_real(inputs, points[0]), fmi2OK);
  ASSERT_EQ(host.exit_initialization_mode(), fmi2OK);
  ASSERT_EQ(host.get_real(outputs, got), fmi2OK);
  for (std::size_t k = 0; k < 2 * m; ++k) EXPECT_TRUE(same_bits(got[k], points[1][k])) << k;
  ASSERT_EQ(host.do_step(0.0, 0.5), fmi2OK);
  ASSERT_EQ(host.terminate(), fmi2OK);
  host.free_instance();
  for (const auto& entry : host.log()) EXPECT_NE(entry.status, fmi2Error) << entry.message;
}

// Instances are independent: four, each stepped in a thread of its own at
// inputs of its own, give the runtime library's numbers bit for bit (the
// live-instance list is shared and locked; nothing else is).
TEST(FmuSurfaceThreads, InstancesSteppedInThreadsAtOnceGiveTheirOwnNumbers) {
  TempDir dir;
  test::make_fmu_database(dir);
  test::export_fmu_file(dir, "grid", "grid", "grid.fmu");
  std::filesystem::create_directory(dir / "unzipped");
  FmiHost host(dir / "grid.fmu", dir / "unzipped");
  hc_runtime_model* opened = nullptr;
  char err[512] = "";
  ASSERT_EQ(hc_runtime_open((dir / "unzipped/resources/model.hcr").c_str(), &opened, err, sizeof err), HC_RUNTIME_OK)
      << err;
  const std::unique_ptr<hc_runtime_model, ModelCloser> runtime(opened);
  const auto& f = host.raw();
  const std::string uri = host.resource_uri(), guid = host.model().guid;
  std::vector<int> mismatches(4, -1);
  std::vector<std::thread> threads;
  for (int k = 0; k < 4; ++k) {
    threads.emplace_back([&, k] {
      const std::string name = "thread" + std::to_string(k);
      const fmi2Component c = f.Instantiate(name.c_str(), fmi2CoSimulation, guid.c_str(), uri.c_str(), host.callbacks(),
                                            fmi2False, fmi2False);
      if (c == nullptr || f.EnterInitializationMode(c) != fmi2OK || f.ExitInitializationMode(c) != fmi2OK) return;
      std::mt19937_64 random(1000 + k);
      std::uniform_real_distribution<double> u_of(-0.1, 0.6), v_of(-0.3, 0.3);
      const fmi2ValueReference in[2] = {0, 1}, out[4] = {2, 3, 4, 5};
      int bad = 0;
      double t = 0.0;
      for (int i = 0; i < 300; ++i) {
        const double x[2] = {u_of(random), v_of(random)};
        double got[4], values[2], sigma[2];
        if (f.SetReal(c, in, 2, x) != fmi2OK || f.DoStep(c, t, 0.01, fmi2True) != fmi2OK ||
            f.GetReal(c, out, 4, got) != fmi2OK ||
            hc_runtime_evaluate(opened, 0, x, values, nullptr, sigma) != HC_RUNTIME_OK) {
          ++bad;
          break;
        }
        t += 0.01;
        for (int o = 0; o < 2; ++o) bad += !same_bits(got[o], values[o]) + !same_bits(got[2 + o], sigma[o]);
      }
      f.FreeInstance(c);
      mismatches[k] = bad;
    });
  }
  for (auto& thread : threads) thread.join();
  EXPECT_EQ(mismatches, std::vector<int>(4, 0));
  EXPECT_TRUE(host.log().empty());
}

INSTANTIATE_TEST_SUITE_P(Surfaces, FmuSurface,
                         ::testing::Values(Case{"asr-v", "surge", {{-0.3, 0.8}}},
                                           Case{"grid", "grid", {{-0.1, 0.6}, {-0.3, 0.3}}},
                                           Case{"grid", "grid-high", {{0.0, 0.7}, {-0.3, 0.3}}}),
                         [](const auto& info) {
                           std::string name = info.param.surface;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace hydrocoef
