// Monte Carlo draws of a vehicle's damping: what `simulate --samples` and
// `equilibrium --samples` run. A draw is a whole DampingModel in which every
// uncertain part is replaced by one sample of its distribution and held for
// the whole trajectory or equilibrium: the coefficients are uncertain, not
// the water, so this is a per-trajectory parameter draw, never per-step noise.
//
//   - A damping law with a covariance Sigma (stored with its fit, or given in
//     the vehicle file): c = c_hat + F z, z ~ N(0, I), F F^T = Sigma
//     (F = P^T L D^1/2 from the pivoted LDL^T of Sigma, so a semi-definite
//     Sigma, e.g. of a coefficient that is known exactly, works too).
//   - A derivative model of several variables with a covariance (given in
//     the vehicle file): the same, over all its coefficients at once.
//   - A Gaussian-process surface: one function drawn from its posterior.
//     The posterior is drawn jointly at the nodes of a grid over the
//     surface's range (mean m and covariance K from GpSurface::posterior;
//     f = m + F z with F F^T = K as above) and a natural cubic spline passes
//     through those nodes. The nodes are evenly spaced: at least 17 per axis
//     and a spacing of at most a sixteenth of the output's shortest length
//     scale (the spline's error is then a few thousandths of the draw's own
//     variation, so a draw passes through a noise-free run to that), within
//     a budget of kMaxNodes nodes (a note says when the budget makes it
//     coarser). Outputs are independent processes and are drawn
//     independently; outputs the vehicle does not read are held at the mean.
//     Outside the range the draw follows the surface's policy: error, clamp,
//     or (extrapolate) linear continuation of the drawn spline.
//   - Laws and derivative models without a covariance and surfaces without
//     a posterior (grid and RBF surfaces: their standard deviation is
//     pointwise, with no joint distribution of functions to draw from) are
//     held at their values;
//     held() lists them, so that a band never looks narrower than it is
//     without saying so.
//
// Draw i of seed s comes from its own generator (std::mt19937_64 seeded with
// s and i), so a set of draws does not depend on the number of threads or
// on the order they run in. Built once and immutable; draw() is const and
// thread-safe.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "src/dynamics/damping.hpp"

namespace hydrocoef {

class DampingDraws {
 public:
  /// The most grid nodes a GP surface's draw is made on (its posterior
  /// covariance is kMaxNodes^2 numbers per output read).
  static constexpr std::size_t kMaxNodes = 1024;

  /// Prepares the draws of `nominal`, built from `spec` (the covariances of
  /// the laws are read from there). InputError naming the DOF for a law's
  /// covariance that is not one.
  DampingDraws(const DampingModel& nominal, const DampingSpec& spec);

  /// What is drawn and what is held, one line each, e.g.
  /// "N: law 1,r,r|r| drawn from its covariance".
  const std::vector<std::string>& drawn() const noexcept { return drawn_; }
  const std::vector<std::string>& held() const noexcept { return held_; }
  /// Things a user should know about the draws (a coarse grid).
  const std::vector<std::string>& notes() const noexcept { return notes_; }
  /// True when there is something to draw.
  bool any() const noexcept { return !drawn_.empty(); }

  /// Draw `index` of the sequence `seed`.
  DampingModel draw(std::uint64_t seed, std::uint64_t index) const;

 private:
  /// mean + factor * z, z standard normal.
  struct Gaussian {
    Eigen::VectorXd mean;
    Eigen::MatrixXd factor;
  };
  struct LawDraw {
    std::size_t law = 0;    // index into DampingModel::laws_
    Gaussian coefficients;  // on the body
  };
  struct SurfaceDraw {
    std::size_t lookup = 0;  // index into DampingModel::lookups_
    std::vector<GridAxis> axes;
    std::vector<std::string> outputs;
    std::size_t nodes = 0;
    /// Per surface output: its Gaussian at the nodes, or an empty factor
    /// for an output held at its mean (mean only).
    std::vector<Gaussian> output;
  };

  static Gaussian gaussian(Eigen::VectorXd mean, const Eigen::MatrixXd& covariance);

  DampingModel nominal_;
  std::vector<LawDraw> laws_;
  std::vector<LawDraw> derivatives_;  // law: index into DampingModel::derivatives_
  std::vector<SurfaceDraw> surfaces_;
  std::vector<std::string> drawn_, held_, notes_;
};

}  // namespace hydrocoef
