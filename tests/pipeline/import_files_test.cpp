// The import as a library call, on the real OpenFOAM sphere runs: case
// folders and force files become runs in body axes with the mean over the
// steady window and its standard error; the frame of the key and of the
// forces is one whatever source each setting comes from (the sidecar-flow
// and --axes bug, and monitors that ignored both); a quarter model with its
// symmetry planes gives the whole body; settings an importer cannot apply
// are refused or noted.
#include "src/pipeline/import_files.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "importers/openfoam_forces.hpp"
#include "src/core/error.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;
const fs::path kSphere = fs::path(HYDROCOEF_DATA_DIR) / "openfoam-sphere";

SettingsLayer command_line(const nlohmann::json& values) {
  return settings_from_json(values, SettingOrigin{SettingSource::CommandLine, "command line"});
}

std::vector<ImportedInput> import(const std::vector<fs::path>& inputs, const nlohmann::json& cli,
                                  const NamePattern* pattern = nullptr) {
  ImportRequest request;
  request.inputs = inputs;
  request.command_line = command_line(cli);
  request.plan.key_pattern = pattern;
  request.jobs = 2;
  return read_inputs(plan_request(request), request);
}

/// The mean of a component over the samples a history analysis used for it
/// (its own window).
double window_mean(const ForceHistory& history, HistoryComponent c, const HistoryAnalysis& analysis) {
  const auto& values = history.values(ForcePart::Total, c);
  const ComponentAnalysis& component = analysis.components[static_cast<std::size_t>(c)];
  double sum = 0.0;
  for (std::size_t i = component.first_sample; i < component.first_sample + component.sample_count; ++i)
    sum += values[i];
  return sum / static_cast<double>(component.sample_count);
}

TEST(ImportFiles, OpenFoamCaseFoldersBecomeRunsInBodyAxesWithTheirUncertainty) {
  const NamePattern pattern("u{u}_v{v}");
  const auto inputs = import({kSphere / "cases"}, {{"body", "sphere"}, {"axes", "-x,y,-z"}, {"rho", 998.2}}, &pattern);
  ASSERT_EQ(inputs.size(), 4u);
  for (const auto& input : inputs) {
    SCOPED_TRACE(input.input.path.string());
    EXPECT_EQ(input.format, "openfoam-case");
    ASSERT_EQ(input.batch.runs.size(), 1u);
    const auto& run = input.batch.runs.front();
    // The folder name gives the free stream (u, v) in CFD axes; the key here
    // comes from the pattern as body velocity u, v directly.
    EXPECT_GT(run.key.nu_b[0], 0.0);
    EXPECT_EQ(run.key.body, "sphere");
    // Drag on a body moving forward points aft: X < 0, and equals minus the
    // solver's Fx averaged over the same window.
    ASSERT_TRUE(run.tau_b[0]);
    EXPECT_LT(run.tau_b[0]->total, 0.0);
    const ForceHistory history = read_openfoam_forces(input.input.path / "postProcessing" / "forces");
    ASSERT_TRUE(input.history);
    EXPECT_NEAR(run.tau_b[0]->total, -window_mean(history, HistoryComponent::Fx, *input.history), 1e-12);
    EXPECT_NEAR(run.tau_b[2]->total, -window_mean(history, HistoryComponent::Fz, *input.history), 1e-12);
    EXPECT_NEAR(run.tau_b[1]->total, window_mean(history, HistoryComponent::Fy, *input.history), 1e-12);
    // Pressure + viscous = total; a standard error; the provenance names the settings.
    EXPECT_NEAR(*run.tau_b[0]->pressure + *run.tau_b[0]->viscous, run.tau_b[0]->total, 1e-12);
    ASSERT_TRUE(run.statistics);
    ASSERT_TRUE(run.statistics->components[0]);
    EXPECT_GT(run.statistics->components[0]->standard_error, 0.0);
    EXPECT_LT(run.statistics->components[0]->standard_error, 0.05 * std::abs(run.tau_b[0]->total));
    const auto settings = nlohmann::json::parse(input.batch.source.settings);
    EXPECT_EQ(settings["axes"]["source"], "command line");
    // The case's own 0/U states the free stream, which outranks the folder
    // name's pattern (the translation is taken as a group from one layer).
    EXPECT_EQ(settings["flow"]["source"], "case files");
    EXPECT_EQ(input.batch.source.sha256.size(), 64u);
  }
}

