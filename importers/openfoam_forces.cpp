#include "importers/openfoam_forces.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <future>
#include <limits>
#include <map>
#include <memory>
#include <system_error>
#include <tuple>
#include <utility>
#include <vector>

#include "importers/history_text.hpp"
#include "src/core/error.hpp"
#include "src/core/text.hpp"
#include "src/core/vec3.hpp"

namespace hydrocoef {
namespace {

// Blanks within a line of a force file (a \r left by CRLF line ends included).
constexpr std::string_view kLineBlanks = " \t\r";

namespace fs = std::filesystem;
using Vector3 = std::array<double, 3>;

std::string shown(std::string_view text) { return history_text::quoted_text(text); }

// ---------------------------------------------------------------------------
// Header

struct CommentLine {
  std::size_t line = 0;
  std::string_view text;  // after '#', trimmed
};

struct Header {
  std::vector<CommentLine> comments;
  std::size_t data_offset = 0;           // byte where the rows start
  std::size_t data_line = 1;             // their first line
  const CommentLine* columns = nullptr;  // the "# Time ..." line
  std::string_view title;
};

bool starts_with_word(std::string_view text, std::string_view word) {
  return text.substr(0, word.size()) == word && (text.size() == word.size() || text[word.size()] == ' ' ||
                                                 text[word.size()] == '\t' || text[word.size()] == '(');
}

Header read_header(std::string_view text) {
  Header header;
  std::size_t offset = 0;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") offset = 3;
  std::size_t line = 1;
  while (offset < text.size()) {
    const std::size_t newline = text.find('\n', offset);
    const std::size_t stop = newline == std::string_view::npos ? text.size() : newline;
    const std::string_view raw = trim(text.substr(offset, stop - offset), kLineBlanks);
    if (!raw.empty() && raw.front() != '#') break;
    if (!raw.empty()) header.comments.push_back({line, trim(raw.substr(1), kLineBlanks)});
    if (newline == std::string_view::npos) {
      offset = text.size();
      break;
    }
    offset = newline + 1;
    ++line;
  }
  header.data_offset = offset;
  header.data_line = line;
  for (const CommentLine& comment : header.comments) {
    if (header.title.empty() && !comment.text.empty()) header.title = comment.text;
    if (starts_with_word(comment.text, "Time")) header.columns = &comment;
  }
  return header;
}

// "# name : value" lines of the header, kept after the header's bytes are gone.
struct HeaderValue {
  std::size_t line = 0;
  std::string text;
};
using HeaderValues = std::map<std::string, HeaderValue>;

HeaderValues header_values(const Header& header) {
  HeaderValues values;
  for (const CommentLine& comment : header.comments) {
    const std::size_t colon = comment.text.find(':');
    if (colon == std::string_view::npos) continue;
    const std::string_view key = trim(comment.text.substr(0, colon), kLineBlanks);
    if (key.empty() || key.find_first_of(" \t") != std::string_view::npos) continue;
    values[std::string(key)] = {comment.line, std::string(trim(comment.text.substr(colon + 1), kLineBlanks))};
  }
  return values;
}

std::optional<double> to_number(std::string_view text) {
  text = trim(text, kLineBlanks);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<Vector3> to_vector(std::string_view text) {
  text = trim(text, kLineBlanks);
  if (text.size() < 2 || text.front() != '(' || text.back() != ')') return std::nullopt;
  text = text.substr(1, text.size() - 2);
  Vector3 v{};
  for (std::size_t k = 0; k < 3; ++k) {
    text = trim(text, kLineBlanks);
    std::size_t stop = text.find_first_of(" \t");
    if (stop == std::string_view::npos) stop = text.size();
    const auto value = to_number(text.substr(0, stop));
    if (!value) return std::nullopt;
    v[k] = *value;
    text = text.substr(stop);
  }
  if (!trim(text, kLineBlanks).empty()) return std::nullopt;
  return v;
}

// ---------------------------------------------------------------------------
// Column line

struct Token {
  std::string word;                // a plain word (may hold "(f)" as in Cd(f))
  std::string group;               // name of a group "forces(...)", "" for a bare "(...)"
  std::vector<std::string> items;  // the group's items
  bool is_group = false;
  std::size_t column = 0;  // 1-based, in the header line
};

bool is_group_name(std::string_view word) {
  return word == "forces" || word == "force" || word == "moment" || word == "moments" || word == "localForces" ||
         word == "localMoments";
}

// `line` is the comment text after '#'; `base` its column offset in the file line.
std::vector<Token> tokenize_columns(std::string_view line, std::size_t base, const std::string& file,
                                    std::size_t line_no) {
  std::vector<Token> tokens;
  std::size_t i = 0;
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == ','; };
  const auto read_group = [&](std::size_t open, Token& token) {
    std::size_t j = open + 1;
    std::string item;
    for (;; ++j) {
      if (j >= line.size())
        throw InputError(SourceLocation{file, line_no, base + open + 1},
                         "'(' without a matching ')' in the column header");
      const char c = line[j];
      if (c == ')' || blank(c)) {
        if (!item.empty()) token.items.push_back(item);
        item.clear();
        if (c == ')') break;
      } else if (c == '(') {
        throw InputError(SourceLocation{file, line_no, base + j + 1}, "a '(' inside a group of the column header");
      } else {
        item += c;
      }
    }
    return j + 1;
  };
  while (i < line.size()) {
    if (blank(line[i])) {
      ++i;
      continue;
    }
    Token token;
    token.column = base + i + 1;
    if (line[i] == ')')
      throw InputError(SourceLocation{file, line_no, token.column}, "')' without a matching '(' in the column header");
    if (line[i] == '(') {
      token.is_group = true;
      i = read_group(i, token);
      tokens.push_back(std::move(token));
      continue;
    }
    std::size_t j = i;
    while (j < line.size() && !blank(line[j]) && line[j] != '(' && line[j] != ')') ++j;
    token.word = std::string(line.substr(i, j - i));
    if (j < line.size() && line[j] == '(') {
      if (is_group_name(token.word)) {
        token.is_group = true;
        token.group = token.word;
        token.word.clear();
        i = read_group(j, token);
        tokens.push_back(std::move(token));
        continue;
      }
      // A name with a parenthesised part, as in Cd(f).
      const std::size_t close = line.find(')', j);
      if (close == std::string_view::npos)
        throw InputError(SourceLocation{file, line_no, base + j + 1},
                         "'(' without a matching ')' in the column header");
      j = close + 1;
      while (j < line.size() && !blank(line[j]) && line[j] != '(' && line[j] != ')') ++j;
      token.word = std::string(line.substr(i, j - i));
    }
    i = j;
    tokens.push_back(std::move(token));
  }
  return tokens;
}

// ---------------------------------------------------------------------------
// Layouts

enum class Kind { Force, Moment, Foundation, Coefficients };

std::string_view format_name(Kind kind) {
  switch (kind) {
    case Kind::Force: return "openfoam-force";
    case Kind::Moment: return "openfoam-moment";
    case Kind::Foundation: return "openfoam-forces";
    case Kind::Coefficients: return "openfoam-coefficient";
  }
  return "";
}

enum class Role { Time, Value, Coefficient, CentreOfRotation, Ignored };

struct Column {
  Role role = Role::Ignored;
  ForcePart part = ForcePart::Total;
  std::size_t component = 0;  // 0..5, or 0..2 for CofR
  std::string name;
};

struct Layout {
  Kind kind = Kind::Force;
  std::vector<Column> columns;
  bool local_rows = false;  // Foundation localForces: a second row per time
  std::vector<std::string> coefficient_names;
};

std::optional<ForcePart> part_of(std::string_view name) {
  if (name == "total") return ForcePart::Total;
  if (name == "pressure" || name == "normal") return ForcePart::Pressure;
  if (name == "viscous" || name == "tangential") return ForcePart::Viscous;
  if (name == "porous" || name == "internal") return ForcePart::Porous;
  return std::nullopt;
}

std::string file_stem_base(const std::string& file) {
  std::string name = fs::path(file).filename().string();
  if (name.size() > 4 && name.substr(name.size() - 4) == ".dat") name.resize(name.size() - 4);
  const std::size_t underscore = name.rfind('_');
  if (underscore != std::string::npos && to_number(std::string_view(name).substr(underscore + 1)))
    name.resize(underscore);
  return name;
}

Layout layout_of(const Header& header, const std::string& file) {
  if (header.columns == nullptr) {
    if (header.comments.empty())
      throw InputError(SourceLocation{file, 1, 1},
                       "no header; expected the '# Time ...' column line that OpenFOAM's forces and forceCoeffs "
                       "function objects write");
    throw InputError(SourceLocation{file, header.comments.back().line, 0},
                     "no '# Time ...' column line in the header; expected the column names that OpenFOAM's forces "
                     "and forceCoeffs function objects write");
  }
  const CommentLine& line = *header.columns;
  // The comment text starts after "#" and blanks; its column in the file is
  // not kept exactly, so columns are counted from the comment text + 2.
  const std::vector<Token> tokens = tokenize_columns(line.text, 2, file, line.line);
  Layout layout;
  layout.columns.push_back({Role::Time, ForcePart::Total, 0, "Time"});
  if (tokens.size() < 2)
    throw InputError(SourceLocation{file, line.line, 0},
                     "the column line names no force, moment or coefficient columns after 'Time'");
  const auto unknown = [&](const Token& token, const std::string& expected) -> InputError {
    const std::string name = token.is_group ? token.group + "(...)" : token.word;
    return InputError(SourceLocation{file, line.line, token.column},
                      "unknown column " + shown(name) + " in the header; expected " + expected);
  };
  const Token& first = tokens[1];
  const bool foundation = first.is_group && !first.group.empty() ? true : (!first.is_group && first.word == "CofR");
  const auto is_coefficient = [](std::string_view w) {
    return w == "Cd" || w == "Cs" || w == "Cl" || w == "Cm" || w == "CmRoll" || w == "CmPitch" || w == "CmYaw" ||
           w == "Cd(f)" || w == "Cd(r)" || w == "Cs(f)" || w == "Cs(r)" || w == "Cl(f)" || w == "Cl(r)";
  };
  if (foundation) {
    layout.kind = Kind::Foundation;
    bool seen_force = false, seen_moment = false;
    for (std::size_t t = 1; t < tokens.size(); ++t) {
      const Token& token = tokens[t];
      if (!token.is_group && token.word == "CofR") {
        for (std::size_t k = 0; k < 3; ++k)
          layout.columns.push_back({Role::CentreOfRotation, ForcePart::Total, k, "CofR"});
        continue;
      }
      if (!token.is_group || token.group.empty())
        throw unknown(token,
                      "forces(pressure viscous [porous]) and moment(pressure viscous [porous]), as in the "
                      "OpenFOAM Foundation's forces.dat");
      if (token.group == "localForces" || token.group == "localMoments") {
        layout.local_rows = true;
        continue;
      }
      const bool force = token.group == "forces" || token.group == "force";
      (force ? seen_force : seen_moment) = true;
      for (const std::string& item : token.items) {
        const auto part = part_of(item);
        if (!part || *part == ForcePart::Total)
          throw InputError(SourceLocation{file, line.line, token.column}, "unknown part " + shown(item) + " in " +
                                                                              shown(token.group + "(...)") +
                                                                              "; expected pressure, viscous or porous");
        for (std::size_t k = 0; k < 3; ++k)
          layout.columns.push_back({Role::Value, *part, (force ? 0 : 3) + k,
                                    token.group + "(" + item + ")_" + std::string(1, char('x' + k))});
      }
    }
    if (!seen_force || !seen_moment)
      throw InputError(SourceLocation{file, line.line, 0},
                       "the header names " +
                           std::string(seen_force ? "forces but no moments" : "moments but no forces") +
                           "; expected both groups of the OpenFOAM Foundation's forces.dat");
    return layout;
  }
  if (!first.is_group && is_coefficient(first.word)) {
    layout.kind = Kind::Coefficients;
    for (std::size_t t = 1; t < tokens.size(); ++t) {
      const Token& token = tokens[t];
      if (token.is_group || !is_coefficient(token.word))
        throw unknown(token, "the coefficients Cd Cs Cl CmRoll CmPitch CmYaw (Cm), Cd(f) Cd(r) ... of forceCoeffs");
      Column column{Role::Ignored, ForcePart::Total, 0, token.word};
      const std::string& w = token.word;
      const std::array<std::pair<const char*, std::size_t>, 7> map{
          {{"Cd", 0}, {"Cs", 1}, {"Cl", 2}, {"CmRoll", 3}, {"CmPitch", 4}, {"Cm", 4}, {"CmYaw", 5}}};
      for (const auto& [name, component] : map)
        if (w == name) {
          column.role = Role::Coefficient;
          column.component = component;
        }
      if (column.role == Role::Coefficient) {
        for (const Column& other : layout.columns)
          if (other.role == Role::Coefficient && other.component == column.component)
            throw InputError(
                SourceLocation{file, line.line, token.column},
                "the coefficient " + shown(w) + " repeats " + shown(other.name) + "; expected each coefficient once");
        layout.coefficient_names.push_back(w);
      }
      layout.columns.push_back(column);
    }
    return layout;
  }
  // ESI force.dat / moment.dat: part_axis names, bare groups allowed.
  const std::string title(header.title);
  const std::string base = file_stem_base(file);
  if (title == "Force" || (title != "Moment" && base == "force")) {
    layout.kind = Kind::Force;
  } else if (title == "Moment" || base == "moment") {
    layout.kind = Kind::Moment;
  } else {
    throw InputError(SourceLocation{file, header.comments.front().line, 0},
                     "cannot tell force from moment: the header's title is " + shown(title) + " and the file is " +
                         shown(fs::path(file).filename().string()) +
                         "; expected the title 'Force' or 'Moment' "
                         "(force.dat, moment.dat)");
  }
  const std::size_t offset = layout.kind == Kind::Force ? 0 : 3;
  for (std::size_t t = 1; t < tokens.size(); ++t) {
    const Token& token = tokens[t];
    std::vector<std::string> words = token.is_group ? token.items : std::vector<std::string>{token.word};
    if (token.is_group && !token.group.empty())
      throw unknown(token, "names such as total_x, pressure_y, viscous_z (ESI force.dat and moment.dat)");
    for (const std::string& word : words) {
      const std::size_t underscore = word.rfind('_');
      const auto part =
          underscore == std::string::npos ? std::nullopt : part_of(std::string_view(word).substr(0, underscore));
      const std::string axis = underscore == std::string::npos ? "" : word.substr(underscore + 1);
      if (!part || (axis != "x" && axis != "y" && axis != "z"))
        throw InputError(SourceLocation{file, line.line, token.column},
                         "unknown column " + shown(word) +
                             " in the header; expected total_x, pressure_y, viscous_z, porous_x and the like");
      const std::size_t component = offset + static_cast<std::size_t>(axis[0] - 'x');
      for (const Column& other : layout.columns)
        if (other.role == Role::Value && other.part == *part && other.component == component)
          throw InputError(SourceLocation{file, line.line, token.column},
                           "the column " + shown(word) + " appears twice; expected each once");
      layout.columns.push_back({Role::Value, *part, component, word});
    }
  }
  return layout;
}

// ---------------------------------------------------------------------------
// One file

std::string number_text(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", value);
  return buffer;
}

double reference_value(const HeaderValues& values, const char* key, std::optional<double> option,
                       const char* option_name, const std::string& file) {
  const auto found = values.find(key);
  if (found != values.end()) {
    const auto value = to_number(found->second.text);
    if (!value || !(*value > 0.0))
      throw InputError(SourceLocation{file, found->second.line, 0},
                       std::string(key) + ": found " + shown(found->second.text) + ", expected a positive number");
    if (option && std::abs(*option - *value) > 1e-9 * std::abs(*value))
      throw InputError(SourceLocation{file, found->second.line, 0},
                       std::string(key) + " is " + number_text(*value) + " in the header but " + number_text(*option) +
                           " was given (" + option_name + "); expected them to agree");
    return *value;
  }
  if (option) {
    if (!(*option > 0.0)) throw InputError(std::string(option_name) + " must be positive");
    return *option;
  }
  throw InputError(SourceLocation{file}, std::string("the header gives no ") + key + " and none was given (" +
                                             option_name + "); expected it to turn coefficients into forces");
}

std::optional<Vector3> direction(const HeaderValues& values, const char* key, const std::string& file) {
  const auto found = values.find(key);
  if (found == values.end()) return std::nullopt;
  const auto v = to_vector(found->second.text);
  if (!v)
    throw InputError(SourceLocation{file, found->second.line, 0},
                     std::string(key) + ": found " + shown(found->second.text) + ", expected a vector (x y z)");
  const double length = std::sqrt((*v)[0] * (*v)[0] + (*v)[1] * (*v)[1] + (*v)[2] * (*v)[2]);
  if (std::abs(length - 1.0) > 1e-6)
    throw InputError(SourceLocation{file, found->second.line, 0},
                     std::string(key) + " has length " + number_text(length) + "; expected a unit vector");
  return v;
}

// A file's header read, and the places its rows go. Holds the vectors the
// sink points into: made on the heap and never moved.
struct Prepared {
  std::string file;
  Layout layout;
  HeaderValues values;
  history_text::FileLayout rows;
  ForceHistory history;
  std::array<std::array<bool, kHistoryComponents>, kForceParts> present{};
  std::array<std::vector<double>, 3> centre_column;
  std::vector<std::uint32_t> lines;
};

std::unique_ptr<Prepared> prepare(std::string_view head, const std::string& file) {
  auto prepared = std::make_unique<Prepared>();
  Prepared& p = *prepared;
  p.file = file;
  const Header header = read_header(head);
  p.layout = layout_of(header, file);
  p.values = header_values(header);
  p.rows.data_offset = header.data_offset;
  p.rows.first_line = header.data_line;
  history_text::RowSyntax& syntax = p.rows.syntax;
  syntax.columns = p.layout.columns.size();
  syntax.parentheses = true;
  syntax.require_line_end = true;
  for (const Column& column : p.layout.columns) syntax.names.push_back(column.name);
  history_text::RowSink& sink = p.rows.sink;
  sink.lines = &p.lines;
  for (const Column& column : p.layout.columns) {
    switch (column.role) {
      case Role::Time: sink.columns.push_back(&p.history.abscissa_values); break;
      case Role::Value:
      case Role::Coefficient:
        sink.columns.push_back(&p.history.values(column.part, static_cast<HistoryComponent>(column.component)));
        p.present[static_cast<std::size_t>(column.part)][column.component] = true;
        break;
      case Role::CentreOfRotation: sink.columns.push_back(&p.centre_column[column.component]); break;
      case Role::Ignored: sink.columns.push_back(nullptr); break;
    }
  }
  return prepared;
}

history_text::RowOptions row_options_of(const OpenFoamForcesOptions& options) {
  history_text::RowOptions row_options;
  row_options.drop_incomplete_last_row = options.drop_incomplete_last_row;
  row_options.threads = options.threads;
  return row_options;
}

// The history from the parsed rows: local rows left out, times checked,
// totals and coefficients worked out, the frame and the origins.
ForceHistory finish(Prepared& prepared, const history_text::ParsedRows& rows, std::uint64_t size_bytes,
                    const OpenFoamForcesOptions& options) {
  const std::string& file = prepared.file;
  const Layout& layout = prepared.layout;
  const HeaderValues& values = prepared.values;
  ForceHistory history = std::move(prepared.history);
  const auto& present = prepared.present;
  auto& centre_column = prepared.centre_column;
  auto& lines = prepared.lines;

  HistorySourceFile source;
  source.path = file;
  source.format = std::string(format_name(layout.kind));
  source.size_bytes = size_bytes;
  if (rows.dropped_last_row)
    history.notes.push_back(file + ": the last row was cut short (a run stopped while writing) and is left out");

  // Foundation local-system rows: every other row, left out.
  if (layout.local_rows) {
    const auto& t = history.abscissa_values;
    for (std::size_t r = 0; r + 1 < rows.rows; r += 2)
      if (t[r + 1] != t[r])
        throw InputError(SourceLocation{file, lines[r + 1], 0},
                         "time " + number_text(t[r + 1]) +
                             " differs from the row before; expected each time twice (global and local axes, as the "
                             "header's localForces says)");
    const auto keep_even = [](auto& series) {
      std::size_t kept = 0;
      for (std::size_t r = 0; r < series.size(); r += 2) series[kept++] = series[r];
      series.resize(kept);
    };
    keep_even(history.abscissa_values);
    keep_even(lines);
    for (auto& part : history.series)
      for (auto& series : part)
        if (!series.empty()) keep_even(series);
    for (auto& series : centre_column)
      if (!series.empty()) keep_even(series);
    history.notes.push_back(file +
                            ": rows in the local coordinate system (localForces) are left out; the global "
                            "axes are kept");
  }
  const std::size_t n = history.abscissa_values.size();
  source.rows = n;

  for (std::size_t i = 1; i < n; ++i)
    if (!(history.abscissa_values[i] > history.abscissa_values[i - 1]))
      throw InputError(SourceLocation{file, lines[i], 0},
                       "time " + number_text(history.abscissa_values[i]) + " is not after " +
                           number_text(history.abscissa_values[i - 1]) + " on line " + std::to_string(lines[i - 1]) +
                           "; expected increasing times (a restart writes a file of its own)");

  std::optional<Vector3> moving_centre;
  bool centre_moves = false;
  if (!centre_column[0].empty() && n > 0) {
    moving_centre = Vector3{centre_column[0][0], centre_column[1][0], centre_column[2][0]};
    for (std::size_t k = 0; k < 3; ++k)
      for (const double value : centre_column[k])
        if (value != (*moving_centre)[k]) centre_moves = true;
  }

  // Totals: the sum of the parts where the file does not write them.
  for (std::size_t component = 0; component < kHistoryComponents; ++component) {
    if (present[0][component]) continue;
    bool any = false;
    for (std::size_t part = 1; part < kForceParts; ++part) any = any || present[part][component];
    if (!any || layout.kind == Kind::Coefficients) continue;
    auto& total = history.series[0][component];
    total.assign(n, 0.0);
    for (std::size_t part = 1; part < kForceParts; ++part)
      if (present[part][component])
        for (std::size_t i = 0; i < n; ++i) total[i] += history.series[part][component][i];
  }

  // The frame.
  if (const auto cofr = values.find("CofR"); cofr != values.end()) {
    const auto centre = to_vector(cofr->second.text);
    if (!centre)
      throw InputError(SourceLocation{file, cofr->second.line, 0},
                       "CofR: found " + shown(cofr->second.text) + ", expected a point (x y z)");
    history.frame.moment_centre = centre;
  }
  if (moving_centre) {
    if (centre_moves) {
      history.frame.moment_centre.reset();
      history.notes.push_back(file + ": the CofR column moves (a moving body): moments are about the moving point");
    } else {
      history.frame.moment_centre = moving_centre;
    }
  }
  history.frame.description =
      "OpenFOAM's global axes (or the forces function object's coordinateSystem, which the file does not state)";

  if (layout.kind == Kind::Coefficients) {
    if (!options.rho)
      throw InputError(SourceLocation{file},
                       "coefficients need the fluid's density to become forces, and none was given (rho); expected "
                       "the case's rhoInf or the fluid's density");
    if (!(*options.rho > 0.0)) throw InputError("rho must be positive");
    const double u = reference_value(values, "magUInf", options.mag_u_inf, "magUInf", file);
    const double area = reference_value(values, "Aref", options.a_ref, "Aref", file);
    const double q = 0.5 * *options.rho * u * u;
    bool needs_length = false;
    for (const Column& column : layout.columns)
      if (column.role == Role::Coefficient && column.component >= 3) needs_length = true;
    const double length = needs_length ? reference_value(values, "lRef", options.l_ref, "lRef", file) : 1.0;

    // Axes: ESI drag/side/lift; Foundation drag/lift and the pitch axis.
    const auto drag = direction(values, "dragDir", file);
    const auto side = direction(values, "sideDir", file);
    const auto lift = direction(values, "liftDir", file);
    const auto pitch = direction(values, "pitchAxis", file);
    double pitch_sign = 1.0;
    if (drag && lift) {
      const Vector3 e2 = side ? *side : cross(*lift, *drag);
      const std::size_t where = values.at("dragDir").line;
      if (std::abs(dot(*drag, *lift)) > 1e-6 || std::abs(dot(*drag, e2)) > 1e-6 || std::abs(dot(e2, *lift)) > 1e-6 ||
          dot(cross(*drag, e2), *lift) < 0.0)
        throw InputError(SourceLocation{file, where, 0},
                         "dragDir, sideDir and liftDir are not a right-handed orthonormal set; expected the "
                         "coefficient axes of forceCoeffs");
      history.frame.axes_in_global = std::array<Vector3, 3>{*drag, e2, *lift};
      if (pitch && !side) {  // Foundation: Cm is about pitchAxis
        const double along = dot(*pitch, e2);
        if (std::abs(std::abs(along) - 1.0) > 1e-6)
          throw InputError(SourceLocation{file, values.at("pitchAxis").line, 0},
                           "pitchAxis is not along liftDir x dragDir; expected the pitch axis perpendicular to drag "
                           "and lift");
        pitch_sign = along > 0 ? 1.0 : -1.0;
      }
      history.frame.description = "forceCoeffs axes: x along dragDir, y " +
                                  std::string(side ? "along sideDir" : "= liftDir x dragDir") +
                                  ", z along liftDir (HistoryFrame::axes_in_global gives them in global axes)";
    } else {
      history.frame.description = "forceCoeffs axes (drag, side, lift); the header does not state their directions";
    }
    for (std::size_t component = 0; component < kHistoryComponents; ++component) {
      auto& series = history.series[0][component];
      if (series.empty()) continue;
      double scale = component < 3 ? q * area : q * area * length;
      if (component == 4 && !side && pitch) scale *= pitch_sign;
      for (double& v : series) v *= scale;
    }
    history.notes.push_back(file + ": coefficients turned into forces with rho " + number_text(*options.rho) +
                            " kg m^-3, magUInf " + number_text(u) + " m s^-1, Aref " + number_text(area) + " m^2" +
                            (needs_length ? ", lRef " + number_text(length) + " m" : std::string()));
  }

  // Origins.
  std::vector<SampleOrigin> origins(n);
  for (std::size_t i = 0; i < n; ++i) origins[i] = {0, lines[i]};
  bool any_force = false, any_moment = false;
  for (std::size_t part = 0; part < kForceParts; ++part)
    for (std::size_t component = 0; component < kHistoryComponents; ++component)
      if (!history.series[part][component].empty()) (component < 3 ? any_force : any_moment) = true;
  if (any_force && any_moment) {
    history.force_origin = origins;
    history.moment_origin = std::move(origins);
  } else if (any_force) {
    history.force_origin = std::move(origins);
  } else if (any_moment) {
    history.moment_origin = std::move(origins);
  }
  source.rows_used = n;
  history.files.push_back(std::move(source));
  return history;
}

// ---------------------------------------------------------------------------
// Pairs, restarts, abscissa

// Puts the moments of `moments` (a moment.dat) into `forces` (its force.dat).
void merge_moments(ForceHistory& forces, ForceHistory&& moments, bool drop_unpaired) {
  const std::string& force_file = forces.files.front().path.string();
  const std::string& moment_file = moments.files.front().path.string();
  std::size_t common = std::min(forces.size(), moments.size());
  for (std::size_t i = 0; i < common; ++i)
    if (forces.abscissa_values[i] != moments.abscissa_values[i])
      throw InputError(SourceLocation{moment_file, moments.moment_origin[i].line, 0},
                       "time " + number_text(moments.abscissa_values[i]) + " differs from " +
                           number_text(forces.abscissa_values[i]) + " on line " +
                           std::to_string(forces.force_origin[i].line) + " of " + force_file +
                           "; expected the force and moment files to hold the same times");
  if (forces.size() != moments.size()) {
    const bool force_longer = forces.size() > moments.size();
    const std::size_t extra = force_longer ? forces.size() - common : moments.size() - common;
    const std::string& longer = force_longer ? force_file : moment_file;
    const std::uint32_t line = force_longer ? forces.force_origin[common].line : moments.moment_origin[common].line;
    if (!drop_unpaired || extra > 1)
      throw InputError(SourceLocation{longer, line, 0},
                       "this row has no partner in " + (force_longer ? moment_file : force_file) + " (" +
                           std::to_string(forces.size()) + " force rows, " + std::to_string(moments.size()) +
                           " moment rows); expected the force and moment files to hold the same times");
    forces.notes.push_back(longer + ":" + std::to_string(line) +
                           ": left out, its partner row was never written (a run stopped while writing)");
  }
  const auto cut = [common](ForceHistory& h) {
    h.abscissa_values.resize(common);
    for (auto& part : h.series)
      for (auto& series : part)
        if (!series.empty()) series.resize(common);
    if (!h.force_origin.empty()) h.force_origin.resize(common);
    if (!h.moment_origin.empty()) h.moment_origin.resize(common);
  };
  cut(forces);
  cut(moments);
  if (forces.frame.moment_centre && moments.frame.moment_centre &&
      *forces.frame.moment_centre != *moments.frame.moment_centre)
    throw InputError(SourceLocation{moment_file},
                     "its CofR differs from that of " + force_file + "; expected one centre of rotation");
  if (!forces.frame.moment_centre) forces.frame.moment_centre = moments.frame.moment_centre;
  for (std::size_t part = 0; part < kForceParts; ++part)
    for (std::size_t c = 3; c < kHistoryComponents; ++c) forces.series[part][c] = std::move(moments.series[part][c]);
  forces.moment_origin = std::move(moments.moment_origin);
  for (SampleOrigin& origin : forces.moment_origin) origin.file = 1;
  moments.files.front().rows_used = common;
  forces.files.front().rows_used = common;
  forces.files.push_back(std::move(moments.files.front()));
  for (auto& note : moments.notes) forces.notes.push_back(std::move(note));
}

std::string presence_signature(const ForceHistory& h) {
  std::string signature;
  for (const auto& part : h.series)
    for (const auto& series : part) signature += series.empty() ? '0' : '1';
  return signature;
}

// Appends `later` to `joined`; `later` wins from its first time on.
void join(ForceHistory& joined, ForceHistory&& later) {
  const std::string later_file = later.files.front().path.string();
  if (presence_signature(joined) != presence_signature(later))
    throw InputError(SourceLocation{later_file},
                     "this restart holds other components or parts than " + joined.files.front().path.string() +
                         "; expected the restarts of one function object to have the same columns");
  if (joined.frame.moment_centre != later.frame.moment_centre ||
      joined.frame.axes_in_global != later.frame.axes_in_global)
    throw InputError(SourceLocation{later_file}, "this restart has another CofR or other axes than " +
                                                     joined.files.front().path.string() +
                                                     "; expected one frame for the whole history");
  const double start = later.abscissa_values.front();
  const auto& t = joined.abscissa_values;
  const std::size_t keep = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), start) - t.begin());
  if (keep < joined.size()) {
    joined.notes.push_back(later_file + " starts at " + number_text(start) + " and replaces " +
                           std::to_string(joined.size() - keep) + " later rows of the files before it");
    joined.abscissa_values.resize(keep);
    for (auto& part : joined.series)
      for (auto& series : part)
        if (!series.empty()) series.resize(keep);
    if (!joined.force_origin.empty()) joined.force_origin.resize(keep);
    if (!joined.moment_origin.empty()) joined.moment_origin.resize(keep);
  }
  const auto offset = static_cast<std::uint32_t>(joined.files.size());
  joined.abscissa_values.insert(joined.abscissa_values.end(), later.abscissa_values.begin(),
                                later.abscissa_values.end());
  for (std::size_t part = 0; part < kForceParts; ++part)
    for (std::size_t c = 0; c < kHistoryComponents; ++c) {
      auto& to = joined.series[part][c];
      const auto& from = later.series[part][c];
      to.insert(to.end(), from.begin(), from.end());
    }
  for (SampleOrigin origin : later.force_origin) joined.force_origin.push_back({origin.file + offset, origin.line});
  for (SampleOrigin origin : later.moment_origin) joined.moment_origin.push_back({origin.file + offset, origin.line});
  for (auto& file : later.files) joined.files.push_back(std::move(file));
  for (auto& note : later.notes) joined.notes.push_back(std::move(note));
}

