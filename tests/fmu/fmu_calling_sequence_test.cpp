// The FMU enforces the Co-Simulation calling sequence of FMI 2.0 (section
// 4.2.4) and never trusts its arguments: each illegal sequence, made on
// purpose through the raw functions, returns fmi2Error (or NULL from
// fmi2Instantiate) with a logger message naming the call and the state or
// the bad argument, and never crashes (the suite runs under ASan and UBSan).
// The host refuses the same illegal calls on its own side without calling
// the FMU. An instance in the error state accepts fmi2Reset and works again.
#include <gtest/gtest.h>

#include <fstream>

#include "tests/fmu/fmi_host.hpp"
#include "tests/fmu/fmu_test_database.hpp"

namespace hydrocoef {
namespace {

using test::FmiHost;
using test::HostRefusal;
using test::TempDir;

// One FMU of the surge surface (input u: vr 0; output X: vr 1; sigma(X): vr 2)
// and one of the surface refusing values outside its axis, exported once.
class FmuCalls : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    test::make_fmu_database(*dir_);
    test::export_fmu_file(*dir_, "asr-v", "surge", "surge.fmu");
    test::export_fmu_file(*dir_, "asr-v", "surge-strict", "strict.fmu");
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  void SetUp() override {
    unzipped_ = std::make_unique<TempDir>();
    host_ = std::make_unique<FmiHost>(*dir_ / "surge.fmu", unzipped_->path());
  }
  void TearDown() override { host_.reset(); }

  // The instance in step mode (stepComplete).
  void initialised() {
    ASSERT_EQ(host_->instantiate(), fmi2OK);
    ASSERT_EQ(host_->setup_experiment(0.0), fmi2OK);
    ASSERT_EQ(host_->enter_initialization_mode(), fmi2OK);
    ASSERT_EQ(host_->exit_initialization_mode(), fmi2OK);
    host_->clear_log();
  }

  // The status was fmi2Error and the logger received an error mentioning every text.
  void expect_refused(fmi2Status status, const std::vector<std::string>& texts) {
    EXPECT_EQ(status, fmi2Error);
    bool found = false;
    for (const auto& entry : host_->log()) {
      bool all = entry.status == fmi2Error && entry.category == "logStatusError";
      for (const auto& text : texts) all = all && entry.message.find(text) != std::string::npos;
      found = found || all;
    }
    std::string messages;
    for (const auto& entry : host_->log()) messages += entry.message + "\n";
    EXPECT_TRUE(found) << "no error message with the expected text among:\n" << messages;
  }