std::string format17(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

// A copy of a real case whose forces function object wrote another layout,
// made from the case's own rows: the Foundation releases' forces.dat, or a
// forceCoeffs coefficient.dat (totals as coefficients, with its reference values).
void copy_case_with_layout(const fs::path& from, const fs::path& to, const std::string& layout) {
  fs::create_directories(to);
  for (const char* part : {"0", "constant", "system"}) fs::copy(from / part, to / part, fs::copy_options::recursive);
  const ForceHistory esi = read_openfoam_forces(from / "postProcessing" / "forces");
  if (layout == "foundation") {
    std::string text = "# Forces\n# CofR : (0 0 0)\n# Time forces(pressure viscous) moments(pressure viscous)\n";
    for (std::size_t i = 0; i < esi.size(); ++i) {
      const auto v = [&](ForcePart part, std::size_t k) { return format17(esi.values(part, HistoryComponent(k))[i]); };
      text += format17(esi.abscissa_values[i]) + "\t((" + v(ForcePart::Pressure, 0) + " " + v(ForcePart::Pressure, 1) +
              " " + v(ForcePart::Pressure, 2) + ") (" + v(ForcePart::Viscous, 0) + " " + v(ForcePart::Viscous, 1) +
              " " + v(ForcePart::Viscous, 2) + ")) ((" + v(ForcePart::Pressure, 3) + " " + v(ForcePart::Pressure, 4) +
              " " + v(ForcePart::Pressure, 5) + ") (" + v(ForcePart::Viscous, 3) + " " + v(ForcePart::Viscous, 4) +
              " " + v(ForcePart::Viscous, 5) + "))\n";
    }
    fs::create_directories(to / "postProcessing/forces/0");
    std::ofstream(to / "postProcessing/forces/0/forces.dat") << text;
  } else {
    const double rho = 998.2, u = 0.2, area = 0.0706858, l = 0.3, q = 0.5 * rho * u * u;
    std::string text =
        "# Force coefficients\n# dragDir : (1 0 0)\n# sideDir : (0 1 0)\n# liftDir : (0 0 1)\n"
        "# magUInf : 0.2\n# lRef : 0.3\n# Aref : 0.0706858\n# CofR : (0 0 0)\n"
        "# Time Cd Cs Cl CmRoll CmPitch CmYaw\n";
    for (std::size_t i = 0; i < esi.size(); ++i) {
      text += format17(esi.abscissa_values[i]);
      for (std::size_t k = 0; k < 6; ++k)
        text +=
            " " + format17(esi.values(ForcePart::Total, HistoryComponent(k))[i] / (k < 3 ? q * area : q * area * l));
      text += "\n";
    }
    fs::create_directories(to / "postProcessing/forceCoeffs/0");
    std::ofstream(to / "postProcessing/forceCoeffs/0/coefficient.dat") << text;
  }
}

// The sweep as Foundation releases and forceCoeffs leave it: the same runs,
// keys and signs as from the ESI force.dat and moment.dat, with sweep-wide
// flags only.
TEST(ImportFiles, FoundationAndCoefficientCaseFoldersGiveTheSameRuns) {
  const auto esi = import({kSphere / "cases"}, {{"body", "sphere"}, {"axes", "-x,y,-z"}});
  ASSERT_EQ(esi.size(), 4u);
  for (const std::string layout : {"foundation", "coefficients"}) {
    SCOPED_TRACE(layout);
    test::TempDir dir;
    for (const auto& input : esi)
      copy_case_with_layout(input.input.path, dir / "sweep" / input.input.path.filename(), layout);
    const auto other = import({dir / "sweep"}, {{"body", "sphere"}, {"axes", "-x,y,-z"}});
    ASSERT_EQ(other.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
      SCOPED_TRACE(esi[i].input.path.filename().string());
      ASSERT_EQ(other[i].input.path.filename(), esi[i].input.path.filename());
      const auto& a = esi[i].batch.runs.front();
      const auto& b = other[i].batch.runs.front();
      EXPECT_EQ(b.key.nu_b, a.key.nu_b);  // u > 0, from 0/U with the sweep's axes
      EXPECT_GT(b.key.nu_b[0], 0.0);
      ASSERT_TRUE(other[i].history);
      EXPECT_EQ(other[i].history->first_sample, esi[i].history->first_sample);
      for (std::size_t c = 0; c < 6; ++c) {
        ASSERT_TRUE(b.tau_b[c]) << c;
        // Foundation: totals are the parts' sums (the ESI file's totals are rounded to 11 digits).
        EXPECT_NEAR(b.tau_b[c]->total, a.tau_b[c]->total, 1e-9 * std::abs(a.tau_b[c]->total) + 1e-15) << c;
      }
      EXPECT_LT(b.tau_b[0]->total, 0.0);  // drag opposes the motion
      ASSERT_TRUE(b.statistics && b.statistics->components[0]);
      EXPECT_NEAR(b.statistics->components[0]->standard_error, a.statistics->components[0]->standard_error,
                  1e-6 * a.statistics->components[0]->standard_error);
    }
  }
}

// No pattern, no sidecar, no per-case flag: the free stream from each case's
// 0/U, rho and the moment centre from its controlDict, nu from
// transportProperties; --axes turns the flow into the body velocity and the
// forces with one frame.
TEST(ImportFiles, OpenFoamCaseFoldersNeedOnlySweepWideSettings) {
  const auto inputs = import({kSphere / "cases"}, {{"body", "sphere"}, {"axes", "-x,y,-z"}});
  ASSERT_EQ(inputs.size(), 4u);
  for (const auto& input : inputs) {
    SCOPED_TRACE(input.input.path.string());
    ASSERT_EQ(input.batch.runs.size(), 1u);
    const auto& run = input.batch.runs.front();
    // Folder u0.10_v0.05: free stream (0.1, 0.05, 0) in CFD axes; the body
    // moves at minus it, and body x is -x, body y is y.
    const std::string name = input.input.path.filename().string();
    const double flow_x = std::stod(name.substr(1, 4)), flow_y = std::stod(name.substr(7, 4));
    EXPECT_DOUBLE_EQ(run.key.nu_b[0], flow_x);
    EXPECT_DOUBLE_EQ(run.key.nu_b[1], -flow_y + 0.0);
    EXPECT_EQ(run.key.nu_b[2], 0.0);
    ASSERT_TRUE(run.tau_b[0]);
    EXPECT_LT(run.tau_b[0]->total, 0.0);
    ASSERT_TRUE(run.fluid.density_kg_m3);
    EXPECT_EQ(*run.fluid.density_kg_m3, 998.2);
    ASSERT_TRUE(run.fluid.kinematic_viscosity_m2_s);
    EXPECT_EQ(*run.fluid.kinematic_viscosity_m2_s, 1.004e-06);
    const auto settings = nlohmann::json::parse(input.batch.source.settings);
    EXPECT_EQ(settings["flow"]["source"], "case files");
    EXPECT_NE(settings["flow"]["where"].get<std::string>().find("0/U:"), std::string::npos) << settings.dump();
    EXPECT_EQ(settings["rho"]["source"], "case files");
    EXPECT_NE(settings["rho"]["where"].get<std::string>().find("controlDict:"), std::string::npos);
  }
}

TEST(ImportFiles, AQuarterModelWithItsSymmetryPlanesGivesTheWholeBody) {
  const NamePattern pattern("U{u}");
  const auto quarter =
      import({kSphere / "quarter-cases" / "U0.1000"}, {{"body", "sphere"}, {"axes", "-x,y,-z"}}, &pattern);
  const auto whole = import({kSphere / "quarter-cases" / "U0.1000"},
                            {{"body", "sphere"}, {"axes", "-x,y,-z"}, {"symmetry", "y=0,z=0"}}, &pattern);
  const auto& q = quarter.front().batch.runs.front();
  const auto& w = whole.front().batch.runs.front();
  EXPECT_NEAR(w.tau_b[0]->total, 4.0 * q.tau_b[0]->total, 1e-9 * std::abs(q.tau_b[0]->total));
  EXPECT_EQ(w.tau_b[1]->total, 0.0);
  EXPECT_EQ(w.tau_b[2]->total, 0.0);
  for (std::size_t i = 3; i < 6; ++i) EXPECT_EQ(w.tau_b[i]->total, 0.0) << i;
  EXPECT_LT(w.tau_b[0]->total, 0.0);
  bool noted = false;
  for (const auto& note : whole.front().notes) noted |= note.find("Fy, Fz, Mx, My, Mz vanish") != std::string::npos;
  EXPECT_TRUE(noted);
}

TEST(ImportFiles, OneFrameForTheKeyAndTheForcesWhateverTheirSource) {
  // The export of u0.10_v0.05 with the free stream in its sidecar and the
  // axes on the command line: the body moves forward (u > 0) and the drag
  // points aft (X < 0).
  test::TempDir dir;
  fs::copy_file(kSphere / "full" / "u0.10_v0.05" / "u0.10_v0.05_sphere_t1000.vtp", dir / "run.vtp");
  std::ofstream(dir / "run.vtp.json") << R"({"flow": [0.1, 0.05, 0], "rho": 998.2})";
  const auto in_sidecar = import({dir / "run.vtp"}, {{"axes", "-x,y,-z"}});
  const auto& run = in_sidecar.front().batch.runs.front();
  EXPECT_DOUBLE_EQ(run.key.nu_b[0], 0.1);
  EXPECT_DOUBLE_EQ(run.key.nu_b[1], -0.05);
  EXPECT_LT(run.tau_b[0]->total, 0.0);
  // The same with everything on the command line, and everything in the sidecar.
  fs::remove(dir / "run.vtp.json");
  const auto all_cli = import({dir / "run.vtp"}, {{"axes", "-x,y,-z"}, {"flow", {0.1, 0.05, 0}}, {"rho", 998.2}});
  std::ofstream(dir / "run.vtp.json") << R"({"flow": [0.1, 0.05, 0], "rho": 998.2, "axes": "-x,y,-z"})";
  const auto all_sidecar = import({dir / "run.vtp"}, nlohmann::json::object());
  for (const auto* other : {&all_cli, &all_sidecar}) {
    const auto& o = other->front().batch.runs.front();
    EXPECT_EQ(o.key.nu_b, run.key.nu_b);
    for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(o.tau_b[i]->total, run.tau_b[i]->total) << i;
  }
}

TEST(ImportFiles, MonitorsTakeTheFlowAndTheAxes) {
  // A monitor used to ignore --flow and --axes (u = v = 0, forces unrotated).
  test::TempDir dir;
  std::ofstream(dir / "monitor.csv")
      << "\"ACCUMULATED TIMESTEP\",\"USER POINT,Fx\",\"USER POINT,Fy\",\"USER POINT,Fz\"\n"
         "1,0.30,0.01,0.02\n2,0.34,0.02,0.03\n";
  const auto inputs = import({dir / "monitor.csv"}, {{"axes", "-x,y,-z"}, {"flow", {0.2, 0, 0}}, {"body", "hull"}});
  ASSERT_EQ(inputs.front().format, "monitor");
  const auto& run = inputs.front().batch.runs.front();
  EXPECT_DOUBLE_EQ(run.key.nu_b[0], 0.2);
  // A monitor is a force history: the mean over its window (here both iterations), in body axes.
  EXPECT_NEAR(run.tau_b[0]->total, -0.32, 1e-15);
  EXPECT_NEAR(run.tau_b[1]->total, 0.015, 1e-15);
  EXPECT_NEAR(run.tau_b[2]->total, -0.025, 1e-15);
  ASSERT_TRUE(run.statistics);
  EXPECT_EQ(run.statistics->abscissa, "iteration");
  EXPECT_EQ(run.statistics->windows[0].samples, 2u);
}

TEST(ImportFiles, SettingsAnImporterCannotApplyAreRefusedOrNoted) {
  test::TempDir dir;
  std::ofstream(dir / "table.csv") << "u [m s^-1],X [N]\n0.1,-0.2\n0.2,-0.7\n";
  try {
    import({dir / "table.csv"}, {{ "axes", "-x,y,-z" }});
    FAIL() << "a table accepted --axes";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("setting 'axes' does not apply to a force table"), std::string::npos)
        << e.what();
  }
  // From a folder sidecar shared with surface exports it is a note.
  std::ofstream(dir / "hydrocoef-run.json") << R"({"axes": "-x,y,-z", "rho": 998.2})";
  const auto inputs = import({dir.path()}, nlohmann::json::object());
  ASSERT_EQ(inputs.size(), 1u);
  ASSERT_FALSE(inputs.front().notes.empty());
  EXPECT_NE(inputs.front().notes.front().find("setting 'axes'"), std::string::npos);
  EXPECT_EQ(inputs.front().batch.runs.size(), 2u);
  EXPECT_EQ(*inputs.front().batch.runs.front().fluid.density_kg_m3, 998.2);
}

