#include "src/dynamics/ensemble.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <numbers>

#include "src/core/error.hpp"
#include "src/core/numbers.hpp"
#include "src/core/parallel.hpp"
#include "src/dynamics/simulation.hpp"

namespace hydrocoef {
namespace {

constexpr std::size_t kQuantities = 12;
constexpr std::array<std::string_view, kQuantities> kQuantityNames = {"x_n", "y_n", "z_n", "phi", "theta", "psi",
                                                                      "u",   "v",   "w",   "p",   "q",     "r"};
constexpr std::array<std::string_view, kQuantities> kQuantityUnits = {
    "m", "m", "m", "rad", "rad", "rad", "m s^-1", "m s^-1", "m s^-1", "rad s^-1", "rad s^-1", "rad s^-1"};
/// Failure messages kept per ensemble.
constexpr std::size_t kKeptFailures = 5;

/// Records draw failures from any thread.
class FailureLog {
 public:
  void add(std::size_t draw, const std::string& message) {
    const std::lock_guard<std::mutex> lock(mutex_);
    ++count_;
    messages_.emplace_back(draw, message);
  }
  EnsembleFailures result() {
    std::sort(messages_.begin(), messages_.end());
    EnsembleFailures out;
    out.count = count_;
    for (std::size_t i = 0; i < messages_.size() && i < kKeptFailures; ++i)
      out.first.push_back("draw " + std::to_string(messages_[i].first) + ": " + messages_[i].second);
    return out;
  }

 private:
  std::mutex mutex_;
  std::size_t count_ = 0;
  std::vector<std::pair<std::size_t, std::string>> messages_;
};

/// Calls progress one at a time.
class ProgressCounter {
 public:
  ProgressCounter(const EnsembleProgress& progress, std::size_t total) : progress_(progress), total_(total) {}
  void done() {
    const std::size_t n = ++done_;
    if (!progress_) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    progress_(n, total_);
  }

 private:
  const EnsembleProgress& progress_;
  std::size_t total_;
  std::atomic<std::size_t> done_{0};
  std::mutex mutex_;
};

/// Runs body(i, drawn model) for every draw i on options.threads threads;
/// a draw whose body throws InputError is recorded as failed. Draws go in
/// batches of `batch_size`: batch(first, count) may do draws first ..
/// first + count - 1 at once and return true, or return false (or throw
/// InputError) to leave them to body one by one. Returns which draws
/// succeeded and the failures.
template <typename Body, typename Batch>
std::vector<char> run_draws(const VehicleModel& model, const DampingDraws& draws, const EnsembleOptions& options,
                            const EnsembleProgress& progress, EnsembleFailures& failed, std::size_t batch_size,
                            Body&& body, Batch&& batch) {
  const std::size_t n = options.samples;
  std::vector<char> ok(n, 0);
  FailureLog failures;
  ProgressCounter counter(progress, n);
  parallel_for((n + batch_size - 1) / batch_size, options.threads, [&](std::size_t b) {
    const std::size_t first = b * batch_size, count = std::min(batch_size, n - first);
    bool done = false;
    try {
      done = batch(first, count);
    } catch (const InputError&) {}
    for (std::size_t i = first; i < first + count; ++i) {
      if (!done) {
        try {
          body(i, model.with_damping(draws.draw(options.seed, i)));
          ok[i] = 1;
        } catch (const InputError& e) {
          failures.add(i, e.what());
        }
      } else {
        ok[i] = 1;
      }
      counter.done();
    }
  });
  failed = failures.result();
  return ok;
}

/// Draw i's output samples into data: position, Euler angles (unwrapped in
/// time below) and velocity at output time k.
class TrajectoryStore {
 public:
  TrajectoryStore(std::vector<double>& data, std::size_t times) : data_(data), times_(times) {}
  /// Draw i at output time k.
  void put(std::size_t i, std::size_t k, const Vector3& p_n, const Vector3& euler_rad, const Vector6& nu_b) {
    double* out = data_.data() + i * kQuantities * times_;
    for (std::size_t a = 0; a < 3; ++a) {
      out[a * times_ + k] = p_n[static_cast<Eigen::Index>(a)];
      out[(3 + a) * times_ + k] = euler_rad[static_cast<Eigen::Index>(a)];
    }
    for (std::size_t a = 0; a < 6; ++a) out[(6 + a) * times_ + k] = nu_b[static_cast<Eigen::Index>(a)];
  }
  /// Draw i at output time k from its state, as make_sample reports it.
  void put(std::size_t i, std::size_t k, const StateVector& x) {
    put(i, k, position_n(x), euler_from_quaternion(unit_attitude(attitude_nb(x))), velocity_b(x));
  }
  /// Unwraps draw i's Euler angles in time.
  void unwrap(std::size_t i) {
    double* out = data_.data() + i * kQuantities * times_;
    for (std::size_t a = 3; a < 6; ++a) {
      double* angle = out + a * times_;
      double turns = 0.0;
      for (std::size_t k = 1; k < times_; ++k) {
        const double raw = angle[k] + turns;
        const double step = raw - angle[k - 1];
        if (step > std::numbers::pi) turns -= 2.0 * std::numbers::pi;
        if (step < -std::numbers::pi) turns += 2.0 * std::numbers::pi;
        angle[k] += turns;
      }
    }
  }

