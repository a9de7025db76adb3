// The vehicle FMU (`hydrocoef export-fmu BODY --vehicle FILE`) driven by the
// project's FMI host equals `hydrocoef simulate` bit for bit: the ASR-V pool
// test (examples/asr-v/vehicle.json, a constant yaw torque of 0.0027 N m
// from rest, RK4 at 1 ms, 60 s), stepped from one of simulate's output times
// to the next, gives at every output time the position, attitude (quaternion
// and Euler angles), velocities and damping of simulate's trajectory CSV; so
// does the surface-damped ASR-V (vehicle-surfaces.json, the surfaces built as
// examples/asr-v/run.sh builds them) in a current from a tilted start. The
// kind's own refusals: a parameter set after initialisation, an unknown
// value reference, a NaN input or parameter, each fmi2Error with a message;
// the model description read back states the vehicle's variables, units and
// dependencies; the binary is the surface FMU's (one binary, two kinds).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "tests/fmu/fmi_host.hpp"
#include "tests/support/asr_v_example.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::FmiHost;
using test::run_cli;
using test::same_bits;
using test::TempDir;

const std::string kExample = HYDROCOEF_SOURCE_DIR "/examples/asr-v/";

// The rows of a trajectory CSV (its header skipped), each number read back
// exactly (the CSV writes the shortest text that reads back to the double).
std::vector<std::vector<double>> read_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) row.push_back(std::strtod(cell.c_str(), nullptr));
    rows.push_back(row);
  }
  return rows;
}

std::uint32_t vr_of(const FmiHost& host, const std::string& name) {
  for (const auto& v : host.model().variables)
    if (v.name == name) return v.value_reference;
  ADD_FAILURE() << "no variable " << name;
  return 0;
}

struct Scenario {
  double duration, rate, step;
  std::vector<double> tau;        // X..N
  std::vector<double> current;    // NED
  std::vector<double> euler0;     // rad
  std::vector<double> velocity0;  // u..r
};

// The CSV's columns (src/dynamics/trajectory.hpp) and the FMU outputs they are.
const std::vector<std::pair<std::size_t, std::string>> kCompared = {
    {1, "x_n"},        {2, "y_n"},        {3, "z_n"},        {4, "phi"},       {5, "theta"},      {6, "psi"},
    {7, "q_eta"},      {8, "q_eps1"},     {9, "q_eps2"},     {10, "q_eps3"},   {11, "u"},         {12, "v"},
    {13, "w"},         {14, "p"},         {15, "q"},         {16, "r"},        {29, "X_damping"}, {30, "Y_damping"},
    {31, "Z_damping"}, {32, "K_damping"}, {33, "M_damping"}, {34, "N_damping"}};

