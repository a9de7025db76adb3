// How the numbers of a force record, a damping law or a surface output are
// signed, and the one conversion between the two conventions.
//
// OnBody is the force the fluid exerts on the body, as SNAME's equations of
// motion use it: a damping force opposes the motion, so it is negative for
// positive velocity. OpposingMotion is a damping magnitude as tables and
// papers often print it: positive when it opposes the motion, the negative
// of OnBody. Converting is a negation whenever the conventions differ (the
// number's sign flips, its size does not), for forces, for moments and for
// law coefficients alike; every module converts through to_convention or
// sign_factor, never by writing the minus sign itself.
#pragma once

#include <optional>
#include <string_view>

namespace hydrocoef {

enum class SignConvention {
  OnBody,         ///< the force the fluid exerts on the body (SNAME); damping is negative
  OpposingMotion  ///< a damping magnitude: positive opposes motion (the negative of OnBody)
};

/// "on-body" or "opposing".
std::string_view to_string(SignConvention convention);
/// The convention named "on-body" or "opposing", or nullopt.
std::optional<SignConvention> sign_convention_named(std::string_view text);
/// Parses "on-body" or "opposing"; throws InputError otherwise.
SignConvention parse_sign_convention(std::string_view text);

/// The factor that turns a number signed `from` into one signed `to`: 1 when
/// they agree, -1 when they differ.
constexpr double sign_factor(SignConvention from, SignConvention to) { return from == to ? 1.0 : -1.0; }

/// `value`, signed `from`, as signed `to`: itself or its negative (a zero's
/// sign flips too, as for any negation).
constexpr double to_convention(double value, SignConvention from, SignConvention to) {
  return from == to ? value : -value;
}

/// `value`, signed `from`, as the force on the body.
constexpr double to_on_body(double value, SignConvention from) {
  return to_convention(value, from, SignConvention::OnBody);
}

}  // namespace hydrocoef
