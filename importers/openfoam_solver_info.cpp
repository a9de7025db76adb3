#include "importers/openfoam_solver_info.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <string_view>
#include <system_error>

#include "importers/history_text.hpp"
#include "src/core/error.hpp"
#include "src/core/file_bytes.hpp"
#include "src/core/numbers.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kMaxBytes = std::uint64_t{1} << 30;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

bool ends_with(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

/// The field a residual column belongs to: "Ux_initial" -> "U" when a column
/// "U_solver" names the field, else the column's stem.
std::string field_of(std::string_view stem, const std::vector<std::string>& fields) {
  static constexpr std::array<std::string_view, 12> kComponents = {"x",  "y",  "z",  "xx", "xy", "xz",
                                                                   "yx", "yy", "yz", "zx", "zy", "zz"};
  std::string best;
  for (const auto& field : fields) {
    if (stem == field) return field;
    if (stem.size() > field.size() && stem.substr(0, field.size()) == field &&
        std::find(kComponents.begin(), kComponents.end(), stem.substr(field.size())) != kComponents.end() &&
        field.size() > best.size())
      best = field;
  }
  return best.empty() ? std::string(stem) : best;
}

}  // namespace

SolverResiduals read_solver_info(const fs::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  const auto size = fs::file_size(file, ec);
  if (!ec && size > kMaxBytes)
    throw InputError(SourceLocation{name},
                     "the file has " + std::to_string(size) + " bytes; expected a solverInfo.dat of at most 1 GiB");
  const FileBytes bytes(file);
  const std::string_view text = bytes.view();

  // The header: the comment line that starts with "# Time".
  std::size_t offset = 0;
  std::size_t line = 1;
  std::vector<std::string> columns;
  while (offset < text.size()) {
    const std::size_t end = std::min(text.find('\n', offset), text.size());
    const std::string_view row = trim(text.substr(offset, end - offset));
    offset = end + 1;
    if (row.empty()) {
      ++line;
      continue;
    }
    if (row.front() != '#')
      throw InputError(SourceLocation{name, line, 1},
                       "found a data row before the header; expected a header line '# Time<TAB>field_solver...'");
    const std::string_view body = trim(row.substr(1));
    if (body.substr(0, 4) == "Time") {
      for (std::size_t start = 0; start <= body.size();) {
        const std::size_t tab = std::min(body.find('\t', start), body.size());
        const std::string_view column = trim(body.substr(start, tab - start));
        if (column.empty())
          throw InputError(SourceLocation{name, line, start + 2}, "found an empty column name in the header");
        if (column.size() > 256)
          throw InputError(SourceLocation{name, line, start + 2},
                           "found a column name of " + std::to_string(column.size()) + " bytes; expected at most 256");
        columns.emplace_back(column);
        start = tab + 1;
      }
      ++line;
      break;
    }
    ++line;
  }
  if (columns.size() < 2)
    throw InputError(SourceLocation{name},
                     "found no header line '# Time<TAB>field_solver<TAB>field_initial...'; "
                     "expected the output of OpenFOAM's solverInfo function object");

  std::vector<std::string> fields;
  for (const auto& c : columns)
    if (ends_with(c, "_solver")) fields.push_back(c.substr(0, c.size() - 7));

  SolverResiduals out;
  out.file = file;
  history_text::RowSyntax syntax;
  syntax.columns = columns.size();
  syntax.delimiter = '\t';
  syntax.names = columns;
  syntax.skip.resize(columns.size());
  std::vector<std::vector<double>> initial_columns;
  std::vector<std::string> initial_fields;
  for (std::size_t i = 1; i < columns.size(); ++i) {
    syntax.skip[i] = ends_with(columns[i], "_solver") || ends_with(columns[i], "_converged");
    if (ends_with(columns[i], "_initial")) {
      initial_fields.push_back(field_of(std::string_view(columns[i]).substr(0, columns[i].size() - 8), fields));
    }
  }
  initial_columns.resize(initial_fields.size());
  history_text::RowSink sink;
  sink.lines = &out.lines;
  std::size_t next_initial = 0;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (syntax.skip[i]) continue;
    if (i == 0)
      sink.columns.push_back(&out.times);
    else if (ends_with(columns[i], "_initial"))
      sink.columns.push_back(&initial_columns[next_initial++]);
    else
      sink.columns.push_back(nullptr);
  }
  history_text::RowOptions options;
  options.drop_incomplete_last_row = true;
  options.threads = 1;
  history_text::parse_rows(text.substr(std::min(offset, text.size())), line, syntax, name, sink, options);

  for (std::size_t r = 1; r < out.times.size(); ++r)
    if (!(out.times[r] > out.times[r - 1]))
      throw InputError(SourceLocation{name, out.lines[r], 1}, "found time " + shortest_number(out.times[r]) +
                                                                  " after " + shortest_number(out.times[r - 1]) +
                                                                  "; expected increasing times");
  for (std::size_t k = 0; k < initial_fields.size(); ++k) {
    auto& residuals = out.initial[initial_fields[k]];
    const auto& column = initial_columns[k];
    if (residuals.empty()) residuals.assign(column.size(), 0.0);
    for (std::size_t r = 0; r < column.size(); ++r) {
      if (column[r] < 0.0)
        throw InputError(SourceLocation{name, out.lines[r], 0}, "found the initial residual " +
                                                                    shortest_number(column[r]) + " of " +
                                                                    initial_fields[k] + "; expected a number >= 0");
      residuals[r] = std::max(residuals[r], column[r]);
    }
  }
  return out;
}

fs::path find_solver_info(const fs::path& case_dir) {
  std::error_code ec;
  const fs::path root = case_dir / "postProcessing" / "solverInfo";
  fs::path best;
  if (!fs::is_directory(root, ec)) return best;
  double best_time = 0.0;
  for (fs::directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string time = it->path().filename().string();
    char* parsed_end = nullptr;
    const double t = std::strtod(time.c_str(), &parsed_end);
    if (time.empty() || parsed_end != time.c_str() + time.size() || !std::isfinite(t)) continue;
    const fs::path candidate = it->path() / "solverInfo.dat";
    if (fs::is_regular_file(candidate, ec) && (best.empty() || t > best_time)) {
      best = candidate;
      best_time = t;
    }
  }
  return best;
}

}  // namespace hydrocoef
