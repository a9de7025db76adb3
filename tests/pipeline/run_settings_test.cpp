// Settings from several sources: precedence, the velocity taken whole from
// one source, one frame for the key whatever source each setting came from,
// provenance, and the refusals of a malformed sidecar.
#include "src/pipeline/run_settings.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "src/core/error.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using json = nlohmann::json;

SettingsLayer layer(SettingSource source, const std::string& where, const json& values) {
  return settings_from_json(values, SettingOrigin{source, where});
}

TEST(RunSettings, HigherPrecedenceWinsAndRemembersItsSource) {
  const auto merged = merge_settings({
      layer(SettingSource::CommandLine, "command line", {{"rho", 1000.0}}),
      layer(SettingSource::FileSidecar, "a.vtp.json", {{"rho", 998.0}, {"nu", 1e-6}}),
      layer(SettingSource::FolderSidecar, "hydrocoef-run.json", {{"nu", 2e-6}, {"body", "sphere"}}),
      layer(SettingSource::CaseFiles, "case/constant/transportProperties", {{"nu", 3e-6}, {"p_ref", 5.0}}),
  });
  EXPECT_EQ(merged.number("rho"), 1000.0);
  EXPECT_EQ(merged.find("rho")->origin.source, SettingSource::CommandLine);
  EXPECT_EQ(merged.number("nu"), 1e-6);
  EXPECT_EQ(merged.find("nu")->origin.where, "a.vtp.json");
  EXPECT_EQ(merged.text("body"), "sphere");
  EXPECT_EQ(merged.find("body")->origin.source, SettingSource::FolderSidecar);
  EXPECT_EQ(merged.number("p_ref"), 5.0);
  EXPECT_EQ(merged.number("absent"), std::nullopt);
  const json provenance = merged.provenance_json();
  EXPECT_EQ(provenance["nu"]["source"], "sidecar");
  EXPECT_EQ(provenance["p_ref"]["where"], "case/constant/transportProperties");
}

TEST(RunSettings, TheTranslationComesWholeFromOneSource) {
  // The case's free stream is overridden by a sidecar that states u alone:
  // v must not come from the case's flow.
  const auto merged = merge_settings({
      layer(SettingSource::FileSidecar, "a.json", {{"u", 0.3}}),
      layer(SettingSource::CaseFiles, "case/0/U", {{"flow", {0.1, 0.05, 0.0}}, {"r", 0.2}}),
  });
  const RunKey key = resolve_key(merged, resolve_frame(merged), "vehicle");
  EXPECT_EQ(key.nu_b[0], 0.3);
  EXPECT_EQ(key.nu_b[1], 0.0);
  EXPECT_EQ(key.nu_b[5], 0.2);  // rotation is not part of the group
}

TEST(RunSettings, EveryPlaceOfFlowAxesAndBodyGivesTheSameRun) {
  // The bug this guards against: flow in a sidecar and --axes on the command
  // line turned the velocity with the sidecar's (absent) axes and the forces
  // with the command line's, storing u = -0.2 with the drag along the motion.
  const std::vector<std::pair<SettingSource, std::string>> places = {
      {SettingSource::CommandLine, "command line"}, {SettingSource::FileSidecar, "a.vtp.json"},
      {SettingSource::Manifest, "sweep.csv:2"},     {SettingSource::FolderSidecar, "hydrocoef-run.json"},
      {SettingSource::CaseFiles, "case/0/U"},       {SettingSource::NamePattern, "u{u}"}};
  for (const auto& flow_at : places) {
    for (const auto& axes_at : places) {
      for (const auto& body_at : places) {
        std::map<SettingSource, json> values;
        values[flow_at.first]["flow"] = {0.2, 0.05, 0.0};
        values[axes_at.first]["axes"] = "-x,y,-z";
        values[body_at.first]["body"] = "sphere";
        std::vector<SettingsLayer> layers;
        for (const auto& [source, where] : places)
          if (values.count(source)) layers.push_back(layer(source, where, values[source]));
        const auto merged = merge_settings(layers);
        const FrameTransform frame = resolve_frame(merged);
        const RunKey key = resolve_key(merged, frame, "vehicle");
        SCOPED_TRACE(std::string(setting_source_name(flow_at.first)) + " / " +
                     std::string(setting_source_name(axes_at.first)) + " / " +
                     std::string(setting_source_name(body_at.first)));
        // Stream along +x (CFD) and body x = -CFD x: the body moves forward.
        EXPECT_EQ(key.body, "sphere");
        EXPECT_DOUBLE_EQ(key.nu_b[0], 0.2);
        EXPECT_DOUBLE_EQ(key.nu_b[1], -0.05);
        EXPECT_EQ(key.nu_b[2], 0.0);
        // The same frame rotates the drag (along +x in CFD axes) to -X: against the motion.
        EXPECT_DOUBLE_EQ(frame.vector_to_body({0.342, 0, 0})[0], -0.342);
      }
    }
  }
}

