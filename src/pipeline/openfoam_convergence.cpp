#include "src/pipeline/openfoam_convergence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

#include "importers/openfoam_dictionary.hpp"
#include "importers/openfoam_solver_info.hpp"
#include "src/core/numbers.hpp"
#include "src/history/iterative_error.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

/// A residualControl key as alternatives of literal words with ".*"
/// wildcards, or nullopt for a pattern outside that subset.
std::optional<std::vector<std::string>> alternatives_of(std::string key) {
  if (key.size() >= 2 && key.front() == '"' && key.back() == '"') key = key.substr(1, key.size() - 2);
  if (key.size() >= 2 && key.front() == '(' && key.back() == ')') key = key.substr(1, key.size() - 2);
  std::vector<std::string> out;
  std::string current;
  for (std::size_t i = 0; i < key.size(); ++i) {
    const char c = key[i];
    if (c == '|') {
      out.push_back(current);
      current.clear();
    } else if (c == '.' && i + 1 < key.size() && key[i + 1] == '*') {
      current += '\x01';  // wildcard
      ++i;
    } else if (std::string_view("()[]{}+?*^$\\.").find(c) != std::string_view::npos) {
      return std::nullopt;
    } else {
      current += c;
    }
  }
  out.push_back(current);
  for (const auto& a : out)
    if (a.empty()) return std::nullopt;
  return out;
}

/// Glob match with '\x01' standing for any run of characters (iterative,
/// linear in practice for the few wildcards a key holds).
bool matches(std::string_view pattern, std::string_view text) {
  std::size_t p = 0, t = 0, star = std::string_view::npos, resume = 0;
  while (t < text.size()) {
    if (p < pattern.size() && pattern[p] == '\x01') {
      star = p++;
      resume = t;
    } else if (p < pattern.size() && pattern[p] == text[t]) {
      ++p;
      ++t;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      t = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '\x01') ++p;
  return p == pattern.size();
}

void read_solver_kind(const fs::path& case_dir, ConvergenceEvidence& out) {
  std::error_code ec;
  const fs::path schemes = case_dir / "system" / "fvSchemes";
  if (fs::is_regular_file(schemes, ec)) {
    const FoamDictionary d = FoamDictionary::read(schemes);
    if (const FoamDictionary* ddt = d.dictionary("ddtSchemes"))
      if (const FoamValue* value = ddt->value("default"); value && !value->tokens.empty()) {
        const std::string& scheme = value->tokens.front();
        if (scheme == "steadyState" || scheme == "localEuler") {
          out.solver = SolverKind::Steady;
        } else if (scheme == "Euler" || scheme == "backward" || scheme == "CrankNicolson" || scheme == "bounded" ||
                   scheme == "CoEuler" || scheme == "SLTS") {
          out.solver = SolverKind::Transient;
        }
        if (out.solver != SolverKind::Unknown) {
          out.solver_source = value->where() + ": ddtSchemes default " + scheme;
          return;
        }
      }
  }
  const fs::path control = case_dir / "system" / "controlDict";
  if (fs::is_regular_file(control, ec)) {
    const FoamDictionary d = FoamDictionary::read(control);
    if (const auto application = foam_word(d.value("application"))) {
      const std::string& a = *application;
      if (a.size() >= 10 && a.substr(a.size() - 10) == "SimpleFoam") out.solver = SolverKind::Steady;
      if (a == "simpleFoam") out.solver = SolverKind::Steady;
      if (a.find("pimple") != std::string::npos || a.find("Pimple") != std::string::npos ||
          a.find("piso") != std::string::npos || a.find("Piso") != std::string::npos || a == "icoFoam" ||
          a == "interFoam")
        out.solver = SolverKind::Transient;
      if (out.solver != SolverKind::Unknown) out.solver_source = d.value("application")->where() + ": " + a;
    }
  }
}

struct Criterion {
  std::string key;
  std::vector<std::string> alternatives;
  double tolerance = 0.0;
};

}  // namespace

ConvergenceEvidence openfoam_convergence_evidence(const fs::path& case_dir, double last_iteration,
                                                  std::vector<std::string>& notes) {
  ConvergenceEvidence out;
  read_solver_kind(case_dir, out);
  std::error_code ec;
  const fs::path solution = case_dir / "system" / "fvSolution";
  if (out.solver == SolverKind::Transient || !fs::is_regular_file(solution, ec)) return out;
  const FoamDictionary d = FoamDictionary::read(solution);
  const FoamDictionary* simple = d.dictionary("SIMPLE");
  const FoamDictionary* control = simple ? simple->dictionary("residualControl") : nullptr;
  if (!control || control->values().empty()) return out;

  std::vector<Criterion> criteria;
  std::string listed;
  std::size_t first_line = 0;
  for (const auto& [key, value] : control->values()) {
    const auto alternatives = alternatives_of(key);
    if (first_line == 0 || value.line < first_line) first_line = value.line;
    if (!alternatives) {
      out.criteria_stated = true;
      out.criteria_source = value.where() + ": SIMPLE residualControl";
      out.criteria_missed = "the residualControl pattern " + key + " is not understood by hydrocoef";
      notes.push_back(value.where() + ": residualControl pattern " + key +
                      " is not understood by hydrocoef (it reads words, (a|b) and .*): the run is not taken as "
                      "converged; give --window to choose the samples");
      return out;
    }
    criteria.push_back({key, *alternatives, foam_scalar(value, "residualControl " + key)});
    listed += (listed.empty() ? "" : ", ") + key + " " + shortest_number(criteria.back().tolerance);
  }
  out.criteria_stated = true;
  out.criteria_source = control->file() + ":" + std::to_string(first_line) + ": SIMPLE residualControl " + listed;

  const fs::path info_file = find_solver_info(case_dir);
  if (info_file.empty()) return out;
  const SolverResiduals info = read_solver_info(info_file);
  if (info.times.empty()) return out;
  const std::size_t last = info.times.size() - 1;
  out.residuals_source = info_file.string() + ":" + std::to_string(info.lines[last]);

  // The controlled fields, their residuals at the last row, the slowest rate.
  std::string missed;
  std::size_t controlled = 0;
  double slowest = std::numeric_limits<double>::quiet_NaN();
  for (const auto& [field, residuals] : info.initial) {
    const Criterion* criterion = nullptr;
    for (const auto& c : criteria)
      for (const auto& alternative : c.alternatives)
        if (!criterion && matches(alternative, field)) criterion = &c;
    if (!criterion) continue;
    ++controlled;
    if (!(residuals[last] < criterion->tolerance))
      missed += (missed.empty() ? "" : ", ") + field + " " + shortest_number(residuals[last]) + " (tolerance " +
                shortest_number(criterion->tolerance) + ")";
    const double rate = decay_rate(residuals);
    if (std::isfinite(rate) && !(rate <= slowest)) slowest = rate;
  }
  out.residual_rate = slowest;
  if (controlled == 0) {
    out.criteria_missed = "no field of " + info_file.string() + " is named by the residualControl";
    return out;
  }
  if (!missed.empty()) {
    out.criteria_missed = "initial residuals at " + shortest_number(info.times[last]) + ": " + missed;
    return out;
  }
  if (std::abs(info.times[last] - last_iteration) >= 0.5) {
    out.criteria_missed = "the residuals end at iteration " + shortest_number(info.times[last]) +
                          " and the force record at " + shortest_number(last_iteration);
    return out;
  }
  out.criteria_met_at = info.times[last];
  return out;
}

}  // namespace hydrocoef
