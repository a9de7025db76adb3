#include "src/dynamics/experiment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "importers/text_table.hpp"
#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/core/run.hpp"
#include "src/core/units.hpp"
#include "src/dynamics/json_input.hpp"

namespace hydrocoef {
namespace {

constexpr Dimension kTime{{0, 0, 1, 0}};

// Linear interpolation of a simulated component at time t (t inside the samples' span).
double interpolate(const std::vector<TrajectorySample>& samples, std::size_t component, double t) {
  const auto it = std::lower_bound(samples.begin(), samples.end(), t,
                                   [](const TrajectorySample& s, double time) { return s.t_s < time; });
  const auto c = static_cast<Eigen::Index>(component);
  if (it == samples.begin()) return it->nu_b[c];
  if (it == samples.end()) return samples.back().nu_b[c];
  const auto& hi = *it;
  const auto& lo = *std::prev(it);
  const double w = hi.t_s > lo.t_s ? (t - lo.t_s) / (hi.t_s - lo.t_s) : 1.0;
  return (1.0 - w) * lo.nu_b[c] + w * hi.nu_b[c];
}

double mean_after(const std::vector<double>& times, const std::vector<double>& values, double start) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < times.size(); ++i)
    if (times[i] >= start) {
      sum += values[i];
      ++n;
    }
  return n ? sum / static_cast<double>(n) : values.back();
}

}  // namespace

MeasuredTrajectory parse_measured_trajectory(std::string_view text, const std::string& file) {
  MeasuredTrajectory m;
  m.file = file;
  const auto lines = split_lines(text);
  std::size_t header_line = 0;
  while (header_line < lines.size() && (lines[header_line].text.empty() || lines[header_line].text.front() == '#'))
    ++header_line;
  if (header_line == lines.size())
    throw InputError(SourceLocation{file}, "found no header line, expected t and velocity columns");
  const TextLine& header = lines[header_line];
  const char delimiter = detect_delimiter(header.text);
  const auto fields = split_fields(header, delimiter, file);

  std::optional<std::size_t> time_column;
  double time_scale = 1.0;
  std::array<std::optional<std::size_t>, 6> columns;
  std::array<double, 6> scales{};
  struct BandColumn {
    std::size_t component;
    double percentile;
    std::size_t column;
    double scale;
  };
  std::vector<BandColumn> band_columns;
  for (std::size_t c = 0; c < fields.size(); ++c) {
    const NameAndUnit nu = split_name_and_unit(fields[c].text);
    const SourceLocation where{file, header.number, fields[c].column};
    const bool is_time = nu.name == "t" || nu.name == "time";
    auto component = velocity_index(nu.name);
    // A percentile band of a Monte Carlo simulation: "r_p5", "u_p97.5".
    std::optional<double> percentile;
    if (!is_time && !component && nu.name.size() > 3 && nu.name.substr(1, 2) == "_p") {
      const auto band_of = velocity_index(nu.name.substr(0, 1));
      const auto value = parse_finite_number(nu.name.substr(3));
      if (band_of && value && *value > 0.0 && *value < 100.0) {
        component = band_of;
        percentile = value;
      }
    }
    if (!is_time && !component) continue;
    const Dimension expected = is_time ? kTime : (*component < 3 ? kVelocity : kAngularVelocity);
    double scale = 1.0;
    if (nu.has_unit) {
      Unit unit;
      try {
        unit = parse_unit(nu.unit);
      } catch (const InputError& e) {
        throw InputError(where, e.what());
      }
      if (!dimension_matches(unit.dimension, expected))
        throw InputError(where, "column '" + nu.name + "' has unit '" + nu.unit + "' (" + si_unit_name(unit.dimension) +
                                    "), expected " + si_unit_name(expected));
      scale = unit.scale;
    }
    if (percentile) {
      for (const auto& band : band_columns)
        if (band.component == *component && band.percentile == *percentile)
          throw InputError(where, "found column '" + nu.name + "' twice, expected it once");
      band_columns.push_back({*component, *percentile, c, scale});
    } else if (is_time) {
      if (time_column) throw InputError(where, "found a second time column '" + fields[c].text + "', expected one");
      time_column = c;
      time_scale = scale;
    } else {
      if (columns[*component]) throw InputError(where, "found column '" + nu.name + "' twice, expected it once");
      columns[*component] = c;
      scales[*component] = scale;
    }
  }
  if (!time_column)
    throw InputError(SourceLocation{file, header.number, 1}, "found no time column, expected one named t or time");
  if (std::none_of(columns.begin(), columns.end(), [](const auto& c) { return c.has_value(); }))
    throw InputError(SourceLocation{file, header.number, 1},
                     "found no velocity column, expected at least one of u, v, w, p, q, r");

  std::sort(band_columns.begin(), band_columns.end(), [](const BandColumn& a, const BandColumn& b) {
    return a.component != b.component ? a.component < b.component : a.percentile < b.percentile;
  });
  for (const auto& band : band_columns) m.bands_b[band.component].push_back({band.percentile, {}});

  for (std::size_t l = header_line + 1; l < lines.size(); ++l) {
    const TextLine& line = lines[l];
    if (line.text.empty() || line.text.front() == '#') continue;
    const auto row = split_fields(line, delimiter, file);
    auto field = [&](std::size_t c, std::string_view name) -> double {
      if (c >= row.size())
        throw InputError(
            SourceLocation{file, line.number, 0},
            "found " + std::to_string(row.size()) + " fields, expected a value for '" + std::string(name) + "'");
      return parse_number(row[c], file, line.number, name);
    };
    const double t = field(*time_column, "t") * time_scale;
    if (!m.t_s.empty() && !(t > m.t_s.back()))
      throw InputError(SourceLocation{file, line.number, row[*time_column].column},
                       "found time " + std::to_string(t) + " s, expected times that increase");
    m.t_s.push_back(t);
    for (std::size_t k = 0; k < 6; ++k)
      if (columns[k]) m.nu_b[k].push_back(field(*columns[k], kVelocityNames[k]) * scales[k]);
    for (std::size_t b = 0, at = 0; b < band_columns.size(); ++b, ++at) {
      const BandColumn& band = band_columns[b];
      if (b > 0 && band.component != band_columns[b - 1].component) at = 0;
      m.bands_b[band.component][at].second.push_back(
          field(band.column, band_column(kVelocityNames[band.component], band.percentile)) * band.scale);
    }
  }
  if (m.t_s.size() < 2)
    throw InputError(SourceLocation{file}, "found " + std::to_string(m.t_s.size()) + " rows, expected at least 2");
  return m;
}

