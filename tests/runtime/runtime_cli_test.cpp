// `hydrocoef export NAME --format runtime` end to end: the ASR-V surge runs
// imported, two surfaces built (pchip with linear extrapolation, linear with
// clamping), exported into one runtime file, opened through the C API: at
// points inside and beyond the axis the runtime's values, gradients and
// standard deviations are `hydrocoef query --gradient --uncertainty --json`'s
// and the stored surface's (10^4 points) bit for bit; the file states its
// provenance; what the file cannot hold is refused in one line, exit 2,
// nothing written.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "hydrocoef/exports.hpp"
#include "hydrocoef/runtime.h"
#include "src/api/vehicle_inputs.hpp"
#include "src/dynamics/scenario.hpp"
#include "src/store/database.hpp"
#include "src/surface/stored_surface.hpp"
#include "tests/runtime/runtime_stepping.hpp"
#include "tests/support/asr_v_example.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;
using test::same_bits;
using test::TempDir;

const std::string kSurge = HYDROCOEF_SOURCE_DIR "/examples/asr-v/asr-v-surge-damping.csv";

void make_database(const TempDir& dir) {
  auto imported = run_cli({"import", kSurge, "--body", "asr-v", "--sign", "opposing", "--rho", "998.2"}, dir.path());
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  for (const auto& [name, method, policy] :
       std::vector<std::array<std::string, 3>>{{"surge", "pchip", "linear"},
                                               {"surge_linear", "linear", "clamp"},
                                               {"surge_spline", "natural-spline", "method"}}) {
    auto built = run_cli({"surface", "build", name, "--body", "asr-v", "--outputs", "X", "--axes", "u", "--method",
                          method, "--extrapolate", policy},
                         dir.path());
    ASSERT_EQ(built.exit_code, 0) << built.err;
  }
}

struct ModelCloser {
  void operator()(hc_runtime_model* model) const { hc_runtime_close(model); }
};

