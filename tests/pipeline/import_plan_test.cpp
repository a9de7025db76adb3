// Planning an import on the real OpenFOAM sphere folders and on small trees:
// case folders found and not walked, twins and partner files reduced with a
// note, a history preferred to surfaces of the same run, filters, and the
// layers of settings each input gets, in order.
#include "src/pipeline/import_plan.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "src/core/error.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;
const fs::path kSphere = fs::path(HYDROCOEF_DATA_DIR) / "openfoam-sphere";

std::vector<std::string> names(const ImportPlan& plan) {
  std::vector<std::string> out;
  for (const auto& input : plan.inputs) out.push_back(input.relative.generic_string());
  return out;
}

TEST(ImportPlan, CaseFoldersAreInputsOfTheirOwn) {
  const NamePattern pattern("u{u}_v{v}");
  const ImportPlan plan = plan_import({kSphere / "cases"}, {.key_pattern = &pattern});
  EXPECT_EQ(names(plan), (std::vector<std::string>{"u0.10_v0.00", "u0.10_v0.05", "u0.20_v0.10", "u0.30_v0.00"}));
  for (const auto& input : plan.inputs) {
    EXPECT_EQ(input.kind, InputKind::OpenFoamCase);
    // The case's own files, then the name pattern (lower precedence).
    ASSERT_EQ(input.layers.size(), 2u);
    EXPECT_EQ(input.layers[0].origin.source, SettingSource::CaseFiles);
    EXPECT_EQ(input.layers[1].origin.source, SettingSource::NamePattern);
  }
  EXPECT_EQ(std::get<double>(plan.inputs[2].layers[1].values.at("v").value), 0.10);
  // A case folder named directly.
  const ImportPlan one = plan_import({kSphere / "cases" / "u0.10_v0.05"}, {});
  ASSERT_EQ(one.inputs.size(), 1u);
  EXPECT_EQ(one.inputs[0].kind, InputKind::OpenFoamCase);
}

TEST(ImportPlan, HistoriesAreTakenOverTheirSurfacesAndTwinsOnce) {
  const ImportPlan plan = plan_import({kSphere / "full"}, {});
  EXPECT_EQ(names(plan), (std::vector<std::string>{"u0.10_v0.00/force.dat", "u0.10_v0.05/force.dat",
                                                   "u0.20_v0.10/force.dat", "u0.30_v0.00/force.dat"}));
  ASSERT_FALSE(plan.notes.empty());
  EXPECT_NE(plan.notes[0].find("force.dat (force history) imported; "), std::string::npos) << plan.notes[0];
  EXPECT_NE(plan.notes[0].find("--prefer-surfaces"), std::string::npos) << plan.notes[0];

  const ImportPlan surfaces = plan_import({kSphere / "full"}, {.prefer_surfaces = true});
  EXPECT_EQ(names(surfaces),
            (std::vector<std::string>{
                "u0.10_v0.00/u0.10_v0.00_sphere_t1000.vtp", "u0.10_v0.05/u0.10_v0.05_sphere_t1000.vtp",
                "u0.20_v0.10/u0.20_v0.10_sphere_t1000.vtp", "u0.30_v0.00/u0.30_v0.00_sphere_t1000.vtp"}));
  bool twin_note = false;
  for (const auto& note : surfaces.notes)
    twin_note |= note.find("its twin u0.10_v0.00_sphere_t1000.vtk") != std::string::npos;
  EXPECT_TRUE(twin_note);
}

TEST(ImportPlan, FoamToVtkMultiblockGivesWayToItsBlocks) {
  const ImportPlan plan = plan_import({kSphere / "cases" / "u0.10_v0.00" / "VTK"}, {});
  EXPECT_EQ(names(plan), (std::vector<std::string>{"u0.10_v0.00_1000/boundary/sphere.vtp"}));
}

class ImportPlanTree : public ::testing::Test {
 protected:
  void write(const fs::path& relative, const std::string& text) {
    fs::create_directories((dir_ / relative.string()).parent_path());
    std::ofstream(dir_ / relative.string()) << text;
  }
  test::TempDir dir_;
};