 private:
  std::vector<double>& data_;
  std::size_t times_;
};

[[noreturn]] void all_failed(const char* what, EnsembleFailures failures) {
  throw InputError("every one of the " + std::to_string(failures.count) + " draws failed to " + what + "; the first, " +
                   (failures.first.empty() ? std::string("?") : failures.first.front()));
}

}  // namespace

void check_ensemble_options(const EnsembleOptions& options) {
  if (options.samples < 2 || options.samples > 10'000'000)
    throw InputError("--samples " + std::to_string(options.samples) + ": expected 2 to 10000000 draws");
  if (options.percentiles.empty()) throw InputError("--percentiles: expected at least one percentile");
  for (std::size_t i = 0; i < options.percentiles.size(); ++i) {
    const double p = options.percentiles[i];
    if (!(p > 0.0 && p < 100.0))
      throw InputError("--percentiles: found " + shortest_number(p) + ", expected percentiles in (0, 100)");
    if (i > 0 && !(p > options.percentiles[i - 1]))
      throw InputError("--percentiles: found " + shortest_number(p) + " after " +
                       shortest_number(options.percentiles[i - 1]) + ", expected increasing percentiles");
  }
}

double percentile_of_sorted(std::span<const double> sorted, double p) {
  const double rank = p / 100.0 * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(rank));
  if (below + 1 >= sorted.size()) return sorted.back();
  const double fraction = rank - static_cast<double>(below);
  return sorted[below] + fraction * (sorted[below + 1] - sorted[below]);
}

TrajectoryBands simulate_samples(const VehicleModel& model, const DampingDraws& draws, const Scenario& scenario,
                                 const EnsembleOptions& options, const EnsembleProgress& progress) {
  check_ensemble_options(options);
  // The nominal model's run fixes the output times (every draw has the same
  // ones) and checks the scenario before any draw starts.
  const SimulationResult nominal = simulate_model(model, scenario);
  const std::size_t times = nominal.samples.size();
  const std::size_t n = options.samples;
  const double total = static_cast<double>(n) * static_cast<double>(times) * static_cast<double>(kQuantities);
  if (!(total <= kMaxEnsembleValues))
    throw InputError(SourceLocation{scenario.file},
                     "key 'output_rate': " + std::to_string(n) + " draws of " + std::to_string(times) +
                         " output samples are " + shortest_number(total) +
                         " numbers; expected at most 6.4e7 (fewer draws, a lower output_rate or a shorter duration)");

  // All trajectories, draw-major: data[(draw * kQuantities + q) * times + k].
  std::vector<double> data(n * kQuantities * times);
  TrajectoryStore store(data, times);
  const auto one = [&](std::size_t i, const VehicleModel& drawn) {
    const SimulationResult r = simulate_model(drawn, scenario);
    if (r.samples.size() != times) throw std::logic_error("simulate_samples: a draw with other output times");
    for (std::size_t k = 0; k < times; ++k)
      store.put(i, k, r.samples[k].p_n, r.samples[k].euler_rad, r.samples[k].nu_b);
    store.unwrap(i);
  };
  // RK4: motion::kLanes draws at once (simulate_lanes), the same numbers;
  // when there are enough of them to keep every thread busy with batches.
  constexpr auto kBatch = static_cast<std::size_t>(motion::kLanes);
  const bool lanes = scenario.integrator.method == IntegratorSettings::Method::Rk4 &&
                     n >= kBatch * parallel_threads(n, options.threads);
  const auto batch = [&](std::size_t first, std::size_t count) {
    if (!lanes) return false;
    std::array<DampingModel, motion::kLanes> drawn;
    std::array<const DampingModel*, motion::kLanes> lane_damping{};
    for (std::size_t l = 0; l < drawn.size(); ++l) {
      // A short last batch fills its lanes with its last draw.
      drawn[l] = draws.draw(options.seed, first + std::min(l, count - 1));
      lane_damping[l] = &drawn[l];
    }
    const LaneSimulation r = simulate_lanes(model, lane_damping, scenario);
    if (r.states.size() != times) throw std::logic_error("simulate_samples: lanes with other output times");
    for (std::size_t l = 0; l < count; ++l) {
      for (std::size_t k = 0; k < times; ++k) store.put(first + l, k, r.states[k].col(static_cast<Eigen::Index>(l)));
      store.unwrap(first + l);
    }
    return true;
  };
  EnsembleFailures failures;
  const std::vector<char> ok = run_draws(model, draws, options, progress, failures, lanes ? kBatch : 1, one, batch);

  TrajectoryBands bands;
  bands.failures = failures;
  for (const char good : ok) bands.samples += good ? 1 : 0;
  if (bands.samples == 0) all_failed("reach the end of the scenario", bands.failures);
  for (const auto& s : nominal.samples) bands.t_s.push_back(s.t_s);
  for (std::size_t q = 0; q < kQuantities; ++q) {
    bands.quantities.emplace_back(kQuantityNames[q]);
    bands.units.emplace_back(kQuantityUnits[q]);
  }
  bands.percentiles = options.percentiles;
  const std::size_t p_count = bands.percentiles.size();
  bands.values.assign(kQuantities * p_count * times, 0.0);
  parallel_for(kQuantities * times, options.threads, [&](std::size_t job, unsigned) {
    const std::size_t q = job / times, k = job % times;
    std::vector<double> column;
    column.reserve(bands.samples);
    for (std::size_t i = 0; i < n; ++i)
      if (ok[i]) column.push_back(data[(i * kQuantities + q) * times + k]);
    std::sort(column.begin(), column.end());
    for (std::size_t j = 0; j < p_count; ++j)
      bands.values[(q * p_count + j) * times + k] = percentile_of_sorted(column, bands.percentiles[j]);
  });
  return bands;
}

