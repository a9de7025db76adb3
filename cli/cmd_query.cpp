// hydrocoef query: a stored surface at one point (NAME u=0.2 v=0.07), or at
// every row of a CSV file or standard input, written as CSV.
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

#include "cli/common.hpp"
#include "src/core/atomic_file.hpp"
#include "src/core/error.hpp"
#include "src/core/escape.hpp"
#include "src/surface/stored_surface.hpp"

namespace hydrocoef::cli {
namespace {

struct QueryArgs {
  std::string name;
  std::vector<std::string> point;
  std::string input;
  std::string output = "-";
  bool gradient = false;
  bool json = false;
};

void warn_if_stale(const SurfaceRecord& record) {
  if (record.stale)
    std::cerr << "hydrocoef: warning: surface '" << record.name
              << "' is stale: forces of its body changed since it was built (hydrocoef surface rebuild " << record.name
              << ")\n";
}

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

void query_point(const QueryArgs& args, const StoredSurface& stored) {
  const CoefficientSurface& surface = stored.surface;
  const std::size_t n_axes = surface.axis_count(), n_out = surface.output_count();
  std::vector<double> point(n_axes, std::nan(""));
  for (const auto& text : args.point) {
    const auto [axis, value] = parse_assignment(text, "point");
    const std::size_t a = surface.axis_index(axis);
    if (!std::isnan(point[a])) throw InputError("axis '" + axis + "' is given twice");
    point[a] = value;
  }
  for (std::size_t a = 0; a < n_axes; ++a)
    if (std::isnan(point[a]))
      throw InputError("no value for axis '" + surface.axis_names()[a] + "'; surface '" + args.name +
                       "' needs one value for each of its axes: " + join(surface.axis_names()) +
                       " (e.g. " + surface.axis_names()[a] + "=0.1)");
  std::vector<double> out(n_out), gradient(n_out * n_axes);
  if (args.gradient)
    surface.evaluate_with_gradient(point, out, gradient);
  else
    surface.evaluate(point, out);

  if (args.json) {
    nlohmann::json json = {{"surface", args.name}, {"stale", stored.record.stale}};
    for (std::size_t a = 0; a < n_axes; ++a) json["point"][surface.axis_names()[a]] = point[a];
    for (std::size_t k = 0; k < n_out; ++k) {
      json["values"][surface.output_names()[k]] = out[k];
      json["units"][surface.output_names()[k]] = surface.output_units()[k];
      if (args.gradient)
        for (std::size_t a = 0; a < n_axes; ++a)
          json["gradient"][surface.output_names()[k]][surface.axis_names()[a]] = gradient[k * n_axes + a];
    }
    std::cout << escape::json_text(json, 2) << '\n';
    return;
  }
  std::cout << args.name << " at";
  for (std::size_t a = 0; a < n_axes; ++a)
    std::cout << " " << surface.axis_names()[a] << "=" << significant(point[a], 8);
  std::cout << " (forces on the body)\n";
  for (std::size_t k = 0; k < n_out; ++k) {
    std::cout << "  " << std::left << std::setw(4) << surface.output_names()[k] << std::setw(16)
              << significant(out[k], 9) << surface.output_units()[k] << '\n';
    if (args.gradient)
      for (std::size_t a = 0; a < n_axes; ++a) {
        const std::string& unit = surface.axis_units()[a];
        std::cout << "      d" << surface.output_names()[k] << "/d" << std::setw(10) << surface.axis_names()[a]
                  << std::setw(16) << significant(gradient[k * n_axes + a], 9) << surface.output_units()[k]
                  << (unit.empty() ? "" : " per " + unit) << '\n';
      }
  }
}

/// Reads a whole file or standard input ("-").
std::string read_all(const std::string& path) {
  std::FILE* file = path == "-" ? stdin : std::fopen(path.c_str(), "rb");
  if (!file) throw InputError(path + ": cannot open for reading");
  std::string data;
  if (file != stdin && std::fseek(file, 0, SEEK_END) == 0) {
    const long size = std::ftell(file);
    if (size > 0) data.reserve(static_cast<std::size_t>(size));
    std::rewind(file);
  }
  char buffer[1 << 16];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) data.append(buffer, n);
  const bool failed = std::ferror(file) != 0;
  if (file != stdin) std::fclose(file);
  if (failed) throw InputError(path + ": read error");
  return data;
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) text.remove_suffix(1);
  return text;
}

/// Buffered output to a file or standard output; the file is written through
/// an AtomicFile (a temporary renamed at the end), so a failed batch leaves
/// no file and a full disk is called that.
class Output {
 public:
  explicit Output(const std::string& path) : path_(path) {
    if (path_ != "-") file_.emplace(path_);
    buffer_.reserve(kFlushAt + 4096);
  }
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;

  void text(std::string_view s) {
    if (s.size() >= kFlushAt) {  // a whole slice of answers: written as it is
      flush();
      write(s);
      return;
    }
    buffer_.append(s);
    if (buffer_.size() >= kFlushAt) flush();
  }
  void finish() {
    flush();
    if (file_) {
      file_->commit();
    } else if (std::fflush(stdout) != 0) {
      throw InputError("standard output: " + write_error_text(errno));
    }
  }