void decide_abscissa(ForceHistory& history, const OpenFoamForcesOptions& options) {
  if (options.abscissa) {
    history.abscissa = *options.abscissa;
    return;
  }
  bool whole = !history.abscissa_values.empty();
  for (const double t : history.abscissa_values)
    if (!(std::abs(t) < 9007199254740992.0) || t != std::floor(t)) {
      whole = false;
      break;
    }
  history.abscissa = whole ? HistoryAbscissa::Iteration : HistoryAbscissa::Time;
  history.notes.push_back(whole ? std::string("abscissa: iterations (every time value is a whole number: a steady "
                                              "solver's pseudo-time; state it if the run was transient)")
                                : std::string("abscissa: time in seconds (a transient run)"));
}

void count_rows_used(ForceHistory& history) {
  for (auto& file : history.files) file.rows_used = 0;
  std::vector<std::size_t> used(history.files.size(), 0);
  for (const SampleOrigin& o : history.force_origin) ++used[o.file];
  for (const SampleOrigin& o : history.moment_origin) ++used[o.file];
  for (std::size_t f = 0; f < history.files.size(); ++f) history.files[f].rows_used = used[f];
}

// ---------------------------------------------------------------------------
// Files on disk

struct FoundFile {
  fs::path path;
  std::string base;                                             // force, moment, forces, coefficient, forceCoeffs
  double name_time = -std::numeric_limits<double>::infinity();  // the _<time> suffix
  double folder_time = 0.0;
};