TEST(RuntimeCli, ExportedFileEvaluatesWhatQueryAnswersBitForBit) {
  TempDir dir;
  make_database(dir);
  const auto exported = run_cli({"export", "surge", "--format", "runtime", "-o", "asr-v.hcrt", "--surface",
                                 "surge_linear", "--surface", "surge_spline", "--json"},
                                dir.path());
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  const auto report = nlohmann::json::parse(exported.out);
  EXPECT_EQ(report.at("format"), "runtime");
  EXPECT_EQ(report.at("surfaces"), nlohmann::json({"surge", "surge_linear", "surge_spline"}));
  EXPECT_EQ(report.at("files"), nlohmann::json({"asr-v.hcrt"}));

  hc_runtime_model* opened = nullptr;
  char err[512] = "";
  ASSERT_EQ(hc_runtime_open((dir / "asr-v.hcrt").c_str(), &opened, err, sizeof err), HC_RUNTIME_OK) << err;
  const std::unique_ptr<hc_runtime_model, ModelCloser> model(opened);
  ASSERT_EQ(hc_runtime_surface_count(opened), 3u);
  EXPECT_STREQ(hc_runtime_metadata(opened, "body"), "asr-v");
  EXPECT_STREQ(hc_runtime_metadata(opened, "surfaces"), "surge,surge_linear,surge_spline");
  EXPECT_NE(std::string(hc_runtime_metadata(opened, "database")).find("hydrocoef.db"), std::string::npos)
      << hc_runtime_metadata(opened, "database");
  EXPECT_NE(hc_runtime_metadata(opened, "created_at"), nullptr);
  EXPECT_EQ(std::string(hc_runtime_surface_metadata(opened, 0, "content_sha256")),
            report.at("content_sha256").get<std::string>());
  EXPECT_EQ(std::string(hc_runtime_surface_metadata(opened, 0, "runs")).size() > 10, true);
  EXPECT_STREQ(hc_runtime_surface_metadata(opened, 0, "stale"), "false");
  EXPECT_STREQ(hc_runtime_surface_metadata(opened, 0, "source"), "the stored grid table, as hydrocoef evaluates it");
  EXPECT_STREQ(hc_runtime_axis_unit(opened, 0, 0), "m/s");
  EXPECT_STREQ(hc_runtime_output_unit(opened, 0, 0), "N");
  EXPECT_STREQ(hc_runtime_axis_extrapolation(opened, 1, 0), "clamp");

  for (std::size_t s = 0; s < 3; ++s) {
    const std::string name = hc_runtime_surface_name(opened, s);
    ASSERT_EQ(hc_runtime_surface_has_sigma(opened, s), 1) << name;
    for (const double u : {-0.2, 0.0, 0.013, 0.1, 0.123456789, 0.25, 0.38, 0.45, 0.9}) {
      SCOPED_TRACE(name + " at u = " + std::to_string(u));
      const auto queried =
          run_cli({"query", name, "u=" + std::to_string(u), "--gradient", "--uncertainty", "--json"}, dir.path());
      ASSERT_EQ(queried.exit_code, 0) << queried.err;
      const auto json = nlohmann::json::parse(queried.out);
      const double x = json.at("point").at("u").get<double>();
      double value = 0.0, gradient = 0.0, sigma = 0.0;
      ASSERT_EQ(hc_runtime_evaluate(opened, s, &x, &value, &gradient, &sigma), HC_RUNTIME_OK);
      EXPECT_TRUE(same_bits(value, json.at("values").at("X").get<double>())) << value;
      EXPECT_TRUE(same_bits(gradient, json.at("gradient").at("X").at("u").get<double>())) << gradient;
      EXPECT_TRUE(same_bits(sigma, json.at("standard_deviation").at("X").get<double>())) << sigma;
    }
  }

  // 10^4 random points against the stored surfaces as the library loads them.
  RunDatabase database(dir / "hydrocoef.db");
  std::mt19937_64 random(37);
  std::uniform_real_distribution<double> u_of(-0.3, 0.8);
  for (std::size_t s = 0; s < 3; ++s) {
    const StoredSurface stored = load_surface(database, hc_runtime_surface_name(opened, s));
    for (int i = 0; i < 10000; ++i) {
      const double x = u_of(random);
      double value[1], gradient[1], sigma[1], r_value, r_gradient, r_sigma;
      stored.surface.evaluate_with_standard_deviation(std::span<const double>(&x, 1), value, sigma, gradient);
      ASSERT_EQ(hc_runtime_evaluate(opened, s, &x, &r_value, &r_gradient, &r_sigma), HC_RUNTIME_OK);
      ASSERT_TRUE(same_bits(value[0], r_value) && same_bits(gradient[0], r_gradient) && same_bits(sigma[0], r_sigma))
          << "surface " << s << " at u = " << x;
    }
  }
}

TEST(RuntimeCli, TheApiWritesWhatTheCliWritesAndValidatesAsItDoes) {
  TempDir dir;
  make_database(dir);
  ASSERT_EQ(
      run_cli({"export", "surge", "--format", "runtime", "-o", "cli.hcrt", "--surface", "surge_linear"}, dir.path())
          .exit_code,
      0);
  const auto db = Database::open((dir / "hydrocoef.db").string(), OpenMode::ReadOnly);
  TableExportOptions options;
  options.name = "surge";
  options.format = "runtime";
  options.output = (dir / "api.hcrt").string();
  options.surfaces = {"surge_linear"};
  const TableExportResult result = export_surface(db, options);
  EXPECT_EQ(result.surfaces, (std::vector<std::string>{"surge", "surge_linear"}));
  EXPECT_EQ(result.files, std::vector<std::string>{options.output});
  hc_runtime_model* from_cli = nullptr;
  hc_runtime_model* from_api = nullptr;
  ASSERT_EQ(hc_runtime_open((dir / "cli.hcrt").c_str(), &from_cli, nullptr, 0), HC_RUNTIME_OK);
  ASSERT_EQ(hc_runtime_open(options.output.c_str(), &from_api, nullptr, 0), HC_RUNTIME_OK);
  const std::unique_ptr<hc_runtime_model, ModelCloser> cli_model(from_cli), api_model(from_api);
  ASSERT_EQ(hc_runtime_surface_count(from_api), 2u);
  for (std::size_t s = 0; s < 2; ++s) {
    EXPECT_STREQ(hc_runtime_surface_metadata(from_api, s, "content_sha256"),
                 hc_runtime_surface_metadata(from_cli, s, "content_sha256"));
    for (const double u : {-0.1, 0.0, 0.2, 0.5}) {
      double a[3], b[3];
      ASSERT_EQ(hc_runtime_evaluate(from_cli, s, &u, &a[0], &a[1], &a[2]), HC_RUNTIME_OK);
      ASSERT_EQ(hc_runtime_evaluate(from_api, s, &u, &b[0], &b[1], &b[2]), HC_RUNTIME_OK);
      for (int k = 0; k < 3; ++k) EXPECT_TRUE(same_bits(a[k], b[k])) << "surface " << s << " u = " << u;
    }
  }
  options.format = "csv";
  try {
    options.validate();
    FAIL() << "--surface with csv was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "--surface applies to --format runtime only; expected it with runtime (got --format csv)");
  }
}

