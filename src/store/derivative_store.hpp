// A derivative model of several variables as the database stores it (tables
// derivative_model, derivative_coefficient and derivative_model_run,
// schema/0018_derivative_models.sql): plain numbers and names, no fitting
// code. Written by the public API's `derivatives fit` (src/api/
// derivatives.cpp) through RunDatabase::save_derivative_model, read back by
// RunDatabase::derivative_models with every value checked (a received
// database is untrusted input).
//
// Units: SI. The output is a force [N] (X, Y, Z) or moment [N m] (K, M, N)
// on the body, body axes x forward, y starboard, z down; a coefficient is in
// the output's unit over its term's unit (src/derivatives/terms.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hydrocoef {

struct DerivativeModelRecord {
  struct Coefficient {
    std::string term;  ///< canonical, e.g. "v*|v|"
    double value = 0.0;
    std::optional<double> std_error, interval_low, interval_high, vif;  ///< empty when undefined
  };
  struct Warning {
    std::string kind;
    std::string message;
  };
  std::int64_t id = 0;
  std::string name;
  std::string body;
  std::string output;              ///< X..N
  std::string terms;               ///< canonical list, "v, r, v*|v|"
  std::string model_template;      ///< "" or "abkowitz", "auv", "mmg", "mmg-beta"
  std::string selection;           ///< "" or "loo", "kfold:K"
  std::string candidates;          ///< the candidate list of a selection ("" without one)
  std::string run_filter;          ///< the selection's canonical text ("" all runs)
  std::string weighting = "none";  ///< "none" or "uncertainty"
  std::size_t n = 0;
  double rmse = 0.0;
  std::optional<double> r2;
  double condition_number = 1.0;
  std::optional<double> chi2_reduced;
  double covariance_scale = 1.0;
  std::optional<double> interval_factor;
  /// m x m row by row; empty when undefined (as many runs as terms, unweighted).
  std::vector<double> covariance;
  std::vector<Warning> warnings;
  std::string created_at;  ///< UTC ISO 8601; set when stored
  bool stale = false;      ///< a force of a run it was fitted to changed or was deleted since
  std::vector<Coefficient> coefficients;
  std::vector<std::int64_t> run_ids;
};

}  // namespace hydrocoef
