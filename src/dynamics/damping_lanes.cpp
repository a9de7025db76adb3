#include "src/dynamics/damping_lanes.hpp"

#include <stdexcept>

namespace hydrocoef {

using motion::kLanes;
using motion::Lanes;

namespace lanes_kernel {
// The shared kernel's law (runtime/src/damping_law_kernel.h) for the lanes:
// DampingModel's arithmetic in every lane.
#define HC_DAMPING_T ::hydrocoef::motion::Lanes
#define HC_DAMPING_SPLAT(v) ::hydrocoef::motion::Lanes::Constant(v)
#define HC_DAMPING_ABS(x) (x).abs()
#include "runtime/src/damping_law_kernel.h"
}  // namespace lanes_kernel

DampingLanes::DampingLanes(const std::array<const DampingModel*, kLanes>& models) : models_(models) {
  for (const DampingModel* m : models_)
    if (!m || m->disturbance_names() != models_[0]->disturbance_names())
      throw std::invalid_argument("DampingLanes: a missing damping model, or one reading other disturbances");
  // The same laws (but their coefficients) and lookups (but their numbers).
  const DampingModel& first = *models_[0];
  shared_ = true;
  for (const DampingModel* m : models_) {
    if (m->laws_.size() != first.laws_.size() || m->lookups_.size() != first.lookups_.size() ||
        m->derivatives_.size() != first.derivatives_.size())
      shared_ = false;
    // Derivative models: the same DOF and terms (they are evaluated lane by lane).
    for (std::size_t i = 0; shared_ && i < first.derivatives_.size(); ++i)
      shared_ =
          first.derivatives_[i].dof == m->derivatives_[i].dof && first.derivatives_[i].text == m->derivatives_[i].text;
    for (std::size_t i = 0; shared_ && i < first.laws_.size(); ++i) {
      const auto &a = first.laws_[i], &b = m->laws_[i];
      shared_ = a.dof == b.dof && a.variable == b.variable && a.count == b.count && a.terms == b.terms;
      // A term outside the enumeration: evaluate() says so, lane by lane.
      for (std::size_t k = 0; k < a.count; ++k) shared_ = shared_ && static_cast<std::size_t>(a.terms[k]) < 6;
    }
    for (std::size_t i = 0; shared_ && i < first.lookups_.size(); ++i) {
      const auto &a = first.lookups_[i], &b = m->lookups_[i];
      shared_ = a.axis_count == b.axis_count && a.source == b.source && a.used == b.used && a.output == b.output &&
                a.dof == b.dof && a.sign == b.sign && a.surface.output_count() == b.surface.output_count();
    }
  }
  if (!shared_) return;
  for (std::size_t i = 0; i < first.laws_.size(); ++i) {
    std::array<Lanes, 6> coefficients;
    for (Lanes& c : coefficients) c.setZero();
    for (std::size_t k = 0; k < first.laws_[i].count; ++k)
      for (std::size_t l = 0; l < models_.size(); ++l)
        coefficients[k][static_cast<Eigen::Index>(l)] = models_[l]->laws_[i].coefficients[k];
    law_coefficients_.push_back(coefficients);
  }
  for (std::size_t i = 0; i < first.lookups_.size(); ++i) {
    std::array<const GridTable*, kLanes> tables{};
    // One-axis tables without a symmetry (whose projection the table alone is not).
    const auto plain_grid = [](const CoefficientSurface& surface) {
      return surface.symmetry().empty() ? surface.grid() : nullptr;
    };
    bool together = first.lookups_[i].axis_count == 1 && plain_grid(first.lookups_[i].surface);
    for (std::size_t l = 0; l < models_.size(); ++l) {
      tables[l] = plain_grid(models_[l]->lookups_[i].surface);
      together = together && tables[l] && tables[l]->shares_axis(*first.lookups_[i].surface.grid());
    }
    if (!together) tables.fill(nullptr);
    tables_.push_back(tables);
  }
}

void DampingLanes::add(const Lanes* nu_r, std::span<const double> disturbances, Lanes* out) const {
  if (!shared_) {
    add_lane_by_lane(nu_r, disturbances, out);
    return;
  }
  // DampingModel::evaluate's sums, in its order, every lane at once.
  const DampingModel& first = *models_[0];
  Lanes tau[6];
  for (Lanes& t : tau) t.setZero();
  for (std::size_t i = 0; i < first.laws_.size(); ++i) {
    const auto& law = first.laws_[i];
    tau[law.dof] += lanes_kernel::hc_damping_law_value(law.codes.data(), law_coefficients_[i].data(), law.count,
                                                       &nu_r[law.variable]);
  }
  // Derivative models, lane by lane: DampingModel::add's numbers.
  for (std::size_t i = 0; i < first.derivatives_.size(); ++i)
    for (std::size_t l = 0; l < kLanes; ++l) {
      double lane_nu[6];
      for (std::size_t c = 0; c < 6; ++c) lane_nu[c] = nu_r[c][static_cast<Eigen::Index>(l)];
      tau[first.derivatives_[i].dof][static_cast<Eigen::Index>(l)] +=
          models_[l]->derivatives_[i].value(lane_nu, disturbances);
    }
  std::array<double, DampingModel::kMaxOutputs * kLanes> values;  // [output][lane]; written before read
  for (std::size_t i = 0; i < first.lookups_.size(); ++i) {
    const auto& lookup = first.lookups_[i];
    if (tables_[i][0]) {
      const std::size_t source = lookup.source[0];
      std::array<double, kLanes> point;
      for (std::size_t l = 0; l < point.size(); ++l)
        point[l] = source < 6 ? nu_r[source][static_cast<Eigen::Index>(l)] : disturbances[source - 6];
      GridTable::evaluate_one_axis_lanes<kLanes>(tables_[i], point.data(), values.data());
    } else {
      std::array<double, DampingModel::kMaxOutputs> lane_values;
      for (std::size_t l = 0; l < kLanes; ++l) {
        double lane_nu[6];
        for (std::size_t c = 0; c < 6; ++c) lane_nu[c] = nu_r[c][static_cast<Eigen::Index>(l)];
        DampingModel::look_up(models_[l]->lookups_[i], lane_nu, disturbances, lane_values.data());
        for (std::size_t k = 0; k < lookup.surface.output_count(); ++k) values[k * kLanes + l] = lane_values[k];
      }
    }
    for (std::size_t k = 0; k < lookup.used; ++k)
      tau[lookup.dof[k]] += lookup.sign[k] * Eigen::Map<const Lanes>(values.data() + lookup.output[k] * kLanes);
  }
  for (std::size_t i = 0; i < 6; ++i) out[i] += tau[i];
}

void DampingLanes::add_lane_by_lane(const Lanes* nu_r, std::span<const double> disturbances, Lanes* out) const {
  for (std::size_t l = 0; l < kLanes; ++l) {
    const auto lane = static_cast<Eigen::Index>(l);
    Vector6 v;
    for (Eigen::Index i = 0; i < 6; ++i) v[i] = nu_r[i][lane];
    const Vector6 d = models_[l]->evaluate(v, disturbances);
    for (Eigen::Index i = 0; i < 6; ++i) out[i][lane] += d[i];
  }
}

}  // namespace hydrocoef
