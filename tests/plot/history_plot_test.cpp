// A run's force history figure from its stored statistics: a window mean
// draws its window, value, ± standard error, ± spread and trend at the
// numbers stored; a converged run its final iterate, ± iterative error and
// change per iteration; a run without a history is refused by name. Rendered
// by gnuplot, the plotted values are those numbers.
#include "src/plot/history_plot.hpp"

#include <gtest/gtest.h>

#include "src/core/error.hpp"
#include "tests/support/plot_data.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef::plot {
namespace {

StoredForce averaged(double value, StoredStatistics statistics) {
  StoredForce force;
  force.value.total = value;
  force.statistics = std::move(statistics);
  return force;
}

StoredRun transient_run() {
  StoredRun run;
  run.id = 7;
  run.key.body = "hull";
  run.key.nu_b[0] = 0.5;
  StoredStatistics st;
  st.abscissa = "time";
  st.window_method = "MSER-5 (White 1997)";
  st.window_first = 3.0;
  st.window_last = 9.0;
  st.samples = 1200;
  st.flags = {"drifting"};
  st.values = {0.01, 0.2, 0.06, 80.0};
  st.convergence = "transient-window";
  st.convergence_reason = "a transient run";
  run.tau_b[0] = averaged(2.0, st);
  StoredForce table;  // N from a table: no statistics, no panel
  table.value.total = -1.0;
  run.tau_b[5] = table;
  return run;
}

TEST(HistoryPlot, AWindowMeanDrawsTheStoredWindowValueErrorSpreadAndTrend) {
  const StoredRun run = transient_run();
  EXPECT_TRUE(has_history(run));
  const Figure figure = history_figure(run);
  EXPECT_NE(figure.title.find("run 7 (hull u=0.5), transient-window"), std::string::npos) << figure.title;
  EXPECT_NE(figure.title.find("samples are not stored"), std::string::npos);
  ASSERT_EQ(figure.panels.size(), 1u);  // X alone: N has no history
  const Panel& panel = figure.panels[0];
  EXPECT_EQ(panel.title, "X: mean over time 3 to 9 (MSER-5 (White 1997)); flags: drifting");
  EXPECT_EQ(panel.x_label, "time [s]");
  EXPECT_EQ(panel.y_label, "X [N] (on-body)");
  ASSERT_EQ(panel.shaded.size(), 1u);
  EXPECT_EQ(panel.shaded[0].x0, 3.0);
  EXPECT_EQ(panel.shaded[0].x1, 9.0);
  EXPECT_NE(panel.shaded_title.find("1200 samples"), std::string::npos);

  test::TempDir dir;
  const auto files = render(figure, dir / "history.svg", {600, 400});
  const auto blocks = test::read_plot_blocks(files.data);
  ASSERT_EQ(blocks.size(), 5u);
  using Rows = std::vector<std::vector<double>>;
  EXPECT_EQ(blocks[0].second, (Rows{{3.0, 1.99, 2.01}, {9.0, 1.99, 2.01}})) << blocks[0].first;  // ± standard error
  EXPECT_EQ(blocks[1].second, (Rows{{3.0, 2.0}, {9.0, 2.0}})) << blocks[1].first;                // the stored value
  EXPECT_EQ(blocks[2].second, (Rows{{3.0, 2.2}, {9.0, 2.2}})) << blocks[2].first;                // + spread
  EXPECT_EQ(blocks[3].second, (Rows{{3.0, 1.8}, {9.0, 1.8}})) << blocks[3].first;                // - spread
  EXPECT_EQ(blocks[4].second, (Rows{{3.0, 1.97}, {9.0, 2.03}})) << blocks[4].first;              // trend: drift 0.06
  EXPECT_NE(blocks[0].first.find("standard error 0.01 N"), std::string::npos) << blocks[0].first;
}

TEST(HistoryPlot, AConvergedRunDrawsItsFinalIterateAndIterativeError) {
  StoredRun run;
  run.id = 3;
  run.key.body = "sphere";
  StoredStatistics st;
  st.abscissa = "iteration";
  st.window_method = "final iterate";
  st.window_first = st.window_last = 145.0;
  st.samples = 1;
  st.values = {0.004, 0.001, 1e-5, 1.0};
  st.convergence = "converged";
  run.tau_b[4] = averaged(0.3, st);
  const Figure figure = history_figure(run);
  ASSERT_EQ(figure.panels.size(), 1u);
  const Panel& panel = figure.panels[0];
  EXPECT_EQ(panel.title, "M: final iterate at iteration 145");
  EXPECT_EQ(panel.y_label, "M [N m] (on-body)");
  EXPECT_TRUE(panel.shaded.empty());
  ASSERT_EQ(panel.series.size(), 3u);
  EXPECT_EQ(panel.series[0].style, Series::Style::Band);
  EXPECT_EQ(panel.series[0].y, (std::vector<double>{0.296, 0.296}));
  EXPECT_EQ(panel.series[0].y_high, (std::vector<double>{0.304, 0.304}));
  // The change per iteration leads to the final iterate over the 7.25
  // iterations drawn before it (5 % of 145).
  EXPECT_EQ(panel.series[1].x, (std::vector<double>{145.0 - 7.25, 145.0}));
  EXPECT_DOUBLE_EQ(panel.series[1].y[0], 0.3 - 7.25e-5);
  EXPECT_EQ(panel.series[2].style, Series::Style::Points);
  EXPECT_EQ(panel.series[2].x, (std::vector<double>{145.0}));
  EXPECT_EQ(panel.series[2].y, (std::vector<double>{0.3}));
  EXPECT_LT((*panel.x_range)[0], 145.0 - 7.25 + 1e-12);
  EXPECT_GT((*panel.x_range)[1], 145.0);
}

TEST(HistoryPlot, WithItsTraceTheWholeRecordIsDrawnAndTheRangeFitsTheWindow) {
  const StoredRun run = transient_run();
  // A record of 1000 samples in 256 bins; a start-up transient up to 50 N
  // before the window, values within 1.5..2.5 N from the window on.
  HistoryTrace trace;
  trace.abscissa_name = "time";
  trace.samples = 1000;
  for (std::size_t b = 0; b < HistoryTrace::kMaxBins; ++b) {
    const double t = 9.0 * static_cast<double>(b + 1) / 256.0;
    trace.abscissa.push_back(t);
    trace.low[0].push_back(t < 3.0 ? 40.0 : 1.5);
    trace.high[0].push_back(t < 3.0 ? 50.0 : 2.5);
  }
  const Figure figure = history_figure(run, trace);
  EXPECT_NE(figure.title.find("the history in brief"), std::string::npos) << figure.title;
  ASSERT_EQ(figure.panels.size(), 1u);
  const Panel& panel = figure.panels[0];
  ASSERT_FALSE(panel.series.empty());
  const Series& history = panel.series.front();
  EXPECT_EQ(history.style, Series::Style::Band);
  EXPECT_EQ(history.x, trace.abscissa);
  EXPECT_EQ(history.y, trace.low[0]);
  EXPECT_EQ(history.y_high, trace.high[0]);
  EXPECT_NE(history.title.find("bin of 3-4 samples"), std::string::npos) << history.title;
  // The whole record across, the window's values up and down (the transient leaves the panel).
  ASSERT_TRUE(panel.x_range && panel.y_range);
  EXPECT_EQ((*panel.x_range)[0], trace.abscissa.front());
  EXPECT_GE((*panel.x_range)[1], 9.0);
  EXPECT_LT((*panel.y_range)[0], 1.5);
  EXPECT_GT((*panel.y_range)[1], 2.5);
  EXPECT_LT((*panel.y_range)[1], 40.0);
  // Rendered: the band's rows are the trace's numbers.
  test::TempDir dir;
  const auto files = render(figure, dir / "history.svg", {600, 400});
  const auto blocks = test::read_plot_blocks(files.data);
  ASSERT_EQ(blocks.size(), 6u);
  ASSERT_EQ(blocks[0].second.size(), HistoryTrace::kMaxBins);
  EXPECT_EQ(blocks[0].second[100], (std::vector<double>{trace.abscissa[100], 1.5, 2.5}));
}

TEST(HistoryPlot, ARunWithoutAHistoryIsRefusedByName) {
  StoredRun run;
  run.id = 12;
  run.key.body = "hull";
  StoredForce table;
  table.value.total = 1.0;
  run.tau_b[0] = table;
  EXPECT_FALSE(has_history(run));
  try {
    history_figure(run);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("run 12: no force component is a mean over a force history"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace hydrocoef::plot
