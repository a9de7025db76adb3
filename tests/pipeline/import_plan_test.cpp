// Planning an import on the real OpenFOAM sphere folders and on small trees:
// case folders found and not walked, twins and partner files reduced with a
// note, a history preferred to surfaces of the same run, filters, and the
// layers of settings each input gets, in order.
#include "src/pipeline/import_plan.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <tuple>

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

// Folders as users keep them: the real sphere run's postProcessing output
// with a README, a source note, notes and a solver log beside it. Only the
// force history is data; the rest is skipped, listed in one note.
TEST_F(ImportPlanTree, FilesThatAreNotCfdDataAreSkippedInOneNote) {
  fs::copy(kSphere / "cases" / "u0.10_v0.00" / "postProcessing", dir_ / "run", fs::copy_options::recursive);
  write("run/README.txt", "Sphere at u = 0.1 m/s, OpenFOAM v2206.\n");
  write("run/SOURCE.txt", "data/openfoam-sphere/cases/u0.10_v0.00\n");
  write("run/notes.md", "# notes\n");
  write("run/log.simpleFoam", "Time = 1\n");
  const ImportPlan plan = plan_import({dir_ / "run"}, {});
  EXPECT_EQ(names(plan), (std::vector<std::string>{"forces/0/force.dat"}));
  std::vector<std::string> skipped;
  for (const auto& f : plan.skipped) skipped.push_back(f.generic_string());
  EXPECT_EQ(skipped, (std::vector<std::string>{"README.txt", "SOURCE.txt", "log.simpleFoam", "notes.md",
                                               "solverInfo/0/solverInfo.dat", "wallShearStress/0/wallShearStress.dat",
                                               "yPlus/0/yPlus.dat"}));
  std::size_t skipped_notes = 0;
  for (const auto& note : plan.notes)
    if (note.find("skipped as not CFD data") != std::string::npos) {
      ++skipped_notes;
      EXPECT_EQ(note.rfind("7 files skipped", 0), 0u) << note;
      EXPECT_NE(note.find("README.txt, SOURCE.txt, log.simpleFoam, notes.md, solverInfo/0/solverInfo.dat, ... (2 "
                          "more)"),
                std::string::npos)
          << note;
    }
  EXPECT_EQ(skipped_notes, 1u);
  // Two folders in one import: still one note, counting both.
  fs::copy(dir_ / "run", dir_ / "run2", fs::copy_options::recursive);
  const ImportPlan two = plan_import({dir_ / "run", dir_ / "run2"}, {});
  EXPECT_EQ(two.inputs.size(), 2u);
  EXPECT_EQ(two.skipped.size(), 14u);
  EXPECT_EQ(std::count_if(two.notes.begin(), two.notes.end(),
                          [](const std::string& n) { return n.find("skipped as not CFD data") != std::string::npos; }),
            1);
  EXPECT_TRUE(is_not_cfd_data("postProcessing/solverInfo/0/solverInfo_1000.dat"));
  EXPECT_TRUE(is_not_cfd_data("README"));
  EXPECT_FALSE(is_not_cfd_data("force_1000.dat"));
  EXPECT_FALSE(is_not_cfd_data("u0.1_source_run.csv"));
}

// --include and --exclude choose among twins before they are paired: the
// .vtk of a run whose .vtp would otherwise be taken.
TEST_F(ImportPlanTree, FiltersApplyBeforeTwinsArePaired) {
  fs::copy(kSphere / "full" / "u0.10_v0.00", dir_ / "run", fs::copy_options::recursive);
  const ImportPlan vtk = plan_import({dir_ / "run"}, {.include = {"*.vtk"}});
  EXPECT_EQ(names(vtk), (std::vector<std::string>{"u0.10_v0.00_sphere_t1000.vtk"}));
  for (const auto& note : vtk.notes) EXPECT_EQ(note.find("twin"), std::string::npos) << note;
  const ImportPlan no_vtp = plan_import({dir_ / "run"}, {.exclude = {"*.vtp", "force.dat"}});
  EXPECT_EQ(names(no_vtp), (std::vector<std::string>{"u0.10_v0.00_sphere_t1000.vtk"}));
  // Without filters the .vtp is the twin kept, and the history is preferred.
  EXPECT_EQ(names(plan_import({dir_ / "run"}, {})), (std::vector<std::string>{"force.dat"}));
  EXPECT_EQ(names(plan_import({dir_ / "run"}, {.prefer_surfaces = true})),
            (std::vector<std::string>{"u0.10_v0.00_sphere_t1000.vtp"}));
}

