// Surface (include/hydrocoef/surface.hpp) over CoefficientSurface and the
// batch engine (src/surface/batch_evaluation).
#include "src/api/internal.hpp"

#include <stdexcept>
#include <vector>

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

}  // namespace api
}  // namespace hydrocoef