TEST(ImportFiles, ForceFilesAndHistoriesAreRecognised) {
  PlannedInput force{kSphere / "full" / "u0.10_v0.00" / "force.dat", {}, InputKind::File, {}};
  EXPECT_EQ(input_format(force, "auto"), "openfoam-forces");
  test::TempDir dir;
  std::ofstream(dir / "history.csv") << "Time [s],Fx [N],Fy [N]\n0.1,1,2\n0.2,1,2\n";
  std::ofstream(dir / "table.csv") << "u [m s^-1],X [N]\n0.1,1\n";
  EXPECT_EQ(input_format({dir / "history.csv", {}, InputKind::File, {}}, "auto"), "force-history");
  EXPECT_EQ(input_format({dir / "table.csv", {}, InputKind::File, {}}, "auto"), "table");
  EXPECT_THROW(input_format(force, "xml"), InputError);
}

TEST(ImportFiles, GivenWindowsAreUsed) {
  const NamePattern pattern("u{u}_v{v}");
  const auto inputs = import({kSphere / "cases" / "u0.30_v0.00"},
                             {{"body", "sphere"}, {"axes", "-x,y,-z"}, {"window", "601:1000"}}, &pattern);
  const auto& statistics = *inputs.front().batch.runs.front().statistics;
  EXPECT_EQ(statistics.convergence, "given-window");
  for (std::size_t c = 0; c < 6; ++c) {
    EXPECT_EQ(statistics.windows[c].first, 601.0);
    EXPECT_EQ(statistics.windows[c].last, 1000.0);
    EXPECT_EQ(statistics.windows[c].samples, 400u);
  }
  EXPECT_THROW(import({kSphere / "cases" / "u0.30_v0.00"}, {{"window", "1000:601"}}, &pattern), InputError);
}