 private:
  static constexpr std::size_t kFlushAt = 1 << 20;
  void write(std::string_view s) {
    if (file_) {
      file_->write(s);
    } else if (std::fwrite(s.data(), 1, s.size(), stdout) != s.size()) {
      throw InputError("standard output: " + write_error_text(errno));
    }
  }
  void flush() {
    write(buffer_);
    buffer_.clear();
  }
  std::string path_;
  std::optional<AtomicFile> file_;
  std::string buffer_;
};

/// One slice of the batch's rows, answered on its own thread: the CSV text
/// of its answers, how many lines it spans, and the first error, if any,
/// with its line counted from the slice's start (1 = first line).
struct SliceResult {
  std::string text;
  std::size_t lines = 0;
  std::size_t points = 0;
  std::optional<std::size_t> error_line;
  std::size_t error_column = 0;
  std::string error;
};

void answer_slice(const CoefficientSurface& surface, const std::vector<std::size_t>& column_axis, bool with_gradient,
                  std::string_view rows, SliceResult& result) {
  const std::size_t n_axes = surface.axis_count(), n_out = surface.output_count();
  std::vector<double> point(n_axes), values(n_out), gradient(n_out * n_axes);
  result.text.reserve(rows.size() * (with_gradient ? 6 : 3) / 2 + 64);
  const auto append_number = [&](double value) {
    char digits[32];
    const auto [end, ec] = std::to_chars(digits, digits + sizeof digits, value);
    (void)ec;
    result.text.append(digits, end);
  };
  while (!rows.empty()) {
    const auto newline = rows.find('\n');
    std::string_view line = rows.substr(0, newline);
    rows = newline == std::string_view::npos ? std::string_view() : rows.substr(newline + 1);
    ++result.lines;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (trim(line).empty()) continue;
    const char* p = line.data();
    const char* const end = line.data() + line.size();
    const auto fail = [&](const char* at, std::string message) {
      result.error_line = result.lines;
      result.error_column = at ? static_cast<std::size_t>(at - line.data()) + 1 : 0;
      result.error = std::move(message);
    };
    for (std::size_t c = 0; c < column_axis.size(); ++c) {
      while (p < end && (*p == ' ' || *p == '\t')) ++p;
      if (p < end && *p == '+') ++p;
      double value = 0.0;
      const auto [stop, ec] = std::from_chars(p, end, value);
      if (ec != std::errc{} || !std::isfinite(value)) {
        const auto cell_end = std::find(p, end, ',');
        fail(p, "'" + printable_text(std::string_view(p, static_cast<std::size_t>(std::min<std::ptrdiff_t>(cell_end - p, 64))), 40) +
                    "' in column '" + surface.axis_names()[column_axis[c]] +
                    "'; expected a finite number");
        return;
      }
      p = stop;
      while (p < end && (*p == ' ' || *p == '\t')) ++p;
      const bool last = c + 1 == column_axis.size();
      if (last ? p != end : (p == end || *p != ',')) {
        fail(p, "row has " + std::string(last ? "more" : "fewer") + " than " + std::to_string(column_axis.size()) +
                    " numbers; expected one per header column");
        return;
      }
      ++p;
      point[column_axis[c]] = value;
    }
    try {
      if (with_gradient)
        surface.evaluate_with_gradient(point, values, gradient);
      else
        surface.evaluate(point, values);
    } catch (const InputError& error) {
      fail(nullptr, error.what());
      return;
    }
    for (std::size_t a = 0; a < n_axes; ++a) {
      if (a) result.text += ',';
      append_number(point[a]);
    }
    for (std::size_t k = 0; k < n_out; ++k) {
      result.text += ',';
      append_number(values[k]);
    }
    if (with_gradient)
      for (double g : gradient) {
        result.text += ',';
        append_number(g);
      }
    result.text += '\n';
    ++result.points;
  }
}