TEST_F(ImportPlanTree, FiltersSelectFilesAndNamedFilesAlwaysCount) {
  write("runs/a.csv", "u,X\n");
  write("runs/b.csv", "u,X\n");
  write("runs/summary.csv", "x\n");
  write("runs/notes.md", "not data");
  const ImportPlan all = plan_import({dir_ / "runs"}, {});
  EXPECT_EQ(names(all), (std::vector<std::string>{"a.csv", "b.csv", "summary.csv"}));
  const ImportPlan some = plan_import({dir_ / "runs"}, {.exclude = {"summary*"}});
  EXPECT_EQ(names(some), (std::vector<std::string>{"a.csv", "b.csv"}));
  EXPECT_EQ(some.excluded, 1u);
  EXPECT_EQ(names(plan_import({dir_ / "runs"}, {.include = {"b.*"}})), (std::vector<std::string>{"b.csv"}));
  try {
    plan_import({dir_ / "runs"}, {.include = {"*.vtp"}});
    FAIL() << "an empty plan was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--include '*.vtp'"), std::string::npos) << e.what();
  }
  // A file named directly is imported whatever the filters.
  EXPECT_EQ(plan_import({dir_ / "runs" / "summary.csv"}, {.exclude = {"*"}}).inputs.size(), 1u);
  EXPECT_THROW(plan_import({dir_ / "none"}, {}), InputError);
}

TEST_F(ImportPlanTree, LayersComeInOrderOfPrecedence) {
  write("sweep/hydrocoef-run.json", R"({"rho": 998.2, "body": "hull"})");
  write("sweep/u0.2/hydrocoef-run.json", R"({"rho": 1000.0})");
  write("sweep/u0.2/run.vtp", "");
  write("sweep/u0.2/run.vtp.json", R"({"p_ref": 5.0})");
  write("sweep.csv", "path,nu\nsweep/u0.2/run.vtp,1e-6\n");
  const Manifest manifest = Manifest::read(dir_ / "sweep.csv");
  const NamePattern pattern("u{u}");
  const ImportPlan plan = plan_import({dir_ / "sweep"}, {.manifest = &manifest, .key_pattern = &pattern});
  ASSERT_EQ(plan.inputs.size(), 1u);
  const auto& layers = plan.inputs[0].layers;
  ASSERT_EQ(layers.size(), 5u);
  EXPECT_EQ(layers[0].origin.source, SettingSource::FileSidecar);
  EXPECT_EQ(layers[1].origin.source, SettingSource::Manifest);
  EXPECT_EQ(layers[2].origin.where, (dir_ / "sweep/u0.2/hydrocoef-run.json").string());
  EXPECT_EQ(layers[3].origin.where, (dir_ / "sweep/hydrocoef-run.json").string());
  EXPECT_EQ(layers[4].origin.source, SettingSource::NamePattern);
  const RunSettings merged = merge_settings(layers);
  EXPECT_EQ(merged.number("rho"), 1000.0);  // the nearer folder wins
  EXPECT_EQ(merged.text("body"), "hull");   // the parent folder's still applies
  EXPECT_EQ(merged.number("nu"), 1e-6);
  EXPECT_EQ(merged.number("p_ref"), 5.0);
  EXPECT_EQ(merged.number("u"), 0.2);
  EXPECT_TRUE(plan_import({dir_ / "sweep"}, {.use_sidecars = false}).inputs[0].layers.empty());
}

TEST_F(ImportPlanTree, MalformedSidecarsAreRefusedByName) {
  write("bad/run.vtp", "");
  write("bad/hydrocoef-run.json", R"({"rho": "dense"})");
  try {
    plan_import({dir_ / "bad"}, {});
    FAIL() << "a malformed sidecar was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("hydrocoef-run.json: key 'rho': expected a number"), std::string::npos)
        << e.what();
  }
}

TEST(ImportPlanGlob, NamesAndPaths) {
  EXPECT_TRUE(glob_matches("*.vtp", "a/b/c.vtp"));
  EXPECT_FALSE(glob_matches("*.vtp", "a/b/c.vtk"));
  EXPECT_TRUE(glob_matches("u0.1*/*.csv", "u0.1_v0/x.csv"));
  EXPECT_TRUE(glob_matches("*/VTK/*", "case/VTK/a/b.vtp"));  // '*' crosses folders in paths
  EXPECT_FALSE(glob_matches("VTK/*", "case/VTK/b.vtp"));
  EXPECT_TRUE(is_force_history_name("force.dat"));
  EXPECT_TRUE(is_force_history_name("force_0.5.dat"));
  EXPECT_FALSE(is_force_history_name("moment.dat"));
  EXPECT_FALSE(is_force_history_name("forces.csv"));
}

}  // namespace
}  // namespace hydrocoef
