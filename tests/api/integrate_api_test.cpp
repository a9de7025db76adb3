// integrate_surface (include/hydrocoef/integrate.hpp) against `hydrocoef
// integrate` on a real OpenFOAM sphere surface: the same text and JSON, the
// public fields the numbers the JSON prints, and options refused with the
// CLI's message.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "hydrocoef/hydrocoef.hpp"
#include "tests/support/api_errors.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace {

using hydrocoef::test::cli_error;
using hydrocoef::test::error_of;

using hydrocoef::test::run_cli;
using hydrocoef::test::TempDir;

const std::string kFile =
    std::string(HYDROCOEF_DATA_DIR) + "/openfoam-sphere/full/u0.10_v0.05/u0.10_v0.05_sphere_t1000.vtp";

TEST(IntegrateApi, GivesTheCliNumbers) {
  TempDir dir;
  hydrocoef::ImportOptions options;
  options.rho = 998.2;
  options.axes = "-x,-y,z";
  options.ref_point = "0,0,0.01";
  const hydrocoef::SurfaceIntegration result = hydrocoef::integrate_surface(kFile, options);
  const auto json = run_cli(
      {"integrate", kFile, "--rho", "998.2", "--axes", "-x,-y,z", "--ref-point", "0,0,0.01", "--json"}, dir.path());
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_EQ(result.json(), json.out);
  const auto text =
      run_cli({"integrate", kFile, "--rho", "998.2", "--axes", "-x,-y,z", "--ref-point", "0,0,0.01"}, dir.path());
  EXPECT_EQ(result.text(), text.out);
  const auto doc = nlohmann::json::parse(json.out);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(result.force[i], doc.at("force")[i].get<double>());
    EXPECT_EQ(result.moment[i], doc.at("moment")[i].get<double>());
    EXPECT_EQ(result.force[i], result.force_pressure[i] + result.force_viscous[i]);
  }
  EXPECT_EQ(result.area, doc.at("area").get<double>());
  EXPECT_TRUE(result.closed);
  // A closed sphere of radius 0.15 m (the shell of data/openfoam-sphere, discretised).
  EXPECT_NEAR(result.area, 4.0 * 3.141592653589793 * 0.15 * 0.15, 0.03 * 0.2827);
  // In the file's own axes the forces are OpenFOAM's own (its forces function object, case.json).
  hydrocoef::ImportOptions own;
  own.rho = 998.2;
  const auto in_cfd_axes = hydrocoef::integrate_surface(kFile, own);
  std::ifstream in(std::string(HYDROCOEF_DATA_DIR) + "/openfoam-sphere/full/u0.10_v0.05/case.json");
  const auto info = nlohmann::json::parse(in);
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_NEAR(in_cfd_axes.force[c], info["openfoam_final_force_N"]["total"][c].get<double>(), 2e-6);
    // -x,-y,z: body x and y are the CFD's reversed.
    EXPECT_DOUBLE_EQ(result.force[c], c < 2 ? -in_cfd_axes.force[c] : in_cfd_axes.force[c]);
  }
}

TEST(IntegrateApi, RefusesWithTheCliMessage) {
  TempDir dir;
  hydrocoef::ImportOptions options;
  options.rho = 998.2;
  options.ref_point = "1,2";
  EXPECT_EQ(error_of([&] { hydrocoef::integrate_surface(kFile, options); }) + "\n",
            run_cli({"integrate", kFile, "--rho", "998.2", "--ref-point", "1,2"}, dir.path())
                .err.substr(std::string("hydrocoef: error: ").size()));
  options.ref_point.reset();
  options.pressure = "NoSuchArray";
  EXPECT_EQ(error_of([&] { hydrocoef::integrate_surface(kFile, options); }) + "\n",
            run_cli({"integrate", kFile, "--rho", "998.2", "--pressure", "NoSuchArray"}, dir.path())
                .err.substr(std::string("hydrocoef: error: ").size()));
}

}  // namespace