TEST(RunSettings, FlowAndUFromOneSourceAreRefused) {
  const auto merged = merge_settings({layer(SettingSource::FileSidecar, "a.json", {{"flow", {1, 0, 0}}, {"u", 1.0}})});
  EXPECT_THROW(resolve_key(merged, resolve_frame(merged), "vehicle"), InputError);
}

TEST(RunSettings, ReferencePointFromTheSolversCentre) {
  const auto merged = merge_settings(
      {layer(SettingSource::CaseFiles, "case/system/controlDict", {{"cofr", {1.0, 2.0, 3.0}}, {"axes", "-x,y,-z"}})});
  const Vec3 point = resolve_reference_point(merged, resolve_frame(merged));
  EXPECT_EQ(point, (Vec3{-1.0, 2.0, -3.0}));
  const auto given = merge_settings({layer(SettingSource::CommandLine, "command line", {{"ref_point", {0, 0, 0.1}}}),
                                     layer(SettingSource::CaseFiles, "controlDict", {{"cofr", {1.0, 2.0, 3.0}}})});
  EXPECT_EQ(resolve_reference_point(given, resolve_frame(given)), (Vec3{0, 0, 0.1}));
}

TEST(RunSettings, DisturbancesAndEffectiveText) {
  const auto merged = merge_settings({
      layer(SettingSource::CommandLine, "command line", {{"disturbances", {{"current_v", 0.05}}}}),
      layer(SettingSource::FolderSidecar, "f.json",
            {{"disturbances", {{"current_v", 0.1}, {"wave_h", 0.2}}}, {"rho", 998.2}}),
  });
  EXPECT_EQ(merged.disturbances(), (std::map<std::string, double>{{"current_v", 0.05}, {"wave_h", 0.2}}));
  EXPECT_EQ(merged.effective_text(), R"({"disturbance.current_v":0.05,"disturbance.wave_h":0.2,"rho":998.2})");
}

TEST(RunSettings, MalformedSidecarsAreRefusedNamingFileAndKey) {
  const auto refused = [](const json& values) {
    try {
      settings_from_json(values, SettingOrigin{SettingSource::FileSidecar, "a.vtp.json"});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refused({{"rh0", 1.0}}).find("a.vtp.json: unknown key 'rh0'"), std::string::npos);
  EXPECT_NE(refused({{"rho", "998"}}).find("key 'rho': expected a number"), std::string::npos);
  EXPECT_NE(refused({{"flow", {1, 2}}}).find("key 'flow': expected an array of three numbers"), std::string::npos);
  EXPECT_NE(refused({{"body", "a\nb"}}).find("body name"), std::string::npos);
  EXPECT_NE(refused({{"disturbances", {{"a=1;b", 2.0}}}}).find("parameter name"), std::string::npos);
  EXPECT_NE(refused({{"disturbances", {{"u", 2.0}}}}).find("velocity component"), std::string::npos);
  EXPECT_NE(refused(json::array()).find("expected a JSON object"), std::string::npos);
}

TEST(RunSettings, SettingsFilesAreReadAndBounded) {
  test::TempDir dir;
  {
    std::ofstream(dir / "ok.json") << R"({"body": "sphere", "rho": 998.2, "axes": "-x,y,-z"})";
    std::ofstream(dir / "bad.json") << R"({"rho": )";
    std::ofstream big(dir / "big.json");
    big << "{\"body\": \"" << std::string(2 << 20, 'x') << "\"}";
  }
  const auto ok = read_settings_file(dir / "ok.json", SettingSource::FolderSidecar);
  EXPECT_EQ(ok.values.at("rho").origin.source, SettingSource::FolderSidecar);
  EXPECT_EQ(ok.values.at("rho").origin.where, (dir / "ok.json").string());
  EXPECT_THROW(read_settings_file(dir / "bad.json", SettingSource::FileSidecar), InputError);
  EXPECT_THROW(read_settings_file(dir / "big.json", SettingSource::FileSidecar), InputError);
  EXPECT_THROW(read_settings_file(dir / "none.json", SettingSource::FileSidecar), InputError);
}

}  // namespace
}  // namespace hydrocoef
