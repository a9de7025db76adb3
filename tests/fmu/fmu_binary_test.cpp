// The FMU binary as a dependency-free shared object: its ELF DT_NEEDED
// entries are libc and libm only (libhydrocoef_runtime is linked in
// statically), and it exports exactly the 34 functions of an FMI 2.0
// Co-Simulation FMU (fmu/include/hydrocoef/fmi2_interface.h) and nothing
// else: no hc_runtime_* symbol of the runtime inside it.
#include <elf.h>
#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "tests/support/elf_dynamic.hpp"
#include "tests/support/run_cli.hpp"

namespace hydrocoef {
namespace {

TEST(FmuBinary, NeedsLibcAndLibmOnlyAndExportsTheFmiFunctionsAlone) {
  const std::string bytes = test::read_text(HYDROCOEF_FMU_BINARY);
  ASSERT_FALSE(bytes.empty()) << HYDROCOEF_FMU_BINARY;
  const test::ElfDynamic dynamic = test::elf_dynamic(bytes);
  bool libc = false;
  for (const std::string& needed : dynamic.needed) {
    EXPECT_TRUE(needed == "libc.so.6" || needed == "libm.so.6") << "the FMU binary needs " << needed;
    libc = libc || needed == "libc.so.6";
  }
  EXPECT_TRUE(libc);
  const std::set<std::string> expected = {"fmi2GetTypesPlatform",
                                          "fmi2GetVersion",
                                          "fmi2SetDebugLogging",
                                          "fmi2Instantiate",
                                          "fmi2FreeInstance",
                                          "fmi2SetupExperiment",
                                          "fmi2EnterInitializationMode",
                                          "fmi2ExitInitializationMode",
                                          "fmi2Terminate",
                                          "fmi2Reset",
                                          "fmi2GetReal",
                                          "fmi2GetInteger",
                                          "fmi2GetBoolean",
                                          "fmi2GetString",
                                          "fmi2SetReal",
                                          "fmi2SetInteger",
                                          "fmi2SetBoolean",
                                          "fmi2SetString",
                                          "fmi2GetFMUstate",
                                          "fmi2SetFMUstate",
                                          "fmi2FreeFMUstate",
                                          "fmi2SerializedFMUstateSize",
                                          "fmi2SerializeFMUstate",
                                          "fmi2DeSerializeFMUstate",
                                          "fmi2GetDirectionalDerivative",
                                          "fmi2SetRealInputDerivatives",
                                          "fmi2GetRealOutputDerivatives",
                                          "fmi2DoStep",
                                          "fmi2CancelStep",
                                          "fmi2GetStatus",
                                          "fmi2GetRealStatus",
                                          "fmi2GetIntegerStatus",
                                          "fmi2GetBooleanStatus",
                                          "fmi2GetStringStatus"};
  EXPECT_EQ(expected.size(), 34u);
  EXPECT_EQ(dynamic.defined, expected);
  for (const std::string& symbol : dynamic.undefined) {
    EXPECT_EQ(symbol.rfind("hc_", 0), std::string::npos) << symbol;
    EXPECT_EQ(symbol.find("_Z"), std::string::npos) << "a C++ symbol: " << symbol;
  }
}

}  // namespace
}  // namespace hydrocoef
