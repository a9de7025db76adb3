// libFuzzer target: OpenFOAM dictionaries (importers/openfoam_dictionary) from
// arbitrary text, parsed as a case file of a case folder that does not exist
// (so every #include is refused and no file is read), and its entries read as
// the case readers read them (scalars, vectors, words). The parser may accept
// the text or throw InputError; it must never recurse without bound (nesting
// is limited), nor copy `$` references without bound (expansion is counted).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "importers/openfoam_dictionary.hpp"
#include "tests/fuzz/fuzz_check.hpp"

namespace {

void visit(const hydrocoef::FoamDictionary& dictionary, int depth) {
  using namespace hydrocoef;
  if (depth > 256) fuzz::finding("dictionaries nested deeper than the limit");
  for (const char* key : {"internalField", "value", "rhoInf", "CofR", "omega", "amplitude", "nu"}) {
    const FoamValue* value = dictionary.value(key);
    if (!value) continue;
    if (value->tokens.size() > 100000) fuzz::finding("an entry longer than the limit");
    try {
      (void)foam_scalar(*value, key);
    } catch (const InputError& error) {
      fuzz::check_error(error);
    }
    try {
      (void)foam_vector(*value, key);
    } catch (const InputError& error) {
      fuzz::check_error(error);
    }
    (void)foam_word(value);
  }
  for (const auto& key : dictionary.dictionary_keys()) {
    const FoamDictionary* child = dictionary.dictionary(key);
    if (!child) fuzz::finding("a dictionary key without its dictionary", key);
    visit(*child, depth + 1);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hydrocoef;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const FoamDictionary dictionary =
        FoamDictionary::parse(text, "/nonexistent-hydrocoef-fuzz-case/system/controlDict");
    visit(dictionary, 0);
    for (const auto& warning : dictionary.warnings())
      if (warning.find('\n') != std::string::npos) fuzz::finding("a warning that spans lines", warning);
  } catch (const InputError& error) {
    fuzz::check_error(error);
  }
  return 0;
}