double share_inside_band(const TrajectoryBands& bands, std::string_view quantity, std::span<const double> t_s,
                         std::span<const double> values) {
  const std::size_t q = bands.quantity_index(quantity);
  const std::size_t lowest = 0, highest = bands.percentiles.size() - 1;
  if (bands.percentiles.size() < 2 || bands.t_s.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  std::size_t inside = 0, counted = 0;
  for (std::size_t i = 0; i < t_s.size() && i < values.size(); ++i) {
    const double t = t_s[i];
    if (t < bands.t_s.front() || t > bands.t_s.back()) continue;
    auto upper = std::upper_bound(bands.t_s.begin(), bands.t_s.end(), t);
    if (upper == bands.t_s.end()) --upper;
    const auto k = static_cast<std::size_t>(upper - bands.t_s.begin());
    const double t0 = bands.t_s[k - 1], t1 = bands.t_s[k];
    const double f = t1 > t0 ? (t - t0) / (t1 - t0) : 0.0;
    auto at = [&](std::size_t j) { return (1.0 - f) * bands.value(q, j, k - 1) + f * bands.value(q, j, k); };
    ++counted;
    if (values[i] >= at(lowest) && values[i] <= at(highest)) ++inside;
  }
  return counted == 0 ? std::numeric_limits<double>::quiet_NaN()
                      : static_cast<double>(inside) / static_cast<double>(counted);
}

EquilibriumSamples solve_equilibrium_samples(const VehicleModel& model, const DampingDraws& draws,
                                             const EquilibriumInputs& inputs, const EnsembleOptions& options,
                                             const EnsembleProgress& progress) {
  check_ensemble_options(options);
  const std::size_t n = options.samples;
  std::vector<Vector6> nu(n, Vector6::Zero());
  EnsembleFailures failures;
  const std::vector<char> ok = run_draws(
      model, draws, options, progress, failures, 1,
      [&](std::size_t i, const VehicleModel& drawn) {
        const EquilibriumResult r = solve_equilibrium(drawn, inputs);
        if (!r.converged) {
          std::size_t worst = 0;
          r.residual_b.cwiseAbs().maxCoeff(&worst);
          throw InputError("no steady state: the residual stays at " +
                           shortest_number(r.residual_b[static_cast<Eigen::Index>(worst)]) + " in " +
                           std::string(1, "XYZKMN"[worst]));
        }
        nu[i] = r.nu_b;
      },
      [](std::size_t, std::size_t) { return false; });

  EquilibriumSamples out;
  out.failures = failures;
  std::vector<Vector6> good;
  for (std::size_t i = 0; i < n; ++i)
    if (ok[i]) good.push_back(nu[i]);
  out.samples = good.size();
  if (good.empty()) all_failed("reach an equilibrium", out.failures);
  for (const Vector6& v : good) out.mean += v;
  out.mean /= static_cast<double>(good.size());
  if (good.size() > 1) {
    for (const Vector6& v : good) out.standard_deviation += (v - out.mean).cwiseAbs2();
    out.standard_deviation = (out.standard_deviation / static_cast<double>(good.size() - 1)).cwiseSqrt();
  }
  out.percentiles = options.percentiles;
  out.percentile_values.assign(out.percentiles.size(), Vector6::Zero());
  std::vector<double> column(good.size());
  for (Eigen::Index dof = 0; dof < 6; ++dof) {
    for (std::size_t i = 0; i < good.size(); ++i) column[i] = good[i][dof];
    std::sort(column.begin(), column.end());
    for (std::size_t j = 0; j < out.percentiles.size(); ++j)
      out.percentile_values[j][dof] = percentile_of_sorted(column, out.percentiles[j]);
  }
  return out;
}

}  // namespace hydrocoef
