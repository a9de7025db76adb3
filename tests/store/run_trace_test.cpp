// A run's force history in brief (schema/0016_run_force_trace.sql): written
// with the run's history import, read back to the bit, carried by merge and
// copy, taken away with the run or by a component written without a history,
// and a damaged one refused naming its table and row.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "src/store/connection.hpp"
#include "src/store/database.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/import_batch.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;
using test::TempDir;

HistoryTrace make_trace(std::size_t samples) {
  HistoryTrace trace;
  trace.abscissa_name = "iteration";
  trace.samples = samples;
  const std::size_t bins = std::min(samples, HistoryTrace::kMaxBins);
  for (std::size_t b = 0; b < bins; ++b) {
    const double i = static_cast<double>(b + 1);
    trace.abscissa.push_back(i * 7.0);
    trace.low[0].push_back(-1.0 - std::exp(-i / 30.0));
    trace.high[0].push_back(-1.0 + std::exp(-i / 30.0) / 3.0);
    trace.low[5].push_back(0.01 * std::sin(i));
    trace.high[5].push_back(0.01 * std::sin(i) + 1e-4);
  }
  return trace;
}

ImportedRun averaged_run(double u, std::optional<HistoryTrace> trace) {
  ImportedRun run;
  run.key.body = "ball";
  run.key.nu_b[0] = u;
  run.tau_b[0] = ForceComponent{-1.0, std::nullopt, std::nullopt};
  run.tau_b[5] = ForceComponent{0.001, std::nullopt, std::nullopt};
  RunStatistics statistics;
  statistics.abscissa = "iteration";
  statistics.convergence = "steady-window";
  for (const std::size_t c : {std::size_t{0}, std::size_t{5}}) {
    statistics.components[c] = ComponentStatistics{0.001, 0.01, 0.0, 100.0};
    statistics.windows[c] = ComponentWindow{"MSER-5", 1000.0, 1792.0, 400, {}};
  }
  run.statistics = statistics;
  run.trace = std::move(trace);
  return run;
}

void expect_same(const HistoryTrace& a, const HistoryTrace& b) {
  EXPECT_EQ(a.abscissa_name, b.abscissa_name);
  EXPECT_EQ(a.samples, b.samples);
  EXPECT_EQ(a.abscissa, b.abscissa);
  for (std::size_t c = 0; c < 6; ++c) {
    EXPECT_EQ(a.low[c], b.low[c]) << c;
    EXPECT_EQ(a.high[c], b.high[c]) << c;
  }
}

std::int64_t only_run(RunDatabase& database) {
  const auto runs = database.runs();
  EXPECT_EQ(runs.size(), 1u);
  return runs.empty() ? 0 : runs.front().id;
}

TEST(RunTrace, ReadsBackToTheBitAndTravelsWithMergeAndCopy) {
  TempDir dir;
  const HistoryTrace trace = make_trace(2000);
  {
    RunDatabase shard(dir / "shard.db");
    shard.import({test::one_run_batch(1, averaged_run(0.2, trace))}, ImportPolicy{});
    const auto stored = shard.run_trace(only_run(shard));
    ASSERT_TRUE(stored);
    expect_same(*stored, trace);
  }
  RunDatabase merged(dir / "merged.db");
  merged.merge({(dir / "shard.db").string()});
  const auto after_merge = merged.run_trace(only_run(merged));
  ASSERT_TRUE(after_merge);
  expect_same(*after_merge, trace);
  RunDatabase copy(dir / "copy.db");
  copy.copy_from(merged);
  const auto after_copy = copy.run_trace(only_run(copy));
  ASSERT_TRUE(after_copy);
  expect_same(*after_copy, trace);
  // Deleting the run takes its trace with it.
  copy.delete_runs({only_run(copy)});
  store::Connection raw((dir / "copy.db").string(), store::Access::ReadWrite);
  auto rows = raw.prepare("SELECT count(*) FROM run_force_trace");
  ASSERT_TRUE(rows.step());
  EXPECT_EQ(rows.get_int(0), 0);
}

TEST(RunTrace, AComponentWrittenWithoutAHistoryTakesTheTraceAway) {
  TempDir dir;
  RunDatabase database(dir / "runs.db");
  database.import({test::one_run_batch(1, averaged_run(0.2, make_trace(100)))}, ImportPolicy{});
  const std::int64_t id = only_run(database);
  ASSERT_TRUE(database.run_trace(id));
  // Y of the same run from a table: the history no longer tells the run's story.
  ImportedRun table;
  table.key.body = "ball";
  table.key.nu_b[0] = 0.2;
  table.tau_b[1] = ForceComponent{0.0, std::nullopt, std::nullopt};
  database.import({test::one_run_batch(2, table)}, ImportPolicy{});
  EXPECT_FALSE(database.run_trace(id));
  // A run from a table never has one.
  database.import({test::one_run_batch(3,
                                       [] {
                                         ImportedRun r;
                                         r.key.body = "ball";
                                         r.key.nu_b[0] = 0.4;
                                         r.tau_b[0] = ForceComponent{-2.0, std::nullopt, std::nullopt};
                                         return r;
                                       }())},
                  ImportPolicy{});
  for (const auto& run : database.runs())
    if (run.key.nu_b[0] == 0.4) EXPECT_FALSE(database.run_trace(run.id));
}

TEST(RunTrace, ADamagedTraceIsRefusedNamingItsTableAndRow) {
  TempDir dir;
  const auto refused = [&](const std::string& sql, const std::string& expected) {
    SCOPED_TRACE(sql);
    std::filesystem::remove(dir / "runs.db");
    std::int64_t id = 0;
    {
      RunDatabase database(dir / "runs.db");
      database.import({test::one_run_batch(1, averaged_run(0.2, make_trace(300)))}, ImportPolicy{});
      id = only_run(database);
    }
    {
      store::Connection raw((dir / "runs.db").string(), store::Access::ReadWrite);
      raw.execute(sql);
    }
    RunDatabase database(dir / "runs.db", RunDatabase::OpenMode::ReadOnly);
    expect_input_error([&] { (void)database.run_trace(id); },
                       {"table 'run_force_trace', row " + std::to_string(id), expected});
  };
  refused("UPDATE run_force_trace SET data = substr(data, 1, 800)", "float64 values");
  refused("UPDATE run_force_trace SET components = 'X,X'", "distinct force components");
  refused("UPDATE run_force_trace SET components = 'X,N', samples = 100", "float64 values");
  refused("UPDATE run_force_trace SET data = zeroblob(8 * 256 * 5)", "increasing");
}

}  // namespace
}  // namespace hydrocoef