  static TempDir* dir_;
  std::unique_ptr<TempDir> unzipped_;
  std::unique_ptr<FmiHost> host_;
};

TempDir* FmuCalls::dir_ = nullptr;

const fmi2ValueReference kU = 0, kX = 1, kSigma = 2;

TEST_F(FmuCalls, DoStepBeforeInitialisationIsRefused) {
  ASSERT_EQ(host_->instantiate(), fmi2OK);
  expect_refused(host_->raw().DoStep(host_->component(), 0.0, 0.1, fmi2True),
                 {"fmi2DoStep is not allowed in state instantiated", "stepComplete"});
}

TEST_F(FmuCalls, DoStepInInitialisationModeIsRefused) {
  ASSERT_EQ(host_->instantiate(), fmi2OK);
  ASSERT_EQ(host_->enter_initialization_mode(), fmi2OK);
  expect_refused(host_->raw().DoStep(host_->component(), 0.0, 0.1, fmi2True), {"fmi2DoStep", "initializationMode"});
}

TEST_F(FmuCalls, SettingAnOutputIsRefused) {
  initialised();
  const double value = 1.0;
  for (const fmi2ValueReference vr : {kX, kSigma}) {
    host_->clear_log();
    ASSERT_EQ(host_->raw().Reset(host_->component()), fmi2OK);
    expect_refused(host_->raw().SetReal(host_->component(), &vr, 1, &value),
                   {"value reference " + std::to_string(vr) + " is an output"});
  }
}

TEST_F(FmuCalls, CallsWithoutAnInstanceReturnErrorWithoutCrashing) {
  fmi2ValueReference vr = kX;
  double value = 0.0;
  const auto& f = host_->raw();
  EXPECT_EQ(f.GetReal(nullptr, &vr, 1, &value), fmi2Error);
  EXPECT_EQ(f.SetReal(nullptr, &vr, 1, &value), fmi2Error);
  EXPECT_EQ(f.DoStep(nullptr, 0.0, 0.1, fmi2True), fmi2Error);
  EXPECT_EQ(f.EnterInitializationMode(nullptr), fmi2Error);
  f.FreeInstance(nullptr);
  // A pointer that is not an instance is never dereferenced.
  int not_an_instance[64] = {};
  EXPECT_EQ(f.GetReal(not_an_instance, &vr, 1, &value), fmi2Error);
  EXPECT_EQ(f.Terminate(not_an_instance), fmi2Error);
  f.FreeInstance(not_an_instance);
  EXPECT_EQ(not_an_instance[0], 0);
}

TEST_F(FmuCalls, DoubleFreeAndUseAfterFreeAreRefused) {
  initialised();
  const fmi2Component c = host_->component();
  host_->free_instance();
  // The host refuses a second free itself; the FMU, called anyway, ignores it.
  EXPECT_THROW(host_->free_instance(), HostRefusal);
  host_->raw().FreeInstance(c);
  fmi2ValueReference vr = kX;
  double value = 0.0;
  EXPECT_EQ(host_->raw().GetReal(c, &vr, 1, &value), fmi2Error);
  EXPECT_EQ(host_->raw().DoStep(c, 0.0, 0.1, fmi2True), fmi2Error);
}

TEST_F(FmuCalls, UnknownValueReferencesAreRefused) {
  initialised();
  const fmi2ValueReference vr = 99;
  double value = 0.0;
  expect_refused(host_->raw().GetReal(host_->component(), &vr, 1, &value), {"unknown value reference 99"});
  ASSERT_EQ(host_->raw().Reset(host_->component()), fmi2OK);
  host_->clear_log();
  expect_refused(host_->raw().SetReal(host_->component(), &vr, 1, &value), {"unknown value reference 99"});
  ASSERT_EQ(host_->raw().Reset(host_->component()), fmi2OK);
  host_->clear_log();
  const int integer = 0;
  expect_refused(host_->raw().SetInteger(host_->component(), &kU, 1, &integer),
                 {"fmi2SetInteger: unknown value reference 0; this FMU has Real variables only"});
}

TEST_F(FmuCalls, NullArraysAreRefused) {
  initialised();
  double value = 0.0;
  expect_refused(host_->raw().GetReal(host_->component(), nullptr, 1, &value), {"fmi2GetReal: vr is NULL"});
  ASSERT_EQ(host_->raw().Reset(host_->component()), fmi2OK);
  host_->clear_log();
  expect_refused(host_->raw().SetReal(host_->component(), &kU, 1, nullptr), {"fmi2SetReal: value is NULL"});
  ASSERT_EQ(host_->raw().Reset(host_->component()), fmi2OK);
  host_->clear_log();
  expect_refused(host_->raw().GetRealStatus(host_->component(), fmi2LastSuccessfulTime, nullptr),
                 {"fmi2GetRealStatus is not allowed in state instantiated"});
  // nvr = 0 with NULL arrays is a call that does nothing.
  ASSERT_EQ(host_->raw().Reset(host_->component()), fmi2OK);
  EXPECT_EQ(host_->raw().SetReal(host_->component(), nullptr, 0, nullptr), fmi2OK);
}

TEST_F(FmuCalls, InitialisationOutOfOrderIsRefused) {
  ASSERT_EQ(host_->instantiate(), fmi2OK);
  expect_refused(host_->raw().ExitInitializationMode(host_->component()),
                 {"fmi2ExitInitializationMode is not allowed in state instantiated"});
  ASSERT_EQ(host_->raw().Reset(host_->component()), fmi2OK);
  ASSERT_EQ(host_->raw().EnterInitializationMode(host_->component()), fmi2OK);
  host_->clear_log();
  expect_refused(host_->raw().SetupExperiment(host_->component(), fmi2False, 0.0, 0.0, fmi2False, 0.0),
                 {"fmi2SetupExperiment is not allowed in state initializationMode"});
}

TEST_F(FmuCalls, TerminateBeforeStepModeAndStepsAfterTerminateAreRefused) {
  ASSERT_EQ(host_->instantiate(), fmi2OK);
  expect_refused(host_->raw().Terminate(host_->component()), {"fmi2Terminate is not allowed in state instantiated"});
  host_->reset();
  ASSERT_EQ(host_->enter_initialization_mode(), fmi2OK);
  ASSERT_EQ(host_->exit_initialization_mode(), fmi2OK);
  ASSERT_EQ(host_->terminate(), fmi2OK);
  expect_refused(host_->raw().DoStep(host_->component(), 0.0, 0.1, fmi2True),
                 {"fmi2DoStep is not allowed in state terminated"});
}

TEST_F(FmuCalls, BadStepsAreRefused) {
  initialised();
  expect_refused(host_->raw().DoStep(host_->component(), 0.0, -0.1, fmi2True), {"expected finite values and a step"});
  ASSERT_EQ(host_->raw().Reset(host_->component()), fmi2OK);
  ASSERT_EQ(host_->raw().EnterInitializationMode(host_->component()), fmi2OK);
  ASSERT_EQ(host_->raw().ExitInitializationMode(host_->component()), fmi2OK);
  host_->clear_log();
  expect_refused(host_->raw().DoStep(host_->component(), 5.0, 0.1, fmi2True),
                 {"currentCommunicationPoint 5 is not the instance's time 0"});
}

TEST_F(FmuCalls, CapabilitiesTheFmuDoesNotHaveAreRefused) {
  initialised();
  fmi2FMUstate state = nullptr;
  expect_refused(host_->raw().GetFMUstate(host_->component(), &state), {"canGetAndSetFMUstate"});
  ASSERT_EQ(host_->raw().Reset(host_->component()), fmi2OK);
  ASSERT_EQ(host_->raw().EnterInitializationMode(host_->component()), fmi2OK);
  ASSERT_EQ(host_->raw().ExitInitializationMode(host_->component()), fmi2OK);
  host_->clear_log();
  expect_refused(host_->raw().CancelStep(host_->component()),
                 {"fmi2CancelStep is not allowed in state stepComplete", "stepInProgress"});
}

TEST_F(FmuCalls, InTheErrorStateOnlyResetFreeAndGettersAreAccepted) {
  initialised();
  const fmi2ValueReference vr = 99;
  double value = 0.0;
  std::vector<double> values;
  EXPECT_EQ(host_->get_real({vr}, values), fmi2Error);
  EXPECT_EQ(host_->state(), "error");
  EXPECT_THROW(host_->do_step(0.0, 0.1), HostRefusal);
  host_->clear_log();
  expect_refused(host_->raw().DoStep(host_->component(), 0.0, 0.1, fmi2True), {"not allowed in state error"});
  EXPECT_EQ(host_->raw().GetReal(host_->component(), &kX, 1, &value), fmi2OK);
  ASSERT_EQ(host_->reset(), fmi2OK);
  ASSERT_EQ(host_->enter_initialization_mode(), fmi2OK);
  ASSERT_EQ(host_->exit_initialization_mode(), fmi2OK);
  ASSERT_EQ(host_->do_step(0.0, 0.1), fmi2OK);
}

TEST_F(FmuCalls, TheHostRefusesIllegalCallsWithoutCallingTheFmu) {
  EXPECT_THROW(host_->do_step(0.0, 0.1), HostRefusal);
  EXPECT_THROW(host_->enter_initialization_mode(), HostRefusal);
  ASSERT_EQ(host_->instantiate(), fmi2OK);
  EXPECT_THROW(host_->instantiate(), HostRefusal);
  EXPECT_THROW(host_->do_step(0.0, 0.1), HostRefusal);
  EXPECT_THROW(host_->exit_initialization_mode(), HostRefusal);
  EXPECT_THROW(host_->terminate(), HostRefusal);
  std::vector<double> values;
  EXPECT_THROW(host_->get_real({kX}, values), HostRefusal);
  EXPECT_THROW(host_->set_real({kX}, {1.0}), HostRefusal);
  EXPECT_TRUE(host_->log().empty());
  EXPECT_EQ(host_->state(), "instantiated");
}

TEST_F(FmuCalls, InstantiateRefusesWhatItCannotUse) {
  const auto& f = host_->raw();
  const std::string uri = host_->resource_uri();
  const std::string guid = host_->model().guid;
  // No call-backs: nobody to tell, NULL.
  EXPECT_EQ(f.Instantiate("a", fmi2CoSimulation, guid.c_str(), uri.c_str(), nullptr, fmi2False, fmi2False), nullptr);
  const struct Bad {
    std::string name;
    fmi2Type type;
    std::string guid, uri, expected;
  } cases[] = {
      {"a", fmi2ModelExchange, guid, uri, "Co-Simulation only"},
      {"", fmi2CoSimulation, guid, uri, "instanceName is empty"},
      {"a", fmi2CoSimulation, "hcrt-xxh64-0000000000000000", uri, "does not match the resource file"},
      {"a", fmi2CoSimulation, guid, "http://example.com/resources", "is not a file URI"},
      {"a", fmi2CoSimulation, guid, "file:resources", "relative path"},
      {"a", fmi2CoSimulation, guid, "file://otherhost/resources", "names host 'otherhost'"},
      {"a", fmi2CoSimulation, guid, uri + "%00/x", "encodes a NUL byte"},
      {"a", fmi2CoSimulation, guid, uri + "%G1", "malformed percent escape"},
      {"a", fmi2CoSimulation, guid, uri + "/missing", "cannot load the FMU's model"},
      {"a", fmi2CoSimulation, guid, "file://" + std::string(20000, 'a'), "longer than"},
  };
  for (const auto& bad : cases) {
    SCOPED_TRACE(bad.expected);
    host_->clear_log();
    EXPECT_EQ(f.Instantiate(bad.name.c_str(), bad.type, bad.guid.c_str(), bad.uri.c_str(), host_->callbacks(),
                            fmi2False, fmi2False),
              nullptr);
    expect_refused(fmi2Error, {bad.expected});
  }
  host_->clear_log();
  EXPECT_EQ(f.Instantiate("a", fmi2CoSimulation, nullptr, uri.c_str(), host_->callbacks(), fmi2False, fmi2False),
            nullptr);
  expect_refused(fmi2Error, {"fmuGUID is NULL"});
  host_->clear_log();
  EXPECT_EQ(f.Instantiate("a", fmi2CoSimulation, guid.c_str(), nullptr, host_->callbacks(), fmi2False, fmi2False),
            nullptr);
  expect_refused(fmi2Error, {"fmuResourceLocation is NULL"});
  // The forms of a local file URI the standard's hosts give are accepted.
  for (const std::string& form : {uri, "file:" + uri.substr(7), "file://localhost" + uri.substr(7), uri + "/"}) {
    SCOPED_TRACE(form);
    const fmi2Component c =
        f.Instantiate("a", fmi2CoSimulation, guid.c_str(), form.c_str(), host_->callbacks(), fmi2False, fmi2False);
    EXPECT_NE(c, nullptr);
    f.FreeInstance(c);
  }
}

TEST_F(FmuCalls, ATamperedResourceFileIsRefusedAtInstantiate) {
  const auto path = unzipped_->path() / "resources/model.hcr";
  std::string bytes = test::read_text(path);
  bytes[bytes.size() - 3] = static_cast<char>(bytes[bytes.size() - 3] ^ 0x40);
  std::ofstream(path, std::ios::binary) << bytes;
  EXPECT_EQ(host_->instantiate(), fmi2Error);
  expect_refused(fmi2Error, {"HC_RUNTIME_E_HASH"});
  EXPECT_EQ(host_->state(), "startAndEnd");
}

TEST_F(FmuCalls, InstanceNamesAreDataInLogMessages) {
  const std::string name = "%s%n%d<>&\"'";
  const auto& f = host_->raw();
  const std::string uri = host_->resource_uri();
  const fmi2Component c = f.Instantiate(name.c_str(), fmi2CoSimulation, host_->model().guid.c_str(), uri.c_str(),
                                        host_->callbacks(), fmi2False, fmi2False);
  ASSERT_NE(c, nullptr);
  const std::string category = "no such category %s%n";
  const fmi2String categories[] = {category.c_str()};
  EXPECT_EQ(f.SetDebugLogging(c, fmi2True, 1, categories), fmi2Error);
  ASSERT_FALSE(host_->log().empty());
  EXPECT_EQ(host_->log().back().instance, name);
  EXPECT_NE(host_->log().back().message.find("'no such category %s%n'"), std::string::npos)
      << host_->log().back().message;
  f.FreeInstance(c);
}

TEST_F(FmuCalls, AnInputOutsideAnAxisThatRefusesItFailsTheStepNamingTheAxis) {
  TempDir unzipped;
  FmiHost strict(*dir_ / "strict.fmu", unzipped.path());
  ASSERT_EQ(strict.instantiate(), fmi2OK);
  ASSERT_EQ(strict.enter_initialization_mode(), fmi2OK);
  ASSERT_EQ(strict.exit_initialization_mode(), fmi2OK);
  ASSERT_EQ(strict.set_real({kU}, {25.0}), fmi2OK);
  EXPECT_EQ(strict.do_step(0.0, 0.1), fmi2Error);
  ASSERT_FALSE(strict.log().empty());
  const std::string& message = strict.log().back().message;
  EXPECT_NE(message.find("HC_RUNTIME_E_OUTSIDE"), std::string::npos) << message;
  EXPECT_NE(message.find("u"), std::string::npos) << message;
  EXPECT_NE(message.find("25"), std::string::npos) << message;
  ASSERT_EQ(strict.reset(), fmi2OK);
  ASSERT_EQ(strict.enter_initialization_mode(), fmi2OK);
  ASSERT_EQ(strict.set_real({kU}, {std::nan("")}), fmi2OK);
  EXPECT_EQ(strict.exit_initialization_mode(), fmi2Error);
  EXPECT_NE(strict.log().back().message.find("HC_RUNTIME_E_NOT_FINITE"), std::string::npos)
      << strict.log().back().message;
}

}  // namespace
}  // namespace hydrocoef