TEST(RuntimeCli, RefusalsAreOneLineAndWriteNothing) {
  TempDir dir;
  make_database(dir);
  const auto rbf =
      run_cli({"surface", "build", "surge_rbf", "--body", "asr-v", "--outputs", "X", "--axes", "u", "--method", "rbf"},
              dir.path());
  ASSERT_EQ(rbf.exit_code, 0) << rbf.err;
  const auto refused =
      run_cli({"export", "surge", "--format", "runtime", "-o", "m.hcrt", "--surface", "surge_rbf"}, dir.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("surface 'surge_rbf' is an RBF surface"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--resample"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "m.hcrt"));

  // Its tabulation on a grid (surface build --resample) is exported, and the file says so.
  const auto resampled = run_cli({"surface", "build", "surge_rbf_grid", "--body", "asr-v", "--outputs", "X", "--axes",
                                  "u", "--method", "rbf", "--resample", "u=0:0.38:12"},
                                 dir.path());
  ASSERT_EQ(resampled.exit_code, 0) << resampled.err;
  const auto tabulated = run_cli({"export", "surge_rbf_grid", "--format", "runtime", "-o", "grid.hcrt"}, dir.path());
  ASSERT_EQ(tabulated.exit_code, 0) << tabulated.err;
  hc_runtime_model* model = nullptr;
  ASSERT_EQ(hc_runtime_open((dir / "grid.hcrt").c_str(), &model, nullptr, 0), HC_RUNTIME_OK);
  const std::unique_ptr<hc_runtime_model, ModelCloser> closer(model);
  EXPECT_EQ(std::string(hc_runtime_surface_metadata(model, 0, "source"))
                .rfind("an RBF surface tabulated on a grid by surface build --resample (12 nodes, ", 0),
            0u)
      << hc_runtime_surface_metadata(model, 0, "source");
  const double u = 0.2;
  double value = 0.0;
  ASSERT_EQ(hc_runtime_evaluate(model, 0, &u, &value, nullptr, nullptr), HC_RUNTIME_OK);
  const auto queried = run_cli({"query", "surge_rbf_grid", "u=0.2", "--json"}, dir.path());
  EXPECT_TRUE(same_bits(value, nlohmann::json::parse(queried.out).at("values").at("X").get<double>()));

  const auto twice =
      run_cli({"export", "surge", "--format", "runtime", "-o", "m.hcrt", "--surface", "surge"}, dir.path());
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_NE(twice.err.find("surface 'surge' is given twice"), std::string::npos) << twice.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "m.hcrt"));

  const auto wrong_format =
      run_cli({"export", "surge", "--format", "csv", "-o", "m.csv", "--surface", "surge_linear"}, dir.path());
  EXPECT_EQ(wrong_format.exit_code, 2);
  EXPECT_NE(wrong_format.err.find("--surface applies to --format runtime only"), std::string::npos) << wrong_format.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "m.csv"));
}

