// libFuzzer target: CFX Command Language (importers/cfx_ccl) from arbitrary
// text: parsed into objects and parameters, every parameter of every object
// evaluated as constant CEL (named expressions followed), and the lookups the
// case readers make. The parser and the evaluator may accept the text or
// throw InputError (CelNotConstant for CEL that is valid but not constant);
// a value they return is finite, and an object found by lookup is one of its
// parent's children.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "importers/cfx_ccl.hpp"
#include "tests/fuzz/fuzz_check.hpp"

namespace {

void visit(const hydrocoef::CclObject& object, const hydrocoef::CelEvaluator& cel, std::size_t& evaluations) {
  using namespace hydrocoef;
  for (const auto& parameter : object.parameters) {
    if (object.parameter(parameter.name) == nullptr) fuzz::finding("a parameter its object does not find");
    if (evaluations++ > 2000) return;  // enough per input
    try {
      const CelValue value = cel.evaluate(parameter);
      if (!std::isfinite(value.value)) fuzz::finding("a CEL value that is not finite", parameter.value);
    } catch (const InputError& error) {
      fuzz::check_error(error);
    }
  }
  for (const auto& child : object.children) {
    const CclObject* found = object.child(child.type, child.label);
    if (found == nullptr) fuzz::finding("a child its object does not find", child.title());
    visit(child, cel, evaluations);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hydrocoef;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto excerpt = ccl_from_solver_output(text);
    const CclDocument document =
        excerpt ? parse_ccl(excerpt->text, "fuzz.out", excerpt->first_line) : parse_ccl(text, "fuzz.ccl");
    const CelEvaluator cel(document);
    std::size_t evaluations = 0;
    visit(document.root, cel, evaluations);
  } catch (const InputError& error) {
    fuzz::check_error(error);
  }
  return 0;
}
