#include "src/plot/pmm_plot.hpp"

#include <cmath>

#include "src/core/run.hpp"
#include "src/pmm/imposed_motion.hpp"

namespace hydrocoef::plot {

Figure pmm_figure(const PmmRecord& record) {
  Figure figure;
  figure.title = "forced oscillation: " + std::string(dof_name(record.dof)) + " of " + record.body;
  Panel panel;
  const std::size_t i = record.dof;
  panel.title = std::string(kForceNames[i]) + " during " + std::string(dof_name(record.dof)) + " motion";
  panel.x_label = "t [s]";
  panel.y_label = std::string(kForceNames[i]) + (i < 3 ? " [N]" : " [N m]");
  Series cfd{"CFD", Series::Style::Line, 0, {}, {}, {}};
  Series fit{"harmonic fit", Series::Style::DashedLine, 1, {}, {}, {}};
  const PmmCoefficient* coefficient = nullptr;
  for (const auto& c : record.coefficients)
    if (c.component == i) coefficient = &c;
  for (std::size_t row = 0; row + kPmmHistoryColumns <= record.history.size(); row += kPmmHistoryColumns) {
    const double t = record.history[row];
    cfd.x.push_back(t);
    cfd.y.push_back(record.history[row + 1 + i]);
    if (!coefficient) continue;
    double f = coefficient->mean;
    const double phase = record.omega * t + record.phase;
    for (std::size_t k = 0; 2 * k + 1 < coefficient->harmonics.size(); ++k) {
      const double n = static_cast<double>(k + 1);
      f +=
          coefficient->harmonics[2 * k] * std::sin(n * phase) + coefficient->harmonics[2 * k + 1] * std::cos(n * phase);
    }
    fit.x.push_back(t);
    fit.y.push_back(f);
  }
  panel.series.push_back(std::move(cfd));
  if (coefficient) panel.series.push_back(std::move(fit));
  figure.panels.push_back(std::move(panel));
  return figure;
}

}  // namespace hydrocoef::plot
