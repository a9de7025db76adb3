// The Monte Carlo options of simulate and equilibrium (--samples, --seed,
// --percentiles, --threads) and the progress lines they print on a terminal.
#pragma once

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>

#include "hydrocoef/simulation.hpp"

namespace hydrocoef::cli {

/// Adds --samples, --seed, --percentiles (its help naming `default_percentiles`) and --threads.
void add_sampling_options(CLI::App* command, SamplingOptions& sampling, const char* default_percentiles);

/// "sampling: 350 of 1000 draws" on stderr when it is a terminal, at most
/// five times a second; empty (no output) otherwise.
std::function<void(std::size_t done, std::size_t total)> draw_progress();

/// "simulating: t = 3.0 of 10.0 s ( 30 %)" on stderr when it is a terminal,
/// at most five times a second; finish() ends the line if one was printed.
class TerminalProgress {
 public:
  explicit TerminalProgress(std::string what);
  /// The callback to give the simulation (empty when stderr is not a terminal).
  std::function<void(double t_s, double duration_s)> time_callback();
  void finish();

 private:
  std::string what_;
  bool tty_ = false;
  bool printed_ = false;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace hydrocoef::cli