TEST(ImportFiles, AConvergedSteadyCaseStoresItsFinalIterateWithItsIterativeError) {
  // The quarter runs stopped when their residualControl held: each component
  // is the last iteration's value, its standard error the iterative error,
  // and nothing is flagged. The full-domain runs ran to endTime without it:
  // window means, as before.
  const NamePattern pattern("U{u}");
  for (const char* name : {"U0.1000", "U0.3000"}) {
    SCOPED_TRACE(name);
    const auto inputs = import({kSphere / "quarter-cases" / name}, {{"body", "sphere"}}, &pattern);
    const auto& run = inputs.front().batch.runs.front();
    ASSERT_TRUE(run.statistics);
    EXPECT_EQ(run.statistics->convergence, "converged");
    EXPECT_NE(run.statistics->convergence_reason.find("solverInfo.dat:"), std::string::npos);
    EXPECT_TRUE(run.statistics->flags.empty());
    const ForceHistory h = read_openfoam_forces(kSphere / "quarter-cases" / name / "postProcessing" / "forces");
    for (std::size_t c = 0; c < 6; ++c) {
      ASSERT_TRUE(run.tau_b[c]);
      EXPECT_EQ(run.tau_b[c]->total, h.values(ForcePart::Total, HistoryComponent(c)).back()) << c;
      EXPECT_EQ(*run.tau_b[c]->pressure, h.values(ForcePart::Pressure, HistoryComponent(c)).back()) << c;
      EXPECT_EQ(run.statistics->windows[c].samples, 1u);
      EXPECT_EQ(run.statistics->windows[c].last, h.abscissa_values.back());
      EXPECT_TRUE(run.statistics->windows[c].flags.empty());
    }
    // The drag still creeps by about 1e-4 of itself per iteration when the
    // criteria are met: the stated error is well above that and a few per cent
    // at most.
    const double drag = std::abs(run.tau_b[0]->total);
    const double error = run.statistics->components[0]->standard_error;
    EXPECT_GT(error, 3e-4 * drag);
    EXPECT_LT(error, 0.05 * drag);
  }
  const NamePattern full("u{u}_v{v}");
  const auto inputs = import({kSphere / "cases" / "u0.10_v0.00"}, {{"body", "sphere"}}, &full);
  const auto& run = inputs.front().batch.runs.front();
  EXPECT_EQ(run.statistics->convergence, "steady-window");
  EXPECT_NE(run.statistics->convergence_reason.find("are not met at the last iteration"), std::string::npos)
      << run.statistics->convergence_reason;
}

