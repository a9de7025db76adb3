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

#include "tests/support/run_cli.hpp"

namespace hydrocoef {
namespace {

template <typename T>
T read_at(const std::string& bytes, std::size_t offset) {
  T value;
  if (offset > bytes.size() || bytes.size() - offset < sizeof(T)) throw std::runtime_error("ELF read out of range");
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

struct Dynamic {
  std::vector<std::string> needed;
  std::set<std::string> defined;    // global, defined
  std::set<std::string> undefined;  // what it takes from the libraries
};

Dynamic dynamic_of(const std::string& bytes) {
  const auto header = read_at<Elf64_Ehdr>(bytes, 0);
  if (std::memcmp(header.e_ident, ELFMAG, SELFMAG) != 0 || header.e_ident[EI_CLASS] != ELFCLASS64)
    throw std::runtime_error("not a 64-bit ELF file");
  std::vector<Elf64_Shdr> sections;
  for (std::size_t i = 0; i < header.e_shnum; ++i)
    sections.push_back(read_at<Elf64_Shdr>(bytes, header.e_shoff + i * header.e_shentsize));
  Dynamic out;
  for (const Elf64_Shdr& section : sections) {
    const Elf64_Shdr& strings = sections.at(section.sh_link);
    if (section.sh_type == SHT_DYNAMIC) {
      for (std::size_t at = section.sh_offset; at + sizeof(Elf64_Dyn) <= section.sh_offset + section.sh_size;
           at += sizeof(Elf64_Dyn)) {
        const auto entry = read_at<Elf64_Dyn>(bytes, at);
        if (entry.d_tag == DT_NULL) break;
        if (entry.d_tag == DT_NEEDED) out.needed.emplace_back(bytes.c_str() + strings.sh_offset + entry.d_un.d_val);
      }
    }
    if (section.sh_type == SHT_DYNSYM) {
      for (std::size_t at = section.sh_offset; at + sizeof(Elf64_Sym) <= section.sh_offset + section.sh_size;
           at += sizeof(Elf64_Sym)) {
        const auto symbol = read_at<Elf64_Sym>(bytes, at);
        const std::string name = bytes.c_str() + strings.sh_offset + symbol.st_name;
        if (name.empty() || ELF64_ST_BIND(symbol.st_info) == STB_LOCAL) continue;
        (symbol.st_shndx == SHN_UNDEF ? out.undefined : out.defined).insert(name);
      }
    }
  }
  return out;
}

TEST(FmuBinary, NeedsLibcAndLibmOnlyAndExportsTheFmiFunctionsAlone) {
  const std::string bytes = test::read_text(HYDROCOEF_FMU_BINARY);
  ASSERT_FALSE(bytes.empty()) << HYDROCOEF_FMU_BINARY;
  const Dynamic dynamic = dynamic_of(bytes);
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
