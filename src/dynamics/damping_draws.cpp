#include "src/dynamics/damping_draws.hpp"
#include "src/surface/grid_nodes.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "src/core/damping_terms.hpp"
#include "src/core/error.hpp"
#include "src/core/run.hpp"

namespace hydrocoef {
namespace {

/// The smallest number of nodes per axis, and the number of nodes per
/// shortest length scale, of a GP surface's draw grid: evenly spaced (so a
/// lookup finds its cell by direct index) and fine enough that the spline's
/// error, of order (spacing / length scale)^4 of the draw's own scale, is
/// far below the posterior's spread even next to a noise-free run.
constexpr std::size_t kMinNodesPerAxis = 17;
constexpr double kNodesPerLengthScale = 16.0;

/// The largest n with n^dims <= budget.
std::size_t nodes_per_axis_cap(std::size_t budget, std::size_t dims) {
  std::size_t n = 1;
  while (true) {
    double product = 1.0;
    for (std::size_t a = 0; a < dims; ++a) product *= static_cast<double>(n + 1);
    if (product > static_cast<double>(budget)) return n;
    ++n;
  }
}

Extrapolation grid_policy(RbfOutOfRange policy) {
  switch (policy) {
    case RbfOutOfRange::Error: return Extrapolation::Error;
    case RbfOutOfRange::Clamp: return Extrapolation::Clamp;
    case RbfOutOfRange::Extrapolate: return Extrapolation::Linear;
  }
  return Extrapolation::Error;
}

}  // namespace

DampingDraws::Gaussian DampingDraws::gaussian(Eigen::VectorXd mean, const Eigen::MatrixXd& covariance) {
  // P A P^T = L D L^T, so A = F F^T with F = P^T L D^1/2 (D >= 0 up to
  // round-off for a semi-definite A; negative round-off counts as 0).
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(covariance);
  const Eigen::VectorXd root = ldlt.vectorD().cwiseMax(0.0).cwiseSqrt();
  Eigen::MatrixXd lower = ldlt.matrixL();
  lower = lower * root.asDiagonal();
  Gaussian g;
  g.mean = std::move(mean);
  g.factor = ldlt.transpositionsP().transpose() * lower;
  return g;
}

DampingDraws::DampingDraws(const DampingModel& nominal, const DampingSpec& spec) : nominal_(nominal) {
  for (std::size_t i = 0; i < nominal_.laws_.size(); ++i) {
    const auto& law = nominal_.laws_[i];
    const DofDamping& d = spec[law.dof];
    const std::string name = std::string(kForceNames[law.dof]) + ": law " + format_damping_terms(d.law) +
                             (d.fit.empty() ? "" : " (fit '" + d.fit + "')");
    if (d.covariance.empty()) {
      held_.push_back(name + " held at its coefficients (no covariance)");
      continue;
    }
    if (const auto problem = covariance_problem(d.covariance, law.count))
      throw InputError("damping of " + std::string(kForceNames[law.dof]) + ": covariance: " + *problem);
    const auto k = static_cast<Eigen::Index>(law.count);
    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> sigma(
        d.covariance.data(), k, k);
    Eigen::VectorXd mean(k);
    for (Eigen::Index j = 0; j < k; ++j) mean[j] = law.coefficients[static_cast<std::size_t>(j)];
    // The sign convention multiplies every coefficient by +-1: the covariance is unchanged.
    laws_.push_back({i, gaussian(std::move(mean), sigma)});
    drawn_.push_back(name + " drawn from its covariance");
  }

  for (std::size_t i = 0; i < nominal_.derivatives_.size(); ++i) {
    const auto& model = nominal_.derivatives_[i];
    const DofDamping& d = spec[model.dof];
    const std::string name = std::string(kForceNames[model.dof]) + ": derivatives " + model.text;
    if (d.covariance.empty()) {
      held_.push_back(name + " held at its coefficients (no covariance; give \"covariance\" to draw them)");
      continue;
    }
    const std::size_t m = model.coefficients.size();
    if (const auto problem = covariance_problem(d.covariance, m))
      throw InputError("damping of " + std::string(kForceNames[model.dof]) + ": covariance: " + *problem);
    const auto k = static_cast<Eigen::Index>(m);
    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> sigma(
        d.covariance.data(), k, k);
    Eigen::VectorXd mean = Eigen::Map<const Eigen::VectorXd>(model.coefficients.data(), k);
    // The sign convention multiplies every coefficient by +-1: the covariance is unchanged.
    derivatives_.push_back({i, gaussian(std::move(mean), sigma)});
    drawn_.push_back(name + " drawn from its covariance");
  }

  for (std::size_t l = 0; l < nominal_.lookups_.size(); ++l) {
    const auto& lookup = nominal_.lookups_[l];
    const CoefficientSurface& surface = lookup.surface;
    std::string dofs;
    for (std::size_t k = 0; k < lookup.used; ++k)
      dofs += std::string(dofs.empty() ? "" : ",") + std::string(kForceNames[lookup.dof[k]]);
    const std::string name = dofs + ": surface '" + lookup.key.substr(0, lookup.key.find('|')) + "'";
    const GpSurfaces* gp = surface.gp();
    if (!gp) {
      held_.push_back(name + " (" + surface.method_name() + ") held at its values (" +
                      (surface.has_standard_deviation()
                           ? "its standard deviation is pointwise, with no joint distribution to draw a function from"
                           : "it states no uncertainty") +
                      "; a GP surface or a fitted law can be drawn)");
      continue;
    }
    SurfaceDraw draw;
    draw.lookup = l;
    draw.outputs = surface.output_names();
    const std::size_t dims = surface.axis_count();
    const std::size_t cap = nodes_per_axis_cap(kMaxNodes, dims);
    std::vector<bool> read(surface.output_count(), false);
    for (std::size_t k = 0; k < lookup.used; ++k) read[lookup.output[k]] = true;
    bool coarse = false;
    draw.nodes = 1;
    for (std::size_t a = 0; a < dims; ++a) {
      double shortest = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < surface.output_count(); ++k)
        if (read[k]) shortest = std::min(shortest, gp->output(k).length_scales()[a]);
      const double range = gp->upper(a) - gp->lower(a);
      const double wanted_spacing = shortest / kNodesPerLengthScale;
      const double wanted = std::ceil(range / wanted_spacing) + 1.0;
      std::size_t n = kMinNodesPerAxis;
      if (wanted > static_cast<double>(n))
        n = wanted > static_cast<double>(cap) ? cap : static_cast<std::size_t>(wanted);
      if (n > cap) n = cap;
      if (wanted > static_cast<double>(n)) coarse = true;
      GridAxis axis;
      axis.name = surface.axis_names()[a];
      axis.extrapolation = grid_policy(gp->out_of_range(a));
      for (std::size_t i = 0; i < n; ++i)
        axis.breakpoints.push_back(
            i + 1 == n ? gp->upper(a) : gp->lower(a) + range * static_cast<double>(i) / static_cast<double>(n - 1));
      draw.nodes *= n;
      draw.axes.push_back(std::move(axis));
    }
    // The nodes, axis 0 fastest (GridTable's order).
    std::vector<double> points(draw.nodes * dims);
    for (std::size_t node = 0; node < draw.nodes; ++node)
      grid_node_point(draw.axes, node, std::span<double>(points).subspan(node * dims, dims));
    for (std::size_t k = 0; k < surface.output_count(); ++k) {
      std::vector<double> mean, covariance;
      gp->output(k).posterior(points, draw.nodes, mean, covariance);
      Eigen::VectorXd m = Eigen::Map<const Eigen::VectorXd>(mean.data(), static_cast<Eigen::Index>(mean.size()));
      if (!read[k]) {
        draw.output.push_back({std::move(m), Eigen::MatrixXd()});
        continue;
      }
      const auto count = static_cast<Eigen::Index>(draw.nodes);
      const Eigen::Map<const Eigen::MatrixXd> c(covariance.data(), count, count);
      draw.output.push_back(gaussian(std::move(m), c));
    }
    std::string grid;
    for (const auto& axis : draw.axes) grid += (grid.empty() ? "" : " x ") + std::to_string(axis.breakpoints.size());
    drawn_.push_back(name + " (gp) drawn from its posterior on " + grid + " nodes");
    if (coarse)
      notes_.push_back(name + ": the draw grid (" + grid + " nodes, at most " + std::to_string(kMaxNodes) +
                       ") is coarser than a sixteenth of the shortest length scale; draws are smoothed between nodes");
    surfaces_.push_back(std::move(draw));
  }
}