MeasuredTrajectory read_measured_trajectory(const std::filesystem::path& path) {
  return parse_measured_trajectory(json_input::read_file(path.string()), path.string());
}

double time_to_63_percent(const std::vector<double>& times, const std::vector<double>& values, double steady) {
  if (times.empty()) return kNaN;
  const double start = values.front();
  const double change = steady - start;
  if (!(std::abs(change) > 0.0)) return kNaN;
  const double target = start + (1.0 - std::exp(-1.0)) * change;
  auto progress = [&](double v) { return (v - target) * (change > 0.0 ? 1.0 : -1.0); };  // >= 0 once reached
  for (std::size_t i = 1; i < times.size(); ++i) {
    if (progress(values[i]) >= 0.0) {
      const double a = progress(values[i - 1]);
      const double b = progress(values[i]);
      const double w = b > a ? -a / (b - a) : 1.0;
      return times[i - 1] + std::clamp(w, 0.0, 1.0) * (times[i] - times[i - 1]) - times.front();
    }
  }
  return kNaN;
}

std::vector<ComponentComparison> compare_with_experiment(const MeasuredTrajectory& measured,
                                                         const std::vector<TrajectorySample>& simulated,
                                                         const ComparisonOptions& options) {
  if (simulated.empty()) throw InputError("comparison: the simulation has no samples");
  const double sim_start = simulated.front().t_s;
  const double sim_end = simulated.back().t_s;
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < measured.t_s.size(); ++i)
    if (measured.t_s[i] >= sim_start - 1e-12 && measured.t_s[i] <= sim_end + 1e-12) rows.push_back(i);
  if (rows.empty())
    throw InputError(SourceLocation{measured.file}, "found times " + std::to_string(measured.t_s.front()) + " to " +
                                                        std::to_string(measured.t_s.back()) +
                                                        " s, expected some inside the simulated 0 to " +
                                                        std::to_string(sim_end) + " s");
  const double t_first = measured.t_s[rows.front()];
  const double t_last = measured.t_s[rows.back()];
  const double steady_start = t_last - options.steady_fraction * (t_last - t_first);

  std::vector<ComponentComparison> out;
  for (std::size_t k = 0; k < 6; ++k) {
    if (measured.nu_b[k].empty()) continue;
    ComponentComparison c;
    c.component = std::string(kVelocityNames[k]);
    c.samples = rows.size();
    std::vector<double> mt, mv;
    double sum_squared = 0.0;
    for (const std::size_t i : rows) {
      const double s = interpolate(simulated, k, measured.t_s[i]);
      const double e = measured.nu_b[k][i] - s;
      sum_squared += e * e;
      mt.push_back(measured.t_s[i]);
      mv.push_back(measured.nu_b[k][i]);
    }
    c.rms_error = std::sqrt(sum_squared / static_cast<double>(rows.size()));
    c.steady_measured = mean_after(mt, mv, steady_start);
    // The simulation's own samples over the same window (finer than the measured rows as a rule).
    std::vector<double> st{t_first}, sv_own{interpolate(simulated, k, t_first)};
    for (const auto& sample : simulated)
      if (sample.t_s > t_first && sample.t_s <= t_last) {
        st.push_back(sample.t_s);
        sv_own.push_back(sample.nu_b[static_cast<Eigen::Index>(k)]);
      }
    c.steady_simulated = mean_after(st, sv_own, steady_start);
    c.steady_error = c.steady_measured - c.steady_simulated;
    c.t63_measured_s = time_to_63_percent(mt, mv, c.steady_measured);
    c.t63_simulated_s = time_to_63_percent(st, sv_own, c.steady_simulated);
    out.push_back(c);
  }
  return out;
}

}  // namespace hydrocoef