// `export BODY --format runtime --vehicle VEHICLE.json`: the ASR-V vehicle
// with its surge damping from the stored surface "surge" (the others laws)
// resolved through the database as simulate resolves it; the runtime's
// derivative equals the model simulate builds, bit for bit. A vehicle file
// the library refuses, or --vehicle with another format, is refused in one
// line, exit 2, nothing written.
TEST(RuntimeCli, AVehicleIsExportedWithTheSurfacesItReads) {
  TempDir dir;
  make_database(dir);
  std::ifstream in(HYDROCOEF_SOURCE_DIR "/examples/asr-v/vehicle.json");
  std::string vehicle((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string law = R"("X": {"law": {"u": -0.0155, "u|u|": -11.0365}, "sign": "on-body"})";
  const auto at = vehicle.find(law);
  ASSERT_NE(at, std::string::npos);
  vehicle.replace(at, law.size(), R"("X": {"surface": "surge", "output": "X", "sign": "on-body"})");
  std::ofstream(dir / "vehicle.json") << vehicle;

  const auto exported =
      run_cli({"export", "asr-v", "--format", "runtime", "--vehicle", "vehicle.json", "-o", "asr-v.hcrt", "--json"},
              dir.path());
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  const auto report = nlohmann::json::parse(exported.out);
  EXPECT_EQ(report.at("surfaces"), nlohmann::json({"surge"}));
  EXPECT_EQ(report.at("vehicle"), "asr-v");
  hc_runtime_model* opened = nullptr;
  char err[512] = "";
  ASSERT_EQ(hc_runtime_open((dir / "asr-v.hcrt").c_str(), &opened, err, sizeof err), HC_RUNTIME_OK) << err;
  const std::unique_ptr<hc_runtime_model, ModelCloser> model(opened);
  ASSERT_EQ(hc_runtime_has_vehicle(opened), 1);
  EXPECT_STREQ(hc_runtime_metadata(opened, "body"), "asr-v");
  EXPECT_STREQ(hc_runtime_vehicle_metadata(opened, "file"), "vehicle.json");

  // The API writes the same vehicle section (the model section's created_at aside) and validates as the CLI.
  {
    const auto db = Database::open((dir / "hydrocoef.db").string(), OpenMode::ReadOnly);
    TableExportOptions options;
    options.name = "asr-v";
    options.format = "runtime";
    options.output = (dir / "api.hcrt").string();
    options.vehicle = (dir / "vehicle.json").string();
    const TableExportResult result = export_surface(db, options);
    EXPECT_EQ(result.vehicle, "asr-v");
    EXPECT_EQ(result.surfaces, std::vector<std::string>{"surge"});
    const auto read = [](const std::filesystem::path& path) {
      std::ifstream file(path, std::ios::binary);
      return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    };
    const auto u32 = [](const std::string& bytes, std::size_t at) {
      std::uint32_t value = 0;
      for (int i = 3; i >= 0; --i)
        value = value << 8 | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]);
      return value;
    };
    // The vehicle section past its texts (the vehicle file's path differs: relative for the CLI).
    const auto vehicle_numbers = [&](const std::string& bytes) {
      const std::size_t entry = 64 + 24 * (u32(bytes, 32) - 1);
      std::size_t at = u32(bytes, entry + 8) | static_cast<std::size_t>(u32(bytes, entry + 12)) << 32;
      const std::uint32_t pairs = u32(bytes, at);
      at += 8;
      for (std::uint32_t i = 0; i < 2 * pairs; ++i) at += (4 + u32(bytes, at) + 1 + 7) / 8 * 8;
      return bytes.substr(at);
    };
    const std::string from_cli = read(dir / "asr-v.hcrt"), from_api = read(options.output);
    EXPECT_GT(vehicle_numbers(from_cli).size(), 4 * 36 * 8u);
    EXPECT_EQ(vehicle_numbers(from_cli), vehicle_numbers(from_api));
    options.format = "csv";
    try {
      options.validate();
      FAIL() << "--vehicle with csv was accepted";
    } catch (const InputError& error) {
      EXPECT_EQ(std::string(error.what()),
                "--vehicle applies to --format runtime only; expected it with runtime (got --format csv)");
    }
  }
  const VehicleModel library = load_vehicle_model((dir / "vehicle.json").string(), (dir / "hydrocoef.db").string());
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::size_t mismatches = 0;
  for (int n = 0; n < 2000; ++n) {
    Vector6 nu;
    for (int i = 0; i < 6; ++i) nu[i] = 0.3 * unit(random);
    const StateVector x =
        make_state(Vector3::Zero(), Quaternion4(1.0, 0.1 * unit(random), 0.1 * unit(random), unit(random)), nu);
    ModelInputs inputs;
    inputs.tau_b[5] = 0.003 * unit(random);
    inputs.current_n = Vector3(0.05 * unit(random), 0.05 * unit(random), 0.0);
    StateVector expected;
    library.derivative(x, inputs, expected);
    double x_dot[13];
    ASSERT_EQ(hc_runtime_vehicle_derivative(opened, x.data(), inputs.tau_b.data(), inputs.current_n.data(), nullptr,
                                            x_dot, err, sizeof err),
              HC_RUNTIME_OK)
        << err;
    for (int i = 0; i < 13; ++i) mismatches += !same_bits(x_dot[i], expected[i]);
  }
  EXPECT_EQ(mismatches, 0u);

  // A vehicle file the library refuses: its one line, exit 2, nothing written.
  std::ofstream(dir / "bad.json") << R"({"mass": -1, "inertia": [1, 1, 1], "center_of_gravity": [0, 0, 0]})";
  const auto bad =
      run_cli({"export", "asr-v", "--format", "runtime", "--vehicle", "bad.json", "-o", "bad.hcrt"}, dir.path());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("bad.json"), std::string::npos) << bad.err;
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.hcrt"));
  // A surface the database lacks.
  std::string missing = vehicle;
  missing.replace(missing.find("\"surge\""), 7, "\"nosuch\"");
  std::ofstream(dir / "missing.json") << missing;
  const auto unknown =
      run_cli({"export", "asr-v", "--format", "runtime", "--vehicle", "missing.json", "-o", "bad.hcrt"}, dir.path());
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("nosuch"), std::string::npos) << unknown.err;
  EXPECT_EQ(std::count(unknown.err.begin(), unknown.err.end(), '\n'), 1) << unknown.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.hcrt"));
  // A surface of another body than the one named.
  const auto other =
      run_cli({"export", "sphere", "--format", "runtime", "--vehicle", "vehicle.json", "-o", "bad.hcrt"}, dir.path());
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("expected surfaces of body 'sphere'"), std::string::npos) << other.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.hcrt"));
  const auto wrong_format =
      run_cli({"export", "asr-v", "--format", "csv", "-o", "m.csv", "--vehicle", "vehicle.json"}, dir.path());
  EXPECT_EQ(wrong_format.exit_code, 2);
  EXPECT_NE(wrong_format.err.find("--vehicle applies to --format runtime only"), std::string::npos) << wrong_format.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "m.csv"));
}