std::optional<FoundFile> classify(const fs::path& path) {
  const std::string name = path.filename().string();
  if (name.size() <= 4 || name.substr(name.size() - 4) != ".dat") return std::nullopt;
  std::string stem = name.substr(0, name.size() - 4);
  FoundFile found;
  found.path = path;
  const std::size_t underscore = stem.rfind('_');
  if (underscore != std::string::npos) {
    const auto time = to_number(std::string_view(stem).substr(underscore + 1));
    if (!time) return std::nullopt;  // force_bins.dat and the like
    found.name_time = *time;
    stem.resize(underscore);
  }
  if (stem != "force" && stem != "moment" && stem != "forces" && stem != "coefficient" && stem != "forceCoeffs")
    return std::nullopt;
  found.base = stem;
  return found;
}

int family_of(const std::string& base) {
  if (base == "force" || base == "moment") return 0;  // ESI
  if (base == "forces") return 1;                     // Foundation
  return 2;                                           // coefficients
}

std::vector<FoundFile> files_in(const fs::path& folder, double folder_time) {
  std::vector<FoundFile> found;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if (!entry.is_regular_file(ec)) continue;
    if (auto file = classify(entry.path())) {
      file->folder_time = folder_time;
      found.push_back(std::move(*file));
    }
  }
  return found;
}

