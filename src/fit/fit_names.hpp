// The names fits are stored under, in one place, so that a name says what the
// fit is: a fit of all the selected runs, "BODY:DOF(TERMS)", with the run
// selection it used after an '@' ("sphere:X(u,u|u|)@v=0"), and one level of a
// per-level fit (fit --by) in brackets after that ("sphere:X(u,u|u|)[v=0]",
// "sphere:X(u,u|u|)@w=0[v=0.05]"). A filtered fit and a per-level fit can
// therefore never be taken for each other.
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace hydrocoef {

/// "BODY:DOF(TERMS)" and "@SELECTION" when the selection is not empty.
std::string default_fit_name(const std::string& body, const std::string& dof, const std::string& terms,
                             const std::string& selection);

/// BASE[BY=LEVEL], the level written as the shortest text that reads back to it.
std::string per_level_fit_name(const std::string& base, const std::string& by, double level);

/// The level of a per-level fit named `fit_name` under `base`:
/// ("v", 0.05) for "BASE[v=0.05]"; nullopt for any other name.
std::optional<std::pair<std::string, double>> fit_level(const std::string& fit_name, const std::string& base);

/// The base of a per-level fit's name ("BASE" from "BASE[v=0.05]"), or the
/// name itself when it is not a per-level fit's.
std::string fit_family_name(const std::string& fit_name);

}  // namespace hydrocoef