// The ASR-V example as examples/asr-v/run.sh makes it: both tables imported,
// the surfaces asr-v-surge and asr-v-yaw built, and vehicle-surfaces.json
// exported with them; its pool test (a constant yaw torque, RK4 at 1 ms)
// stepped through the C API is simulate's trajectory bit for bit.
TEST(RuntimeCli, TheAsrVPoolTestWithItsSurfacesStepsAsSimulate) {
  TempDir dir;
  ASSERT_NO_FATAL_FAILURE(test::make_asr_v_example_database(dir));
  const std::string vehicle = HYDROCOEF_SOURCE_DIR "/examples/asr-v/vehicle-surfaces.json";
  const auto exported =
      run_cli({"export", "asr-v", "--format", "runtime", "--vehicle", vehicle, "-o", "asr-v.hcrt"}, dir.path());
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  EXPECT_NE(exported.out.find("exported vehicle asr-v (damping from lookup surfaces) of body asr-v (2 surfaces)"),
            std::string::npos)
      << exported.out;
  hc_runtime_model* opened = nullptr;
  char err[512] = "";
  ASSERT_EQ(hc_runtime_open((dir / "asr-v.hcrt").c_str(), &opened, err, sizeof err), HC_RUNTIME_OK) << err;
  const std::unique_ptr<hc_runtime_model, ModelCloser> model(opened);
  EXPECT_STREQ(hc_runtime_metadata(opened, "surfaces"), "asr-v-surge,asr-v-yaw");
  const VehicleModel library = load_vehicle_model(vehicle, (dir / "hydrocoef.db").string());
  Scenario scenario = load_scenario(HYDROCOEF_SOURCE_DIR "/examples/asr-v/scenario-yaw-0.0027.json");
  scenario.duration_s = 10.0;
  expect_simulate_bit_for_bit(library, opened, scenario);
}

}  // namespace
}  // namespace hydrocoef