// Steps the FMU from each of simulate's output times to the next and
// compares every compared output with the CSV row, bit for bit.
void expect_fmu_is_simulate(const TempDir& dir, const std::string& fmu, const std::filesystem::path& csv,
                            const Scenario& run) {
  const auto rows = read_csv(csv);
  const auto outputs = static_cast<std::size_t>(std::llround(run.duration * run.rate));
  ASSERT_EQ(rows.size(), outputs + 1);
  std::filesystem::create_directory(dir / (fmu + ".d"));
  FmiHost host(dir / fmu, dir / (fmu + ".d"));
  ASSERT_EQ(host.instantiate(), fmi2OK);
  ASSERT_EQ(host.setup_experiment(0.0), fmi2OK);
  ASSERT_EQ(host.enter_initialization_mode(), fmi2OK);
  std::vector<fmi2ValueReference> parameters = {vr_of(host, "step")};
  std::vector<double> parameter_values = {run.step};
  const char* const euler[3] = {"phi0", "theta0", "psi0"};
  for (int i = 0; i < 3; ++i) parameters.push_back(vr_of(host, euler[i]));
  parameter_values.insert(parameter_values.end(), run.euler0.begin(), run.euler0.end());
  const char* const nu[6] = {"u0", "v0", "w0", "p0", "q0", "r0"};
  for (int i = 0; i < 6; ++i) parameters.push_back(vr_of(host, nu[i]));
  parameter_values.insert(parameter_values.end(), run.velocity0.begin(), run.velocity0.end());
  ASSERT_EQ(host.set_real(parameters, parameter_values), fmi2OK);
  std::vector<fmi2ValueReference> inputs;
  std::vector<double> input_values = run.tau;
  for (const char* dof : {"X", "Y", "Z", "K", "M", "N"}) inputs.push_back(vr_of(host, dof));
  for (const char* axis : {"current_north", "current_east", "current_down"}) inputs.push_back(vr_of(host, axis));
  input_values.insert(input_values.end(), run.current.begin(), run.current.end());
  ASSERT_EQ(host.set_real(inputs, input_values), fmi2OK);
  ASSERT_EQ(host.exit_initialization_mode(), fmi2OK);
  std::vector<fmi2ValueReference> compared;
  for (const auto& c : kCompared) compared.push_back(vr_of(host, c.second));
  std::size_t mismatches = 0;
  std::vector<double> values;
  double t = 0.0;
  for (std::size_t k = 0; k <= outputs; ++k) {
    if (k > 0) {
      const double event = static_cast<double>(k) / run.rate;
      ASSERT_EQ(host.do_step(t, event - t), fmi2OK) << (host.log().empty() ? "" : host.log().back().message);
      t = event;
    }
    ASSERT_EQ(host.get_real(compared, values), fmi2OK);
    for (std::size_t c = 0; c < kCompared.size(); ++c)
      if (!same_bits(values[c], rows[k][kCompared[c].first])) {
        if (++mismatches <= 5)
          ADD_FAILURE() << "t = " << rows[k][0] << ": " << kCompared[c].second << " is " << values[c]
                        << " from the FMU, " << rows[k][kCompared[c].first] << " from simulate";
      }
  }
  EXPECT_EQ(mismatches, 0u);
  // The run went somewhere: the yaw rate is well away from rest.
  EXPECT_GT(std::abs(values[15]), 1e-3);
  ASSERT_EQ(host.terminate(), fmi2OK);
  host.free_instance();
}

std::string scenario_json(const Scenario& run) {
  std::ostringstream out;
  out.precision(17);
  out << R"({"duration": )" << run.duration << R"(, "output_rate": )" << run.rate
      << R"(, "integrator": {"method": "rk4", "step": )" << run.step << R"(}, "initial": {"euler_rad": [)";
  for (int i = 0; i < 3; ++i) out << (i ? ", " : "") << run.euler0[i];
  out << R"(], "velocity": [)";
  for (int i = 0; i < 6; ++i) out << (i ? ", " : "") << run.velocity0[i];
  out << R"(]}, "segments": [{"start": 0.0, "tau": {)";
  const char* const dofs[6] = {"X", "Y", "Z", "K", "M", "N"};
  for (int i = 0; i < 6; ++i) out << (i ? ", " : "") << '"' << dofs[i] << "\": " << run.tau[i];
  out << R"(}, "current": [)" << run.current[0] << ", " << run.current[1] << ", " << run.current[2] << "]}]}";
  return out.str();
}

TEST(FmuVehicle, TheAsrVPoolTestIsSimulateBitForBit) {
  TempDir dir;
  ASSERT_NO_FATAL_FAILURE(test::make_asr_v_example_database(dir));
  const auto exported =
      run_cli({"export-fmu", "asr-v", "--vehicle", kExample + "vehicle.json", "-o", "asr-v.fmu"}, dir.path());
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  EXPECT_NE(exported.out.find("exported vehicle "), std::string::npos) << exported.out;
  const auto simulated = run_cli({"simulate", "--vehicle", kExample + "vehicle.json", "--scenario",
                                  kExample + "scenario-yaw-0.0027.json", "--out", "pool.csv"},
                                 dir.path());
  ASSERT_EQ(simulated.exit_code, 0) << simulated.err;
  expect_fmu_is_simulate(dir, "asr-v.fmu", dir / "pool.csv",
                         {60.0, 10.0, 0.001, {0, 0, 0, 0, 0, 0.0027}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0, 0, 0, 0}});
}

