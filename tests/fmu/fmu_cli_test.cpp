// `hydrocoef export-fmu BODY --surface NAME -o FILE.fmu`: --help names the
// options; the text and --json reports state the variables, identifier and
// GUID of the file written, and hydrocoef::export_fmu (the C++ API) states
// the same variables; bad input is one line on stderr naming what was wrong,
// exit code 2, no file written and the database byte-identical.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "hydrocoef/fmu.hpp"
#include "tests/fmu/fmi_host.hpp"
#include "tests/fmu/fmu_test_database.hpp"

namespace hydrocoef {
namespace {

using test::run_cli;
using test::TempDir;

TEST(FmuCli, HelpNamesTheOptions) {
  TempDir dir;
  const auto help = run_cli({"export-fmu", "--help"}, dir.path());
  ASSERT_EQ(help.exit_code, 0) << help.err;
  for (const std::string option : {"--surface", "-o,--output", "--json", "FMI 2.0 Co-Simulation"})
    EXPECT_NE(help.out.find(option), std::string::npos) << option;
  const auto top = run_cli({"--help"}, dir.path());
  EXPECT_NE(top.out.find("export-fmu"), std::string::npos);
}

TEST(FmuCli, ReportsWhatItWroteAsTheApiDoes) {
  TempDir dir;
  test::make_fmu_database(dir);
  const auto json_run = run_cli({"export-fmu", "asr-v", "--surface", "surge", "-o", "surge.fmu", "--json"}, dir.path());
  ASSERT_EQ(json_run.exit_code, 0) << json_run.err;
  const auto report = nlohmann::json::parse(json_run.out);
  EXPECT_EQ(report.at("file"), "surge.fmu");
  EXPECT_EQ(report.at("kind"), "surface");
  EXPECT_EQ(report.at("fmi_version"), "2.0");
  EXPECT_EQ(report.at("model_identifier"), "hc_surge");
  const std::string fmu = test::read_text(dir / "surge.fmu");
  EXPECT_EQ(report.at("fmu_bytes").get<std::size_t>(), fmu.size());
  const auto files = test::unzip_stored(fmu);
  EXPECT_EQ(report.at("binary_bytes").get<std::size_t>(), files.at("binaries/linux64/hc_surge.so").size());
  EXPECT_EQ(report.at("runtime_file_bytes").get<std::size_t>(), files.at("resources/model.hcr").size());
  const auto md = test::read_model_description(files.at("modelDescription.xml"));
  EXPECT_EQ(report.at("guid"), md.guid);
  ASSERT_EQ(report.at("variables").size(), 3u);
  EXPECT_EQ(report.at("variables")[0].at("name"), "u");
  EXPECT_EQ(report.at("variables")[0].at("causality"), "input");
  EXPECT_EQ(report.at("variables")[0].at("start"), 0.0);
  EXPECT_EQ(report.at("variables")[2].at("name"), "sigma(X)");

  const auto text = run_cli({"export-fmu", "asr-v", "--surface", "surge", "-o", "again.fmu"}, dir.path());
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("exported surface surge of body asr-v as an FMI 2.0 Co-Simulation FMU"), std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("input  0 u [m/s], start 0"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("output 2 sigma(X) [N]"), std::string::npos) << text.out;

  // The C++ API: the same variables (the GUID differs: each export states its time).
  const auto db = Database::open((dir / "hydrocoef.db").string(), OpenMode::ReadOnly);
  const auto result = export_fmu(db, {.body = "asr-v", .surface = "surge", .output = (dir / "api.fmu").string()});
  const auto api = nlohmann::json::parse(result.json());
  EXPECT_EQ(api.at("variables"), report.at("variables"));
  EXPECT_EQ(api.at("model_identifier"), report.at("model_identifier"));
  EXPECT_EQ(api.at("binary_bytes"), report.at("binary_bytes"));
  EXPECT_EQ(result.fmu_bytes, test::read_text(dir / "api.fmu").size());
}

TEST(FmuCli, BadInputIsOneLineExitTwoNothingWritten) {
  TempDir dir;
  test::make_fmu_database(dir);
  const auto gp = run_cli({"surface", "build", "gp", "--body", "asr-v", "--outputs", "X", "--axes", "u", "--method",
                           "gp", "--starts", "2", "--extrapolate", "clamp"},
                          dir.path());
  ASSERT_EQ(gp.exit_code, 0) << gp.err;
  const std::string before = test::read_text(dir / "hydrocoef.db");
  const struct {
    std::vector<std::string> args;
    std::string expected;
  } cases[] = {
      {{"export-fmu", "asr-v", "--surface", "nope", "-o", "x.fmu"}, "nope"},
      {{"export-fmu", "grid", "--surface", "surge", "-o", "x.fmu"}, "belongs to body 'asr-v'"},
      {{"export-fmu", "asr-v", "--surface", "surge", "-o", "x.zip"}, "does not end in .fmu"},
      {{"export-fmu", "asr-v", "--surface", "gp", "-o", "x.fmu"}, "--resample"},
      {{"export-fmu", "asr-v", "--surface", "surge", "-o", "no/such/dir/x.fmu"}, "no/such/dir"},
      {{"export-fmu", "asr-v", "-o", "x.fmu"}, "--surface"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.expected);
    const auto result = run_cli(c.args, dir.path());
    EXPECT_EQ(result.exit_code, 2) << result.out;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_NE(result.err.find(c.expected), std::string::npos) << result.err;
    EXPECT_EQ(result.err.find("internal error"), std::string::npos) << result.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.fmu"));
    EXPECT_FALSE(std::filesystem::exists(dir / "x.zip"));
  }
  EXPECT_EQ(test::read_text(dir / "hydrocoef.db"), before);
  FmuExportOptions options{.body = "asr-v", .surface = "surge", .output = "x"};
  try {
    options.validate();
    ADD_FAILURE() << "validate accepted an output without .fmu";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("-o/--output 'x' does not end in .fmu"), std::string::npos);
  }
}

}  // namespace
}  // namespace hydrocoef
