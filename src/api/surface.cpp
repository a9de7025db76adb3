// Surface (include/hydrocoef/surface.hpp) over CoefficientSurface and the
// batch engine (src/surface/batch_evaluation): evaluation, a gridded
// surface's own table, any surface tabulated on given breakpoints, and where
// its standard deviation is largest.
#include "src/api/internal.hpp"
#include "src/api/surface_report.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "src/core/numbers.hpp"
#include "src/surface/grid_table.hpp"

namespace hydrocoef {
inline namespace api {

Surface::Surface(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {
  if (!impl_) throw std::invalid_argument("hydrocoef::Surface: no surface");
}

const std::string& Surface::name() const { return impl_->name; }
const std::string& Surface::body() const { return impl_->body; }
const std::string& Surface::method() const { return impl_->method; }
bool Surface::stale() const { return impl_->stale; }
const std::vector<std::string>& Surface::axes() const { return impl_->surface.axis_names(); }
const std::vector<std::string>& Surface::outputs() const { return impl_->surface.output_names(); }
const std::vector<std::string>& Surface::axis_units() const { return impl_->surface.axis_units(); }
const std::vector<std::string>& Surface::output_units() const { return impl_->surface.output_units(); }
double Surface::lower(std::size_t axis) const { return impl_->surface.lower(axis); }
double Surface::upper(std::size_t axis) const { return impl_->surface.upper(axis); }

std::string Surface::out_of_range(std::size_t axis) const {
  if (axis >= impl_->surface.axis_count())
    throw std::out_of_range("hydrocoef::Surface::out_of_range: axis " + std::to_string(axis) + " of " +
                            std::to_string(impl_->surface.axis_count()));
  return impl_->surface.out_of_range_name(axis);
}

std::vector<double> Surface::evaluate(const std::vector<double>& point) const {
  std::vector<double> out(impl_->surface.output_count());
  impl_->surface.evaluate(point, out);
  return out;
}

Surface::ValueAndGradient Surface::evaluate_with_gradient(const std::vector<double>& point) const {
  const CoefficientSurface& s = impl_->surface;
  ValueAndGradient result{std::vector<double>(s.output_count()),
                          std::vector<double>(s.output_count() * s.axis_count())};
  s.evaluate_with_gradient(point, result.values, result.gradient);
  return result;
}

bool Surface::has_standard_deviation() const { return impl_->surface.has_standard_deviation(); }

Surface::ValueAndDeviation Surface::evaluate_with_standard_deviation(const std::vector<double>& point) const {
  const CoefficientSurface& s = impl_->surface;
  ValueAndDeviation result{std::vector<double>(s.output_count()), std::vector<double>(s.output_count())};
  s.evaluate_with_standard_deviation(point, result.values, result.standard_deviation);
  return result;
}

void Surface::evaluate_batch(std::size_t count, const std::vector<ConstColumn>& inputs,
                             const std::vector<Column>& outputs, const std::vector<Column>& gradients, unsigned threads,
                             const std::vector<Column>& standard_deviations) const {
  // The public columns and the engine's have the same layout; copied (a few
  // per batch) rather than cast, so that neither depends on the other.
  std::vector<StridedInput> in(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) in[i] = {inputs[i].data, inputs[i].stride};
  std::vector<StridedOutput> out(outputs.size()), grad(gradients.size());
  for (std::size_t i = 0; i < outputs.size(); ++i) out[i] = {outputs[i].data, outputs[i].stride};
  for (std::size_t i = 0; i < gradients.size(); ++i) grad[i] = {gradients[i].data, gradients[i].stride};
  std::vector<StridedOutput> sd(standard_deviations.size());
  for (std::size_t i = 0; i < standard_deviations.size(); ++i)
    sd[i] = {standard_deviations[i].data, standard_deviations[i].stride};
  hydrocoef::evaluate_batch(impl_->surface, count, in, out, grad, threads, sd);
}

bool Surface::gridded() const { return impl_->surface.grid() != nullptr; }

SurfaceTable Surface::table() const {
  const GridTable* grid = impl_->surface.grid();
  if (!grid)
    throw InputError("surface '" + impl_->name + "' (method " + impl_->method +
                     ") is not gridded: it has no breakpoints or node values; expected a table "
                     "(nearest, linear, pchip, makima, natural-spline, or rbf with --resample), or use tabulate()");
  const CoefficientSurface& s = impl_->surface;
  std::vector<std::vector<double>> breakpoints;
  for (const GridAxis& axis : grid->axes()) breakpoints.push_back(axis.breakpoints);
  // The values as stored (outputs interleaved per node); the standard
  // deviations as the surface states them at the nodes (export's way).
  SurfaceTable table =
      s.has_standard_deviation()
          ? tabulate(breakpoints)
          : SurfaceTable{s.axis_names(), s.axis_units(), s.output_names(), s.output_units(), breakpoints, {}, {}};
  const std::size_t n_out = s.output_count(), nodes = grid->node_count();
  table.values.assign(n_out, std::vector<double>(nodes));
  for (std::size_t node = 0; node < nodes; ++node)
    for (std::size_t k = 0; k < n_out; ++k) table.values[k][node] = grid->values()[node * n_out + k];
  return table;
}

SurfaceTable Surface::tabulate(const std::vector<std::vector<double>>& breakpoints, unsigned threads) const {
  const CoefficientSurface& s = impl_->surface;
  const std::size_t d = s.axis_count(), n_out = s.output_count();
  if (breakpoints.size() != d)
    throw InputError("tabulate: " + std::to_string(breakpoints.size()) + " lists of breakpoints for surface '" +
                     impl_->name + "'; expected one per axis (" + std::to_string(d) + ")");
  std::size_t nodes = 1;
  for (std::size_t a = 0; a < d; ++a) {
    const auto& x = breakpoints[a];
    const std::string axis = "tabulate: axis '" + s.axis_names()[a] + "': ";
    if (x.empty()) throw InputError(axis + "no breakpoints; expected at least one");
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (!std::isfinite(x[i])) throw InputError(axis + "breakpoint " + std::to_string(i) + " is not finite");
      if (i && !(x[i] > x[i - 1]))
        throw InputError(axis + "breakpoint " + shortest_number(x[i]) + " after " + shortest_number(x[i - 1]) +
                         "; expected strictly increasing breakpoints");
    }
    if (x.size() > 100'000'000 / nodes) throw InputError("tabulate: more than 10^8 nodes; expected fewer breakpoints");
    nodes *= x.size();
  }
  SurfaceTable table{s.axis_names(), s.axis_units(), s.output_names(), s.output_units(), breakpoints, {}, {}};
  // The nodes' coordinates as columns, the first axis fastest.
  std::vector<std::vector<double>> coordinates(d, std::vector<double>(nodes));
  for (std::size_t node = 0; node < nodes; ++node) {
    std::size_t rest = node;
    for (std::size_t a = 0; a < d; ++a) {
      coordinates[a][node] = breakpoints[a][rest % breakpoints[a].size()];
      rest /= breakpoints[a].size();
    }
  }
  table.values.assign(n_out, std::vector<double>(nodes));
  if (s.has_standard_deviation()) table.standard_deviation.assign(n_out, std::vector<double>(nodes));
  std::vector<StridedInput> in;
  for (const auto& column : coordinates) in.push_back({column.data(), 1});
  std::vector<StridedOutput> out, sd;
  for (auto& column : table.values) out.push_back({column.data(), 1});
  for (auto& column : table.standard_deviation) sd.push_back({column.data(), 1});
  hydrocoef::evaluate_batch(s, nodes, in, out, {}, threads, sd);
  return table;
}

std::vector<std::vector<SigmaPeak>> Surface::largest_standard_deviations(std::size_t count) const {
  if (!impl_->surface.has_standard_deviation()) return {};
  return surface_text::largest_sd(impl_->surface, count);
}

Surface make_surface(StoredSurface stored) {
  std::string method = stored.surface.method_name();
  return Surface(std::make_shared<const Surface::Impl>(Surface::Impl{
      std::move(stored.surface), stored.record.name, stored.record.body, std::move(method), stored.record.stale}));
}

}  // namespace api
}  // namespace hydrocoef