TEST(ImportFiles, NoVelocityIsEverADefault) {
  // A case whose free stream is nowhere: refused naming where it looked, and
  // imported at rest only when the user says so.
  test::TempDir dir;
  fs::copy(kSphere / "quarter-cases" / "U0.1000", dir / "case", fs::copy_options::recursive);
  fs::remove_all(dir / "case" / "0");
  try {
    import({dir / "case"}, {{ "body", "sphere" }});
    ADD_FAILURE() << "expected a refusal";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("no body velocity found"), std::string::npos) << message;
    EXPECT_NE(message.find("no velocity file"), std::string::npos) << message;
    EXPECT_NE(message.find("--at-rest"), std::string::npos) << message;
  }
  const auto at_rest = import({dir / "case"}, {{"body", "sphere"}, {"at_rest", true}});
  EXPECT_EQ(at_rest.front().batch.runs.front().key.nu_b, (std::array<double, 6>{}));
  EXPECT_THROW(import({dir / "case"}, {{"body", "sphere"}, {"at_rest", true}, {"u", 0.1}}), InputError);
  // A force file alone, outside a case: the same.
  EXPECT_THROW(import({kSphere / "full" / "u0.10_v0.00" / "force.dat"}, {{"body", "sphere"}}), InputError);
}

const fs::path kCfxOut = fs::path(HYDROCOEF_SOURCE_DIR) / "tests/data/cfx/hull_u1.5_001.out";