/// Answers every row of a CSV of points. Rows are split into slices at line
/// ends and answered on all cores (a surface is thread-safe to evaluate);
/// the answers are written in input order, and the first bad row (in input
/// order) is the one reported.
void query_batch(const QueryArgs& args, const StoredSurface& stored) {
  const CoefficientSurface& surface = stored.surface;
  const std::size_t n_axes = surface.axis_count(), n_out = surface.output_count();
  const std::string source = args.input == "-" ? "<stdin>" : args.input;
  const std::string data = read_all(args.input);
  std::string_view rest = data;
  std::size_t line_number = 0;
  const auto next_line = [&]() -> std::string_view {
    const auto end = rest.find('\n');
    std::string_view line = rest.substr(0, end);
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return line;
  };
  // Header: one column per axis, in any order.
  std::string_view header;
  while (!rest.empty() && (header = trim(next_line())).empty()) {
  }
  if (header.empty())
    throw InputError(source + ": empty; expected a header naming the axes (" + join(surface.axis_names()) + ")");
  std::vector<std::size_t> column_axis;
  std::vector<bool> seen(n_axes, false);
  for (std::size_t start = 0; start <= header.size();) {
    const auto comma = header.find(',', start);
    const std::string name(trim(header.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    std::size_t a = n_axes;
    for (std::size_t i = 0; i < n_axes; ++i)
      if (surface.axis_names()[i] == name) a = i;
    if (a == n_axes)
      throw InputError(SourceLocation{source, line_number, start + 1},
                       "column '" + printable_text(name, 40) + "' is not an axis of surface '" + args.name + "'; expected the axes " +
                           join(surface.axis_names()));
    if (seen[a]) throw InputError(SourceLocation{source, line_number, start + 1}, "column '" + printable_text(name, 40) + "' repeats");
    seen[a] = true;
    column_axis.push_back(a);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  for (std::size_t a = 0; a < n_axes; ++a)
    if (!seen[a])
      throw InputError(SourceLocation{source, line_number, 0},
                       "no column for axis '" + surface.axis_names()[a] + "'; expected columns " +
                           join(surface.axis_names()));

  Output out(args.output);
  for (std::size_t a = 0; a < n_axes; ++a) out.text((a ? "," : "") + surface.axis_names()[a]);
  for (std::size_t k = 0; k < n_out; ++k) out.text("," + surface.output_names()[k]);
  if (args.gradient)
    for (std::size_t k = 0; k < n_out; ++k)
      for (std::size_t a = 0; a < n_axes; ++a)
        out.text(",d" + surface.output_names()[k] + "/d" + surface.axis_names()[a]);
  out.text("\n");

  // Rounds of one slice per thread, each slice about 4 MB of input.
  const std::size_t threads = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 8);
  constexpr std::size_t kSliceBytes = std::size_t{4} << 20;
  std::size_t points = 0;
  std::vector<SliceResult> results(threads);
  while (!rest.empty()) {
    std::vector<std::string_view> slices;
    for (std::size_t t = 0; t < threads && !rest.empty(); ++t) {
      std::size_t cut = std::min(rest.size(), kSliceBytes);
      if (cut < rest.size()) {
        const auto newline = rest.find('\n', cut);
        cut = newline == std::string_view::npos ? rest.size() : newline + 1;
      }
      slices.push_back(rest.substr(0, cut));
      rest.remove_prefix(cut);
    }
    std::vector<std::thread> workers;
    for (std::size_t t = 0; t < slices.size(); ++t) {
      results[t] = SliceResult{};
      if (t + 1 == slices.size())
        answer_slice(surface, column_axis, args.gradient, slices[t], results[t]);
      else
        workers.emplace_back(answer_slice, std::cref(surface), std::cref(column_axis), args.gradient, slices[t],
                             std::ref(results[t]));
    }
    for (auto& worker : workers) worker.join();
    for (std::size_t t = 0; t < slices.size(); ++t) {
      const SliceResult& result = results[t];
      if (result.error_line)
        throw InputError(SourceLocation{source, line_number + *result.error_line, result.error_column}, result.error);
      out.text(result.text);
      line_number += result.lines;
      points += result.points;
    }
  }
  out.finish();
  if (args.output != "-" && !args.json)
    std::cerr << "hydrocoef: " << points << " points of surface '" << args.name << "' written to " << args.output
              << '\n';
  if (args.json && args.output != "-")
    std::cout << escape::json_text(nlohmann::json{{"surface", args.name}, {"points", points}, {"output", args.output}}, 2) << '\n';
}

void run_query(const QueryArgs& args, const GlobalOptions& global) {
  if (!args.input.empty() && !args.point.empty())
    throw InputError("give either a point (AXIS=VALUE ...) or --input, not both");
  if (args.input.empty() && args.point.empty())
    throw InputError("no point; expected AXIS=VALUE for each axis of the surface, or --input FILE (- for stdin)");
  Database database(global.database, Database::OpenMode::ReadOnly);
  const StoredSurface stored = load_surface(database, args.name);
  warn_if_stale(stored.record);
  if (args.input.empty())
    query_point(args, stored);
  else
    query_batch(args, stored);
}

}  // namespace

void add_query_command(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<QueryArgs>();
  auto* query = app.add_subcommand(
      "query",
      "Evaluate a stored surface: at one point (hydrocoef query NAME u=0.2 v=0.07), or at every row of a CSV whose "
      "header names the axes (--input FILE, - for stdin), written as CSV (--output FILE, default stdout). Values are "
      "forces on the body in N or N m; out-of-range points follow the surface's policy.");
  query->add_option("name", args->name, "Surface name")->required();
  query->add_option("point", args->point, "AXIS=VALUE for each axis (SI units)");
  query->add_option("--input", args->input, "CSV of points (header: axis names), - for standard input");
  query->add_option("--output", args->output, "CSV of results, - for standard output")->capture_default_str();
  query->add_flag("--gradient", args->gradient, "Also the derivative of each output along each axis");
  query->add_flag("--json", args->json, "Machine-readable output (single point)");
  query->callback([args, &global] { run_query(*args, global); });
}

}  // namespace hydrocoef::cli