TEST(FmuVehicle, TheSurfaceDampedAsrVInACurrentIsSimulateBitForBit) {
  TempDir dir;
  ASSERT_NO_FATAL_FAILURE(test::make_asr_v_example_database(dir));
  const auto exported = run_cli(
      {"export-fmu", "asr-v", "--vehicle", kExample + "vehicle-surfaces.json", "-o", "surfaces.fmu"}, dir.path());
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  const Scenario run{8.0,
                     5.0,
                     0.004,
                     {0.05, 0.02, 0.0, 0.0, 0.0, 0.004},
                     {0.1, -0.05, 0.01},
                     {0.05, -0.03, 0.4},
                     {0.1, 0.02, 0.0, 0.0, 0.01, 0.05}};
  std::ofstream(dir / "current.json") << scenario_json(run);
  const auto simulated = run_cli({"simulate", "--vehicle", kExample + "vehicle-surfaces.json", "--scenario",
                                  (dir / "current.json").string(), "--out", "current.csv"},
                                 dir.path());
  ASSERT_EQ(simulated.exit_code, 0) << simulated.err;
  expect_fmu_is_simulate(dir, "surfaces.fmu", dir / "current.csv", run);
}

class FmuVehicleCalls : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    test::make_asr_v_example_database(*dir_);
    for (const auto& [vehicle, fmu] : std::vector<std::pair<std::string, std::string>>{
             {"vehicle.json", "laws.fmu"}, {"vehicle-surfaces.json", "surfaces.fmu"}}) {
      const auto exported = run_cli({"export-fmu", "asr-v", "--vehicle", kExample + vehicle, "-o", fmu}, dir_->path());
      ASSERT_EQ(exported.exit_code, 0) << exported.err;
    }
    const auto surface = run_cli({"export-fmu", "asr-v", "--surface", "asr-v-yaw", "-o", "yaw.fmu"}, dir_->path());
    ASSERT_EQ(surface.exit_code, 0) << surface.err;
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  void SetUp() override {
    unzipped_ = std::make_unique<TempDir>();
    host_ = std::make_unique<FmiHost>(*dir_ / "laws.fmu", unzipped_->path());
    ASSERT_EQ(host_->instantiate(), fmi2OK);
    ASSERT_EQ(host_->setup_experiment(0.0), fmi2OK);
    ASSERT_EQ(host_->enter_initialization_mode(), fmi2OK);
  }
  void TearDown() override { host_.reset(); }
  bool logged(const std::string& text) const {
    for (const auto& entry : host_->log())
      if (entry.status == fmi2Error && entry.message.find(text) != std::string::npos) return true;
    return false;
  }
  std::string last() const { return host_->log().empty() ? "(nothing logged)" : host_->log().back().message; }
  static TempDir* dir_;
  std::unique_ptr<TempDir> unzipped_;
  std::unique_ptr<FmiHost> host_;
};
TempDir* FmuVehicleCalls::dir_ = nullptr;

TEST_F(FmuVehicleCalls, AParameterSetAfterInitialisationIsRefused) {
  const fmi2ValueReference step = vr_of(*host_, "step");
  const double small = 0.002;
  ASSERT_EQ(host_->set_real({step}, {small}), fmi2OK);  // in initialisation: allowed
  ASSERT_EQ(host_->exit_initialization_mode(), fmi2OK);
  // The host refuses on its own side; the FMU too, when called.
  EXPECT_THROW(host_->set_real({step}, {0.01}), test::HostRefusal);
  EXPECT_EQ(host_->raw().SetReal(host_->component(), &step, 1, &small), fmi2Error);
  EXPECT_TRUE(logged("is a fixed parameter")) << last();
}

TEST_F(FmuVehicleCalls, AnUnknownValueReferenceIsRefused) {
  // vehicle.json's damping reads no disturbance: the Reals end with the parameters.
  const auto count = static_cast<fmi2ValueReference>(host_->model().variables.size());
  const double value = 1.0;
  EXPECT_EQ(host_->raw().SetReal(host_->component(), &count, 1, &value), fmi2Error);
  EXPECT_TRUE(logged("unknown value reference " + std::to_string(count))) << last();
}

TEST_F(FmuVehicleCalls, ANaNInputFailsTheStepWithItsName) {
  ASSERT_EQ(host_->exit_initialization_mode(), fmi2OK);
  ASSERT_EQ(host_->do_step(0.0, 0.1), fmi2OK);
  ASSERT_EQ(host_->set_real({vr_of(*host_, "current_east")}, {std::numeric_limits<double>::quiet_NaN()}), fmi2OK);
  EXPECT_EQ(host_->do_step(0.1, 0.1), fmi2Error);
  EXPECT_TRUE(logged("input 'current_east' (value reference 7) is nan; expected a finite value")) << last();
  EXPECT_EQ(host_->state(), "error");
}