// A CFX run with only its solver output: the wall force summary's domain
// group totals, pressure and viscous parts apart, in body axes with the key
// from the CCL's inlet (tests/data/cfx/hull_u1.5_001.out; the numbers are the
// file's own table).
TEST(ImportFiles, ACfxOutImportsFromItsWallForceSummary) {
  test::TempDir dir;
  fs::copy_file(kCfxOut, dir / "hull_u1.5_001.out");
  const auto inputs = import({dir / "hull_u1.5_001.out"}, {{"body", "hull"}, {"axes", "-x,y,-z"}});
  ASSERT_EQ(inputs.size(), 1u);
  EXPECT_EQ(inputs[0].format, "cfx-out");
  EXPECT_EQ(inputs[0].batch.source.importer, "cfx-out-summary");
  const auto& run = inputs[0].batch.runs.at(0);
  EXPECT_DOUBLE_EQ(run.key.nu_b[0], 1.5);  // the inlet's (1.5, 0.1, 0) m/s, the body moving into it
  EXPECT_DOUBLE_EQ(run.key.nu_b[1], -0.1);
  EXPECT_EQ(*run.fluid.density_kg_m3, 997.0);
  EXPECT_FALSE(run.statistics);  // one value, not a mean over a history
  // Totals: pressure (13.25, 1.5, -0.5) + viscous (3.75, 0.005, 0.02) N in CFD
  // axes; body axes (-x, y, -z).
  EXPECT_DOUBLE_EQ(*run.tau_b[0]->pressure, -13.25);
  EXPECT_DOUBLE_EQ(*run.tau_b[0]->viscous, -3.75);
  EXPECT_DOUBLE_EQ(run.tau_b[0]->total, -17.0);
  EXPECT_DOUBLE_EQ(run.tau_b[1]->total, 1.505);
  EXPECT_DOUBLE_EQ(run.tau_b[2]->total, 0.5 - 0.02);
  // Moments (0.01, -0.24, -0.575) + (0, -0.012, 0.00125) N m.
  EXPECT_DOUBLE_EQ(*run.tau_b[3]->pressure, -0.01);
  EXPECT_DOUBLE_EQ(run.tau_b[4]->total, -0.252);
  EXPECT_DOUBLE_EQ(*run.tau_b[5]->viscous, -0.00125);
  EXPECT_DOUBLE_EQ(run.tau_b[5]->total, 0.575 - 0.00125);

  // --location: one boundary, or several summed (their sum is the totals).
  const auto hull = import({dir / "hull_u1.5_001.out"}, {{"axes", "-x,y,-z"}, {"locations", {"hull"}}});
  const auto& h = hull[0].batch.runs.at(0);
  EXPECT_DOUBLE_EQ(*h.tau_b[0]->pressure, -12.5);
  EXPECT_DOUBLE_EQ(*h.tau_b[0]->viscous, -3.5);
  EXPECT_DOUBLE_EQ(h.tau_b[1]->total, 0.26);
  const auto both = import({dir / "hull_u1.5_001.out"}, {{"axes", "-x,y,-z"}, {"locations", {"rudder", "hull"}}});
  for (std::size_t c = 0; c < 6; ++c)
    EXPECT_NEAR(both[0].batch.runs.at(0).tau_b[c]->total, run.tau_b[c]->total, 1e-12) << c;
  try {
    import({dir / "hull_u1.5_001.out"}, {{ "locations", { "keel" } }});
    FAIL() << "an unknown location was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("hull_u1.5_001.out:217:"), std::string::npos) << m;
    EXPECT_NE(m.find("no location 'keel'"), std::string::npos) << m;
    EXPECT_NE(m.find("hull, rudder, Default Domain"), std::string::npos) << m;
  }
}

