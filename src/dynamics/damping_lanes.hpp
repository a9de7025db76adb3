// The damping of motion::kLanes vehicles integrated in lock-step (the drawn
// models of an ensemble, simulate_lanes). When the models share their shape,
// as the draws of one model do (the same laws with other coefficients, the
// same lookups with other numbers on the same axes), the laws are evaluated
// for every lane at once (derivative models of several variables lane by
// lane within that path) and one-axis tables on a shared axis are looked up
// together; otherwise lane by lane. Either way lane l's numbers are
// models[l]->evaluate()'s, bit for bit.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "src/dynamics/damping.hpp"
#include "src/dynamics/motion_terms.hpp"

namespace hydrocoef {

class DampingLanes {
 public:
  /// The models (non-null, kept by pointer: they must outlive this) must read
  /// the same disturbances; std::invalid_argument otherwise.
  explicit DampingLanes(const std::array<const DampingModel*, motion::kLanes>& models);

  /// True when the models share their shape (evaluated lanes at once).
  bool shared() const noexcept { return shared_; }

  /// out (6 per lane) += lane l's damping force on the body at its velocity
  /// relative to the water nu_r (6 per lane), with the disturbance values
  /// (disturbance_names() order). Throws InputError where a lane's
  /// DampingModel::evaluate would (a lookup outside its surface under policy
  /// "error"), with the message of lane 0's surface for a shared table.
  /// Allocates nothing for laws and shared one-axis tables (other surfaces as
  /// their evaluate()).
  void add(const motion::Lanes* nu_r, std::span<const double> disturbances, motion::Lanes* out) const;

 private:
  void add_lane_by_lane(const motion::Lanes* nu_r, std::span<const double> disturbances, motion::Lanes* out) const;

  std::array<const DampingModel*, motion::kLanes> models_;
  bool shared_ = false;
  // Shared shape: per law, each term's coefficient in every lane.
  std::vector<std::array<motion::Lanes, 6>> law_coefficients_;
  // Shared shape: per lookup, every lane's one-axis table on one axis (or all
  // null: looked up lane by lane).
  std::vector<std::array<const GridTable*, motion::kLanes>> tables_;
};

}  // namespace hydrocoef
