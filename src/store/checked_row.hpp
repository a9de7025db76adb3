// Every value read back from a database is checked for its type and range
// before it is used: a database someone else made is untrusted input. A text
// where a number belongs ('fast' as a velocity), a NaN or infinite force, a
// negative count, a name that breaks the name rule (src/core/names.hpp) or an
// oversized blob is refused with one line naming the database, the table,
// the row and the column, what was found and what was expected.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "src/core/names.hpp"
#include "src/store/connection.hpp"

namespace hydrocoef::store {

class CheckedRow {
 public:
  /// `row` is the row's id (or rowid) as the message should name it.
  CheckedRow(const Statement& statement, std::string database, std::string_view table, std::int64_t row)
      : statement_(statement), database_(std::move(database)), table_(table), row_(row) {}

  /// A finite number (an integer is taken as a number).
  double real(int column) const;
  /// A finite number >= 0.
  double non_negative(int column) const;
  /// A finite number > 0.
  double positive(int column) const;
  /// NULL, or a finite number.
  std::optional<double> optional_real(int column) const;
  /// NULL, or a finite number > 0.
  std::optional<double> optional_positive(int column) const;
  /// NULL, or a finite number >= 0.
  std::optional<double> optional_non_negative(int column) const;
  /// An integer in [min, max].
  std::int64_t integer(int column, std::int64_t min, std::int64_t max) const;
  /// Text (valid or not as UTF-8) of at most max_bytes bytes.
  std::string text(int column, std::size_t max_bytes = 4096) const;
  /// Text that is one of `allowed`.
  std::string one_of(int column, const std::vector<std::string_view>& allowed) const;
  /// A name that follows the name rule for its kind.
  std::string name(int column, NameKind kind) const;
  /// A blob of float64 values (a whole number of them, at most max_count).
  std::vector<double> doubles(int column, std::size_t max_count) const;
  /// Text holding a JSON list of at most max_count finite numbers; '' is
  /// the empty list.
  std::vector<double> real_list(int column, std::size_t max_count) const;

  /// Throws InputError: "<db>: table 't', row N, column 'c': found ...; expected ...".
  [[noreturn]] void fail(int column, std::string_view expected) const;
  /// The same with a message of the caller's (e.g. about a whole row).
  [[noreturn]] void fail_row(std::string_view message) const;

 private:
  std::string found(int column) const;
  const Statement& statement_;
  std::string database_;
  std::string_view table_;  ///< a literal
  std::int64_t row_;
};

}  // namespace hydrocoef::store