// A pressure-driven CFX case states no free stream: refused at the opening's
// line unless the flow comes from the command line or a sidecar, which
// complete the case's settings by precedence.
TEST(ImportFiles, APressureDrivenCfxCaseTakesTheFlowGivenElsewhere) {
  std::string text;
  {
    std::ifstream in(kCfxOut);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::string inlet_from = "       Boundary Type = INLET\n";
  text.replace(text.find(inlet_from), inlet_from.size(), "       Boundary Type = OPENING\n");
  const auto option = text.find("Option = Cartesian Velocity Components");
  const auto end = text.find("W = 0 [m s^-1]", option);
  text.replace(option, end + 14 - option,
               "Option = Opening Pressure and Direction\n           Relative Pressure = 0 [Pa]");
  const std::size_t line =
      static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(option), '\n')) + 1;
  test::TempDir dir;
  std::ofstream(dir / "channel_001.out") << text;
  try {
    import({dir / "channel_001.out"}, {{ "axes", "-x,y,-z" }});
    FAIL() << "a pressure-driven case without a flow was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("channel_001.out:" + std::to_string(line) + ": opening 'inlet'"), std::string::npos) << m;
    EXPECT_NE(m.find("--flow"), std::string::npos) << m;
  }
  const auto given = import({dir / "channel_001.out"}, {{"axes", "-x,y,-z"}, {"flow", {1.2, 0, 0}}});
  EXPECT_DOUBLE_EQ(given[0].batch.runs.at(0).key.nu_b[0], 1.2);
  EXPECT_DOUBLE_EQ(given[0].batch.runs.at(0).tau_b[0]->total, -17.0);
  std::ofstream(dir / "channel_001.out.json") << R"({"u": 0.8})";
  const auto sidecar = import({dir / "channel_001.out"}, {{"axes", "-x,y,-z"}});
  EXPECT_DOUBLE_EQ(sidecar[0].batch.runs.at(0).key.nu_b[0], 0.8);
  EXPECT_EQ(sidecar[0].settings.find("u")->origin.source, SettingSource::FileSidecar);
}