TEST_F(FmuVehicleCalls, ANaNOrZeroStepParameterFailsInitialisation) {
  ASSERT_EQ(host_->set_real({vr_of(*host_, "psi0")}, {std::numeric_limits<double>::infinity()}), fmi2OK);
  EXPECT_EQ(host_->exit_initialization_mode(), fmi2Error);
  EXPECT_TRUE(logged("parameter 'psi0'")) << last();
  ASSERT_EQ(host_->reset(), fmi2OK);
  ASSERT_EQ(host_->setup_experiment(0.0), fmi2OK);
  ASSERT_EQ(host_->enter_initialization_mode(), fmi2OK);
  ASSERT_EQ(host_->set_real({vr_of(*host_, "step")}, {0.0}), fmi2OK);
  EXPECT_EQ(host_->exit_initialization_mode(), fmi2Error);
  EXPECT_TRUE(logged("parameter 'step' is 0; expected an internal RK4 step above 0 s")) << last();
}

TEST_F(FmuVehicleCalls, AnOutputCannotBeSet) {
  const fmi2ValueReference x = vr_of(*host_, "x_n");
  const double value = 1.0;
  EXPECT_EQ(host_->raw().SetReal(host_->component(), &x, 1, &value), fmi2Error);
  EXPECT_TRUE(logged("is an output")) << last();
}

// A step H that is not a multiple of the internal step: equal steps of at
// most the internal step (simulate's rule), so one step of 0.0025 with an
// internal step of 0.001 is three steps of 0.0025/3, not 0.001 + 0.001 +
// 0.0005; a reset instance starts again from the parameters.
TEST_F(FmuVehicleCalls, AStepIsSplitIntoEqualInternalSteps) {
  ASSERT_EQ(host_->set_real({vr_of(*host_, "N")}, {0.5}), fmi2OK);
  ASSERT_EQ(host_->exit_initialization_mode(), fmi2OK);
  ASSERT_EQ(host_->do_step(0.0, 0.0025), fmi2OK);
  std::vector<double> once, thirds;
  ASSERT_EQ(host_->get_real({vr_of(*host_, "r"), vr_of(*host_, "psi")}, once), fmi2OK);
  ASSERT_EQ(host_->reset(), fmi2OK);
  ASSERT_EQ(host_->setup_experiment(0.0), fmi2OK);
  ASSERT_EQ(host_->enter_initialization_mode(), fmi2OK);
  ASSERT_EQ(host_->set_real({vr_of(*host_, "N"), vr_of(*host_, "step")}, {0.5, 0.0025 / 3.0}), fmi2OK);
  ASSERT_EQ(host_->exit_initialization_mode(), fmi2OK);
  double t = 0.0;
  for (int k = 0; k < 3; ++k) {
    ASSERT_EQ(host_->do_step(t, 0.0025 / 3.0), fmi2OK);
    t += 0.0025 / 3.0;
  }
  ASSERT_EQ(host_->get_real({vr_of(*host_, "r"), vr_of(*host_, "psi")}, thirds), fmi2OK);
  EXPECT_GT(once[0], 0.0);
  EXPECT_TRUE(same_bits(once[0], thirds[0])) << once[0] << " " << thirds[0];
  EXPECT_TRUE(same_bits(once[1], thirds[1])) << once[1] << " " << thirds[1];
}