std::string listing(const fs::path& folder) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  std::string text;
  for (std::size_t i = 0; i < names.size() && i < 12; ++i) text += (i ? ", " : "") + shown(names[i]);
  if (names.size() > 12) text += ", ...";
  return text.empty() ? "nothing" : text;
}

ForceHistory parse_file(std::string_view text, const std::string& file, const OpenFoamForcesOptions& options) {
  const std::unique_ptr<Prepared> prepared = prepare(text, file);
  const history_text::ParsedRows rows =
      history_text::parse_rows(text.substr(prepared->rows.data_offset), prepared->rows.first_line,
                               prepared->rows.syntax, file, prepared->rows.sink, row_options_of(options));
  return finish(*prepared, rows, text.size(), options);
}

// A file streamed from disk: the header from its first block, the rows block
// by block, the digest on the way.
ForceHistory read_one(const fs::path& path, const OpenFoamForcesOptions& options) {
  std::unique_ptr<Prepared> prepared;
  const history_text::StreamedRows streamed = history_text::parse_file_rows(
      path,
      [&](std::string_view head) {
        prepared = prepare(head, path.string());
        return prepared->rows;
      },
      row_options_of(options), options.compute_sha256);
  ForceHistory history = finish(*prepared, streamed.rows, streamed.size_bytes, options);
  history.files.front().sha256 = streamed.sha256;
  return history;
}

}  // namespace

