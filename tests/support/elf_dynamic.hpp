// The dynamic section and dynamic symbols of a 64-bit ELF shared object, for
// the tests that check what a built library needs and exports
// (tests/runtime/runtime_linking_test.cpp, tests/fmu/fmu_binary_test.cpp).
#pragma once

#include <elf.h>

#include <cstring>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace hydrocoef::test {

template <typename T>
T elf_read_at(const std::string& bytes, std::size_t offset) {
  T value;
  if (offset > bytes.size() || bytes.size() - offset < sizeof(T)) throw std::runtime_error("ELF read out of range");
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

struct ElfDynamic {
  std::vector<std::string> needed;  ///< DT_NEEDED entries, in order
  std::set<std::string> defined;    ///< global or weak dynamic symbols it defines
  std::set<std::string> undefined;  ///< those it takes from the libraries it needs
};

inline ElfDynamic elf_dynamic(const std::string& bytes) {
  const auto header = elf_read_at<Elf64_Ehdr>(bytes, 0);
  if (std::memcmp(header.e_ident, ELFMAG, SELFMAG) != 0 || header.e_ident[EI_CLASS] != ELFCLASS64)
    throw std::runtime_error("not a 64-bit ELF file");
  std::vector<Elf64_Shdr> sections;
  for (std::size_t i = 0; i < header.e_shnum; ++i)
    sections.push_back(elf_read_at<Elf64_Shdr>(bytes, header.e_shoff + i * header.e_shentsize));
  const auto text_at = [&](const Elf64_Shdr& strings, std::size_t offset) {
    if (strings.sh_offset + offset >= bytes.size()) throw std::runtime_error("ELF string out of range");
    return std::string(bytes.c_str() + strings.sh_offset + offset);
  };
  ElfDynamic out;
  for (const Elf64_Shdr& section : sections) {
    if (section.sh_type == SHT_DYNAMIC) {
      const Elf64_Shdr& strings = sections.at(section.sh_link);
      for (std::size_t at = section.sh_offset; at + sizeof(Elf64_Dyn) <= section.sh_offset + section.sh_size;
           at += sizeof(Elf64_Dyn)) {
        const auto entry = elf_read_at<Elf64_Dyn>(bytes, at);
        if (entry.d_tag == DT_NULL) break;
        if (entry.d_tag == DT_NEEDED) out.needed.push_back(text_at(strings, entry.d_un.d_val));
      }
    }
    if (section.sh_type == SHT_DYNSYM) {
      const Elf64_Shdr& strings = sections.at(section.sh_link);
      for (std::size_t at = section.sh_offset; at + sizeof(Elf64_Sym) <= section.sh_offset + section.sh_size;
           at += sizeof(Elf64_Sym)) {
        const auto symbol = elf_read_at<Elf64_Sym>(bytes, at);
        const std::string name = text_at(strings, symbol.st_name);
        if (name.empty() || ELF64_ST_BIND(symbol.st_info) == STB_LOCAL) continue;
        (symbol.st_shndx == SHN_UNDEF ? out.undefined : out.defined).insert(name);
      }
    }
  }
  return out;
}

}  // namespace hydrocoef::test
