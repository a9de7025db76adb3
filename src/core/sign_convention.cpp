#include "src/core/sign_convention.hpp"

#include <string>

#include "src/core/error.hpp"

namespace hydrocoef {

std::string_view to_string(SignConvention convention) {
  return convention == SignConvention::OnBody ? "on-body" : "opposing";
}

std::optional<SignConvention> sign_convention_named(std::string_view text) {
  if (text == "on-body") return SignConvention::OnBody;
  if (text == "opposing") return SignConvention::OpposingMotion;
  return std::nullopt;
}

SignConvention parse_sign_convention(std::string_view text) {
  if (const auto convention = sign_convention_named(text)) return *convention;
  throw InputError("unknown sign convention '" + std::string(text) +
                   "': expected 'on-body' (force on the body) or 'opposing' (positive opposes motion)");
}

}  // namespace hydrocoef
