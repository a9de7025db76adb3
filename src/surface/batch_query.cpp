#include "src/surface/batch_query.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <thread>

#include "src/core/atomic_file.hpp"
#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/core/parallel.hpp"
#include "src/core/text.hpp"

namespace hydrocoef {
namespace {

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
                  bool with_sd, std::string_view rows, SliceResult& result) {
  const std::size_t n_axes = surface.axis_count(), n_out = surface.output_count();
  std::vector<double> point(n_axes), values(n_out), gradient(n_out * n_axes), sd(n_out);
  result.text.reserve(rows.size() * (with_gradient ? 6 : 3) / 2 + 64);
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
        fail(p, "'" +
                    printable_text(
                        std::string_view(p, static_cast<std::size_t>(std::min<std::ptrdiff_t>(cell_end - p, 64))), 40) +
                    "' in column '" + surface.axis_names()[column_axis[c]] + "'; expected a finite number");
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
      if (with_sd)
        surface.evaluate_with_standard_deviation(point, values, sd,
                                                 with_gradient ? std::span<double>(gradient) : std::span<double>());
      else if (with_gradient)
        surface.evaluate_with_gradient(point, values, gradient);
      else
        surface.evaluate(point, values);
    } catch (const InputError& error) {
      fail(nullptr, error.what());
      return;
    }
    for (std::size_t a = 0; a < n_axes; ++a) {
      if (a) result.text += ',';
      append_shortest_number(result.text, point[a]);
    }
    for (std::size_t k = 0; k < n_out; ++k) {
      result.text += ',';
      append_shortest_number(result.text, values[k]);
    }
    if (with_sd)
      for (double s : sd) {
        result.text += ',';
        append_shortest_number(result.text, s);
      }
    if (with_gradient)
      for (double g : gradient) {
        result.text += ',';
        append_shortest_number(result.text, g);
      }
    result.text += '\n';
    ++result.points;
  }
}

}  // namespace

/// Answers every row of a CSV of points. Rows are split into slices at line
/// ends and answered on all cores (a surface is thread-safe to evaluate);
/// the answers are written in input order, and the first bad row (in input
/// order) is the one reported.
std::size_t query_csv_batch(const CoefficientSurface& surface, const CsvBatchRequest& request) {
  const std::size_t n_axes = surface.axis_count(), n_out = surface.output_count();
  const std::string source = request.input == "-" ? "<stdin>" : request.input;
  if (request.standard_deviation && !surface.has_standard_deviation())
    throw InputError("surface '" + request.surface_name + "' (method '" + surface.method_name() +
                     "') states no standard deviation (stored without its runs' uncertainty: rebuild it with "
                     "hydrocoef surface rebuild); expected a GP surface or a grid or RBF surface built by this "
                     "hydrocoef");
  const std::string data = read_all(request.input);
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
  while (!rest.empty() && (header = trim(next_line())).empty()) {}
  if (header.empty())
    throw InputError(source + ": empty; expected a header naming the axes (" + join(surface.axis_names(), ", ") + ")");
  std::vector<std::size_t> column_axis;
  std::vector<bool> seen(n_axes, false);
  for (std::size_t start = 0; start <= header.size();) {
    const auto comma = header.find(',', start);
    const std::string name(
        trim(header.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    std::size_t a = n_axes;
    for (std::size_t i = 0; i < n_axes; ++i)
      if (surface.axis_names()[i] == name) a = i;
    if (a == n_axes)
      throw InputError(SourceLocation{source, line_number, start + 1},
                       "column '" + printable_text(name, 40) + "' is not an axis of surface '" + request.surface_name +
                           "'; expected the axes " + join(surface.axis_names(), ", "));
    if (seen[a])
      throw InputError(SourceLocation{source, line_number, start + 1},
                       "column '" + printable_text(name, 40) + "' repeats");
    seen[a] = true;
    column_axis.push_back(a);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  for (std::size_t a = 0; a < n_axes; ++a)
    if (!seen[a])
      throw InputError(
          SourceLocation{source, line_number, 0},
          "no column for axis '" + surface.axis_names()[a] + "'; expected columns " + join(surface.axis_names(), ", "));

  Output out(request.output);
  for (std::size_t a = 0; a < n_axes; ++a) out.text((a ? "," : "") + surface.axis_names()[a]);
  for (std::size_t k = 0; k < n_out; ++k) out.text("," + surface.output_names()[k]);
  if (request.standard_deviation)
    for (std::size_t k = 0; k < n_out; ++k) out.text(",sigma_" + surface.output_names()[k]);
  if (request.gradient)
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
    parallel_for(slices.size(), static_cast<unsigned>(threads), [&](std::size_t t) {
      results[t] = SliceResult{};
      answer_slice(surface, column_axis, request.gradient, request.standard_deviation, slices[t], results[t]);
    });
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
  return points;
}

}  // namespace hydrocoef
