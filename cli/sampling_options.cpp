// The Monte Carlo options and terminal progress of simulate and equilibrium
// (cli/sampling_options.hpp).
#include "cli/sampling_options.hpp"

#include <unistd.h>

#include <cstdio>
#include <memory>

namespace hydrocoef::cli {
namespace {

constexpr auto kProgressInterval = std::chrono::milliseconds(200);

}  // namespace

void add_sampling_options(CLI::App* command, SamplingOptions& sampling, const char* default_percentiles) {
  command->add_option("--samples", sampling.samples,
                      "Monte Carlo: draw the uncertain damping N times (laws from their covariance, GP surfaces from "
                      "their posterior; one draw per run, not per step) and report percentiles");
  command->add_option("--seed", sampling.seed, "Seed of the draws (the same seed gives the same draws)")
      ->capture_default_str();
  command
      ->add_option(
          "--percentiles", sampling.percentiles,
          std::string("Percentiles to report, comma-separated, increasing (default ") + default_percentiles + ")")
      ->delimiter(',');
  command->add_option("--threads", sampling.threads, "Threads for the draws (0: one per core)")->capture_default_str();
}

std::function<void(std::size_t, std::size_t)> draw_progress() {
  if (isatty(STDERR_FILENO) == 0) return {};
  auto last = std::make_shared<std::chrono::steady_clock::time_point>();
  return [last](std::size_t done, std::size_t total) {
    const auto now = std::chrono::steady_clock::now();
    if (now - *last < kProgressInterval && done < total) return;
    *last = now;
    std::fprintf(stderr, "\rsampling: %zu of %zu draws%s", done, total, done == total ? "\n" : "");
  };
}

TerminalProgress::TerminalProgress(std::string what)
    : what_(std::move(what)), tty_(isatty(STDERR_FILENO) != 0), last_(std::chrono::steady_clock::now()) {}

std::function<void(double, double)> TerminalProgress::time_callback() {
  if (!tty_) return {};
  return [this](double t, double duration) {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < kProgressInterval && t < duration) return;
    last_ = now;
    printed_ = true;
    std::fprintf(stderr, "\r%s: t = %.1f of %.1f s (%3.0f %%)", what_.c_str(), t, duration, 100.0 * t / duration);
  };
}

void TerminalProgress::finish() {
  if (printed_) std::fprintf(stderr, "\n");
}

}  // namespace hydrocoef::cli