ForceHistory parse_openfoam_force_file(std::string_view text, const std::string& file,
                                       const OpenFoamForcesOptions& options) {
  ForceHistory history = parse_file(text, file, options);
  decide_abscissa(history, options);
  check_force_history(history);
  return history;
}

bool looks_like_openfoam_forces(std::string_view head) {
  const Header header = read_header(head);
  if (header.columns == nullptr) return false;
  const std::string_view line = header.columns->text;
  return line.find("total_x") != std::string_view::npos || line.find("forces(") != std::string_view::npos ||
         line.find("Cd") != std::string_view::npos || line.find("Cl") != std::string_view::npos;
}

ForceHistory read_openfoam_forces(const fs::path& path, const OpenFoamForcesOptions& options) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(SourceLocation{path.string()}, "no such file or folder");

  // Collect the candidate files with their start-time folder.
  std::vector<FoundFile> found;
  bool single_file = false;
  if (fs::is_regular_file(path, ec)) {
    auto file = classify(path);
    if (!file)
      throw InputError(SourceLocation{path.string()},
                       "not an OpenFOAM force file; expected force.dat, moment.dat, forces.dat, coefficient.dat or "
                       "forceCoeffs.dat (or a _<time> restart of one)");
    single_file = true;
    found.push_back(*file);
    if (file->base == "force" || file->base == "moment") {
      const std::string name = path.filename().string();
      const std::string suffix = name.substr(file->base.size(), name.size() - file->base.size() - 4);  // "" or "_500"
      const fs::path other = path.parent_path() / ((file->base == "force" ? "moment" : "force") + suffix + ".dat");
      if (fs::is_regular_file(other, ec)) {
        auto partner_file = classify(other);
        if (partner_file) found.push_back(*partner_file);
      }
    }
  } else {
    std::vector<std::pair<double, fs::path>> time_folders;
    for (const auto& entry : fs::directory_iterator(path, ec)) {
      if (!entry.is_directory(ec)) continue;
      if (const auto time = to_number(entry.path().filename().string())) time_folders.emplace_back(*time, entry.path());
    }
    if (time_folders.empty()) {
      const auto time = to_number(path.filename().string());
      found = files_in(path, time.value_or(0.0));
    } else {
      for (const auto& [time, folder] : time_folders) {
        auto files = files_in(folder, time);
        found.insert(found.end(), files.begin(), files.end());
      }
    }
    if (found.empty())
      throw InputError(SourceLocation{path.string()},
                       "no OpenFOAM force files (force.dat and moment.dat, forces.dat, coefficient.dat, "
                       "forceCoeffs.dat) in it or in its start-time folders; it holds " +
                           listing(path));
  }

  // One family: ESI force/moment over Foundation forces over coefficients.
  int family = 3;
  for (const FoundFile& f : found) family = std::min(family, family_of(f.base));
  std::vector<std::string> ignored;
  std::vector<FoundFile> used;
  for (FoundFile& f : found) {
    if (family_of(f.base) == family)
      used.push_back(std::move(f));
    else
      ignored.push_back(f.path.string());
  }

  // Segments: a file, or a force/moment pair, per (folder, name time).
  struct Segment {
    double folder_time;
    double name_time;
    ForceHistory history;
  };
  std::map<std::tuple<double, double, std::string>, std::vector<FoundFile>> groups;
  for (FoundFile& f : used) {
    const std::string key_base = family == 0 ? std::string("force/moment") : f.base;
    groups[{f.folder_time, f.name_time, f.path.parent_path().string() + "|" + key_base}].push_back(std::move(f));
  }
  std::vector<Segment> segments;
  std::vector<std::string> notes;
  for (auto& [key, files] : groups) {
    std::sort(files.begin(), files.end(), [](const FoundFile& a, const FoundFile& b) { return a.base < b.base; });
    ForceHistory history;
    if (family == 0) {
      const FoundFile* force = nullptr;
      const FoundFile* moment = nullptr;
      for (const FoundFile& f : files) (f.base == "force" ? force : moment) = &f;
      if (force && moment) {
        // moment.dat is read on another thread while force.dat is read here: the
        // files' reading and their serial steps overlap. A failure of force.dat
        // is reported first, as when they were read in turn.
        auto moments = std::async(std::launch::async, [&] { return read_one(moment->path, options); });
        history = read_one(force->path, options);
        merge_moments(history, moments.get(), options.drop_incomplete_last_row);
      } else {
        const FoundFile* only = force ? force : moment;
        history = read_one(only->path, options);
        notes.push_back(only->path.string() + " has no " + (force ? "moment" : "force") +
                        " file beside it: " + (force ? "moments" : "forces") + " are left empty");
      }
    } else {
      if (files.size() > 1)
        throw InputError(SourceLocation{files[1].path.string()},
                         "two coefficient files for one start time (" + files[0].path.filename().string() + " and " +
                             files[1].path.filename().string() + "); expected one");
      history = read_one(files[0].path, options);
    }
    if (history.size() == 0) {
      notes.push_back(history.files.front().path.string() + " holds no rows and is left out");
      continue;
    }
    segments.push_back({std::get<0>(key), std::get<1>(key), std::move(history)});
  }
  if (segments.empty())
    throw InputError(SourceLocation{path.string()}, "the force files hold no rows; expected at least one sample");

  std::stable_sort(segments.begin(), segments.end(), [](const Segment& a, const Segment& b) {
    return std::make_tuple(a.history.abscissa_values.front(), a.folder_time, a.name_time) <
           std::make_tuple(b.history.abscissa_values.front(), b.folder_time, b.name_time);
  });
  ForceHistory joined = std::move(segments.front().history);
  for (std::size_t s = 1; s < segments.size(); ++s) join(joined, std::move(segments[s].history));
  for (auto& note : notes) joined.notes.push_back(std::move(note));
  for (const auto& file : ignored)
    joined.notes.push_back(file + " is left out: " +
                           std::string(family == 0 ? "force.dat and moment.dat" : "forces.dat") + " are read instead");
  if (segments.size() > 1 && !single_file)
    joined.notes.push_back(std::to_string(segments.size()) + " files (restarts) joined in time order");
  count_rows_used(joined);
  decide_abscissa(joined, options);
  check_force_history(joined);
  return joined;
}

}  // namespace hydrocoef
