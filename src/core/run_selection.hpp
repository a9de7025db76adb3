// Which runs a command works on: the one selection language of `runs`,
// `fit`, `surface build`, `report` and `export-gazebo`. Clauses on a velocity
// component (u..r, SI) or a disturbance parameter, combined with AND, and
// runs left out by id:
//
//   u=0.1        equal (within 1e-9 relative, as stored keys are compared)
//   v!=0         not equal
//   u<0.3 u<=0.3 u>0 u>=0
//   u=0.1:0.3    a closed range, both ends included
//   --exclude-run 7
//
// A velocity component a run does not state is 0. A disturbance a run does
// not have matches no clause on it (not even !=), so `current_v!=0` selects
// the runs that have a current and it is not 0.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "src/core/run.hpp"

namespace hydrocoef {

struct SelectionClause {
  enum class Op { Equal, NotEqual, Less, LessEqual, Greater, GreaterEqual, Range };
  std::string name;  ///< u..r or a disturbance parameter
  Op op = Op::Equal;
  double value = 0.0;  ///< SI; the lower end of a Range
  double upper = 0.0;  ///< the upper end of a Range
  std::string text;    ///< as given, for messages

  bool matches(const RunKey& key) const;
};

struct RunSelection {
  std::vector<SelectionClause> clauses;  ///< all must hold
  std::vector<std::int64_t> excluded_runs;

  bool empty() const { return clauses.empty() && excluded_runs.empty(); }
  bool matches(const RunKey& key, std::int64_t run_id) const;
  /// Canonical text, e.g. "u>=0.1 v=-0.1:0.1 exclude-run 7"; "" when empty.
  /// parse_selection_text reads it back.
  std::string text() const;
  /// The names of the Equal clauses and their values (for fits that record
  /// which condition they were made at).
  std::vector<std::pair<std::string, double>> equalities() const;
};

/// Parses one --where clause. Throws InputError naming the clause, what was
/// found and what was expected ("--where 'v>=abc': found 'abc', expected a
/// finite number").
SelectionClause parse_selection_clause(std::string_view text);

/// Parses --where clauses and --exclude-run ids (ids must be > 0).
RunSelection parse_selection(const std::vector<std::string>& where, const std::vector<std::int64_t>& excluded_runs);

/// Reads back RunSelection::text().
RunSelection parse_selection_text(std::string_view text);

}  // namespace hydrocoef