// --prefer-surfaces inside OpenFOAM case folders: the surface export
// foamToVTK left under VTK/ (its latest time), with the case's settings.
TEST(ImportPlan, PreferSurfacesTakesACaseFoldersVtkExport) {
  const NamePattern pattern("u{u}_v{v}");
  const ImportPlan plan = plan_import({kSphere / "cases"}, {.key_pattern = &pattern, .prefer_surfaces = true});
  EXPECT_EQ(names(plan), (std::vector<std::string>{"u0.10_v0.00/VTK/u0.10_v0.00_1000/boundary/sphere.vtp",
                                                   "u0.10_v0.05/VTK/u0.10_v0.05_1000/boundary/sphere.vtp",
                                                   "u0.20_v0.10/VTK/u0.20_v0.10_1000/boundary/sphere.vtp",
                                                   "u0.30_v0.00/VTK/u0.30_v0.00_1000/boundary/sphere.vtp"}));
  for (const auto& input : plan.inputs) {
    EXPECT_EQ(input.kind, InputKind::File);
    ASSERT_EQ(input.layers.size(), 2u);
    EXPECT_EQ(input.layers[0].origin.source, SettingSource::CaseFiles);  // 0/U, controlDict, transportProperties
    EXPECT_EQ(input.layers[1].origin.source, SettingSource::NamePattern);
  }
  EXPECT_EQ(std::get<double>(plan.inputs[2].layers[1].values.at("u").value), 0.20);
  bool noted = false;
  for (const auto& note : plan.notes)
    noted |= note.find("VTK/u0.10_v0.00_1000/boundary/sphere.vtp (surfaces, as asked) imported") != std::string::npos;
  EXPECT_TRUE(noted);
  // Named directly, and without the flag: the force history.
  const ImportPlan one = plan_import({kSphere / "cases" / "u0.10_v0.05"}, {.prefer_surfaces = true});
  ASSERT_EQ(one.inputs.size(), 1u);
  EXPECT_EQ(one.inputs[0].path,
            kSphere / "cases" / "u0.10_v0.05" / "VTK" / "u0.10_v0.05_1000" / "boundary" / "sphere.vtp");
  EXPECT_EQ(plan_import({kSphere / "cases" / "u0.10_v0.05"}, {}).inputs[0].kind, InputKind::OpenFoamCase);
}

// The name pattern reads the path of files and case folders named on the
// command line as it reads folder contents.
TEST_F(ImportPlanTree, TheNamePatternAppliesToInputsNamedDirectly) {
  write("exports/u0.5_v0.1.csv", "x\n");
  write("sweep/u0.3_v0/force.dat", "# Time Fx\n");
  const NamePattern pattern("u{u}_v{v}");
  for (const auto& [file, u, v] : {std::tuple{dir_ / "exports" / "u0.5_v0.1.csv", 0.5, 0.1},
                                   std::tuple{dir_ / "sweep" / "u0.3_v0" / "force.dat", 0.3, 0.0}}) {
    const ImportPlan plan = plan_import({file}, {.key_pattern = &pattern});
    ASSERT_EQ(plan.inputs.size(), 1u);
    ASSERT_EQ(plan.inputs[0].layers.size(), 1u) << file;
    const RunSettings merged = merge_settings(plan.inputs[0].layers);
    EXPECT_EQ(merged.number("u"), u);
    EXPECT_EQ(merged.number("v"), v);
    EXPECT_EQ(merged.find("u")->origin.source, SettingSource::NamePattern);
  }
  const ImportPlan named_case = plan_import({kSphere / "cases" / "u0.20_v0.10"}, {.key_pattern = &pattern});
  EXPECT_EQ(merge_settings(named_case.inputs[0].layers).number("v"), std::nullopt);  // the case's own 0/U wins
  EXPECT_EQ(named_case.inputs[0].layers.back().origin.source, SettingSource::NamePattern);
}

// A CFX run with only its solver output: the .out is the run, read from its
// wall force summary, in a folder and named directly.
TEST_F(ImportPlanTree, ACfxOutWithoutDataFilesIsARunOfItsOwn) {
  fs::create_directories(dir_ / "cfx");
  fs::copy_file(fs::path(HYDROCOEF_SOURCE_DIR) / "tests/data/cfx/hull_u1.5_001.out",
                dir_ / "cfx" / "hull_u1.5_001.out");
  fs::copy_file(fs::path(HYDROCOEF_SOURCE_DIR) / "tests/data/cfx/tow_u1.5_001.out", dir_ / "cfx" / "tow_u1.5_001.out");
  const ImportPlan folder = plan_import({dir_ / "cfx"}, {});
  EXPECT_EQ(names(folder), (std::vector<std::string>{"hull_u1.5_001.out"}));
  ASSERT_EQ(folder.inputs[0].layers.size(), 1u);
  EXPECT_EQ(folder.inputs[0].layers[0].origin.source, SettingSource::CaseFiles);
  EXPECT_EQ(folder.skipped, (std::vector<fs::path>{"tow_u1.5_001.out"}));  // no summary: a run still going
  const ImportPlan named = plan_import({dir_ / "cfx" / "hull_u1.5_001.out"}, {});
  ASSERT_EQ(named.inputs.size(), 1u);
  EXPECT_EQ(named.inputs[0].path, dir_ / "cfx" / "hull_u1.5_001.out");
  // With monitors beside it, the monitors are the run and the .out its settings.
  write("cfx/hull_u1.5_001.csv", "\"ACCUMULATED TIMESTEP\",\"USER POINT,Fx\"\n1,2\n");
  EXPECT_EQ(names(plan_import({dir_ / "cfx"}, {})), (std::vector<std::string>{"hull_u1.5_001.csv"}));
  EXPECT_EQ(plan_import({dir_ / "cfx" / "hull_u1.5_001.out"}, {}).inputs[0].path, dir_ / "cfx" / "hull_u1.5_001.csv");
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