TEST_F(FmuVehicleCalls, TheModelDescriptionStatesTheVehiclesVariables) {
  const auto& model = host_->model();
  const std::vector<std::tuple<std::string, std::string, std::string>> expected = {
      {"X", "input", "N"},        {"N", "input", "N m"},        {"current_north", "input", "m/s"},
      {"x_n", "output", "m"},     {"q_eta", "output", "1"},     {"psi", "output", "rad"},
      {"u", "output", "m/s"},     {"r", "output", "rad/s"},     {"N_damping", "output", "N m"},
      {"step", "parameter", "s"}, {"psi0", "parameter", "rad"}, {"r0", "parameter", "rad/s"}};
  for (const auto& [name, causality, unit] : expected) {
    bool found = false;
    for (const auto& v : model.variables) {
      if (v.name != name) continue;
      found = true;
      EXPECT_EQ(v.causality, causality) << name;
      EXPECT_EQ(v.unit, unit) << name;
      if (causality == "parameter") EXPECT_EQ(v.variability, "fixed") << name;
    }
    EXPECT_TRUE(found) << name;
  }
  EXPECT_EQ(model.variables.size(), 9u + 22u + 13u);
  for (const auto& v : model.variables)
    if (v.name == "step") EXPECT_EQ(v.start, 0.001);
  for (const char* unit : {"N", "N m", "m/s", "rad/s", "m", "rad", "s"})
    EXPECT_NE(std::find(model.units.begin(), model.units.end(), unit), model.units.end()) << unit;
  // The damping depends directly on the current (its relative velocity); the pose on no input.
  const auto index = [&](const std::string& name) {
    for (const auto& v : model.variables)
      if (v.name == name) return v.index;
    return std::size_t{0};
  };
  EXPECT_EQ(model.outputs.at(index("N_damping")),
            (std::vector<std::size_t>{index("current_north"), index("current_east"), index("current_down")}));
  EXPECT_TRUE(model.outputs.at(index("x_n")).empty());
  // In initialisation they are those of the initial state: InitialUnknowns add its parameters.
  std::ifstream in(unzipped_->path() / "modelDescription.xml");
  const auto root = test::parse_xml(std::string(std::istreambuf_iterator<char>(in), {}));
  std::string initial_x;
  for (const auto* structure : root.all("ModelStructure"))
    for (const auto* unknowns : structure->all("InitialUnknowns"))
      for (const auto* unknown : unknowns->all("Unknown"))
        if (unknown->at("index") == std::to_string(index("x_n"))) initial_x = unknown->at("dependencies");
  EXPECT_NE((" " + initial_x + " ").find(" " + std::to_string(index("x_n0")) + " "), std::string::npos) << initial_x;
  EXPECT_EQ((" " + initial_x + " ").find(" " + std::to_string(index("step")) + " "), std::string::npos) << initial_x;
  EXPECT_NE(model.guid.find("hcrt-xxh64-"), std::string::npos);
}

TEST_F(FmuVehicleCalls, OneBinaryServesBothKinds) {
  const auto read = [](const std::filesystem::path& fmu) {
    std::ifstream in(fmu, std::ios::binary);
    return test::unzip_stored(std::string(std::istreambuf_iterator<char>(in), {}));
  };
  const auto vehicle = read(*dir_ / "surfaces.fmu"), surface = read(*dir_ / "yaw.fmu");
  const auto so = [](const std::map<std::string, std::string>& files) {
    for (const auto& [name, bytes] : files)
      if (name.starts_with("binaries/linux64/")) return bytes;
    return std::string();
  };
  EXPECT_FALSE(so(vehicle).empty());
  EXPECT_EQ(so(vehicle), so(surface));  // fmu_binary_test checks its ELF needs libc and libm only
  EXPECT_NE(vehicle.at("resources/model.hcr").find("vehicle"), std::string::npos);
}

TEST(FmuVehicleCli, RefusedExportsWriteNothing) {
  TempDir dir;
  ASSERT_NO_FATAL_FAILURE(test::make_asr_v_example_database(dir));
  std::ofstream(dir / "bad.json") << R"({"mass": -6.7, "inertia": [1, 1, 1], "center_of_gravity": [0, 0, 0],
                                        "neutrally_buoyant": true})";
  for (const auto& [args, text] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"export-fmu", "asr-v", "--vehicle", (dir / "bad.json").string(), "-o", "x.fmu"}, "'mass'"},
           {{"export-fmu", "asr-v", "--vehicle", kExample + "vehicle.json", "--surface", "asr-v-yaw", "-o", "x.fmu"},
            "--surface and --vehicle were both given"},
           {{"export-fmu", "asr-v", "-o", "x.fmu"}, "--surface or --vehicle is required"}}) {
    const auto result = run_cli(args, dir.path());
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_NE(result.err.find(text), std::string::npos) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.fmu"));
  }
}

}  // namespace
}  // namespace hydrocoef