// A forced-oscillation case is for `hydrocoef pmm`, not for import.
TEST(ImportFiles, AForcedOscillationCaseIsRefusedNamingPmm) {
  const fs::path pmm_case = fs::path(HYDROCOEF_SOURCE_DIR) / "examples/openfoam-sphere/pmm/surge-A0.015-T2";
  try {
    import({pmm_case}, {{ "axes", "-x,y,-z" }});
    FAIL() << "a forced-oscillation case was imported";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("constant/dynamicMeshDict:"), std::string::npos) << m;
    EXPECT_NE(m.find("a forced-oscillation case"), std::string::npos) << m;
    EXPECT_NE(m.find("hydrocoef pmm " + pmm_case.string()), std::string::npos) << m;
  }
}

ImportResult read_all(const std::vector<fs::path>& inputs, const nlohmann::json& cli,
                      const NamePattern* pattern = nullptr) {
  ImportRequest request;
  request.inputs = inputs;
  request.command_line = command_line(cli);
  request.plan.key_pattern = pattern;
  request.jobs = 2;
  return read_import(request);
}

// --key-from-name reads files named on the command line as it reads folder
// contents; two files that give one run's component are refused naming both
// and where each key came from.
TEST(ImportFiles, NamePatternKeysFilesNamedDirectlyAndCollisionsNameTheirSources) {
  test::TempDir dir;
  for (const char* run : {"u0.10_v0.00", "u0.20_v0.00"}) {
    fs::create_directories(dir / "a" / run);
    for (const char* f : {"force.dat", "moment.dat"})
      fs::copy_file(kSphere / "full" / "u0.10_v0.00" / f, dir / "a" / run / f);
  }
  const NamePattern pattern("u{u}_v{v}");
  const auto keyed =
      read_all({dir / "a/u0.10_v0.00/force.dat", dir / "a/u0.20_v0.00/force.dat"}, {{"axes", "-x,y,-z"}}, &pattern);
  ASSERT_EQ(keyed.inputs.size(), 2u);
  EXPECT_DOUBLE_EQ(keyed.inputs[0].batch.runs.at(0).key.nu_b[0], 0.1);
  EXPECT_DOUBLE_EQ(keyed.inputs[1].batch.runs.at(0).key.nu_b[0], 0.2);

  // The same run from two folders: refused, each key's source named.
  fs::create_directories(dir / "b" / "u0.10_v0.00");
  for (const char* f : {"force.dat", "moment.dat"})
    fs::copy_file(kSphere / "full" / "u0.10_v0.00" / f, dir / "b" / "u0.10_v0.00" / f);
  try {
    read_all({dir / "a/u0.10_v0.00/force.dat", dir / "b/u0.10_v0.00/force.dat"}, {{"axes", "-x,y,-z"}}, &pattern);
    FAIL() << "two files of one run were accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind((dir / "b/u0.10_v0.00/force.dat").string() + ": run ", 0), 0u) << m;
    EXPECT_NE(m.find("gets X from two files of this import"), std::string::npos) << m;
    EXPECT_NE(m.find((dir / "a/u0.10_v0.00/force.dat").string() + " (u from the name pattern"), std::string::npos) << m;
    EXPECT_NE(m.find("--key-from-name 'u{u}_v{v}'"), std::string::npos) << m;
  }
  // Files that give no key at all are never told to --replace one another.
  try {
    read_all({dir / "a/u0.10_v0.00/force.dat", dir / "a/u0.20_v0.00/force.dat"}, {{"axes", "-x,y,-z"}});
    FAIL() << "two files without a key were accepted as one run";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.find("--replace"), std::string::npos) << m;
    EXPECT_NE(m.find("--key-from-name"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace hydrocoef