DampingModel DampingDraws::draw(std::uint64_t seed, std::uint64_t index) const {
  std::seed_seq sequence{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                         static_cast<std::uint32_t>(index), static_cast<std::uint32_t>(index >> 32)};
  std::mt19937_64 generator(sequence);
  std::normal_distribution<double> normal;
  auto sample = [&](const Gaussian& g) {
    Eigen::VectorXd z(g.factor.cols());
    for (Eigen::Index i = 0; i < z.size(); ++i) z[i] = normal(generator);
    return Eigen::VectorXd(g.mean + g.factor * z);
  };

  DampingModel model = nominal_;
  for (const LawDraw& law : laws_) {
    const Eigen::VectorXd c = sample(law.coefficients);
    auto& target = model.laws_[law.law];
    for (std::size_t j = 0; j < target.count; ++j) target.coefficients[j] = c[static_cast<Eigen::Index>(j)];
  }
  for (const LawDraw& draw : derivatives_) {
    const Eigen::VectorXd c = sample(draw.coefficients);
    auto& target = model.derivatives_[draw.law].coefficients;
    for (std::size_t j = 0; j < target.size(); ++j) target[j] = c[static_cast<Eigen::Index>(j)];
  }
  for (const SurfaceDraw& s : surfaces_) {
    const std::size_t outputs = s.outputs.size();
    std::vector<double> values(s.nodes * outputs);
    for (std::size_t k = 0; k < outputs; ++k) {
      const Gaussian& g = s.output[k];
      const Eigen::VectorXd v = g.factor.size() == 0 ? g.mean : sample(g);
      for (std::size_t node = 0; node < s.nodes; ++node)
        values[node * outputs + k] = v[static_cast<Eigen::Index>(node)];
    }
    auto& lookup = model.lookups_[s.lookup];
    const CoefficientSurface& nominal = lookup.surface;
    // A draw of the interpolant; the nominal surface's symmetry projects it as it projects the mean.
    lookup.surface = CoefficientSurface(GridTable(s.axes, s.outputs, std::move(values), Interpolation::NaturalSpline),
                                        nominal.axis_units(), nominal.output_units())
                         .with_symmetry(nominal.symmetry());
  }
  return model;
}

}  // namespace hydrocoef
