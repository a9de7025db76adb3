// Test support: every write path of the store (import, import --replace,
// runs delete, fit, surface, gci, pmm and derivative-model store and delete,
// body reference data, merge of a shard, copy into an empty database) run
// against a database with content while a fault injector makes the N-th I/O
// call or allocation fail, for N = 1, 2, 3, ... until the operation runs
// through without meeting the fault: SQLite's own
// habit (its ioerr and malloc tests). After each failure the database must
// pass PRAGMA integrity_check and hold exactly what it held before; after a
// reported success, exactly what the operation writes without a fault. A
// failure must be an InputError of one line (exit 2), never another type
// (the CLI's "internal error").
#pragma once

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "src/core/error.hpp"
#include "src/pipeline/grid_convergence_runs.hpp"
#include "src/store/body_reference.hpp"
#include "src/store/database.hpp"
#include "src/store/derivative_store.hpp"
#include "src/store/pmm_record.hpp"
#include "tests/support/import_batch.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef::test {

namespace write_paths {

inline ImportedRun sphere_run(double u, double x, double n) {
  ImportedRun run;
  run.key.body = "sphere";
  run.key.nu_b[0] = u;
  run.fluid.density_kg_m3 = 998.2;
  run.tau_b[0] = ForceComponent{x, 0.8 * x, 0.2 * x, std::nullopt};
  run.tau_b[5] = ForceComponent{n, std::nullopt, std::nullopt, 0.01};
  run.source_line = 2;
  return run;
}

inline ImportedRun mesh_run(double mesh, double cell_size, double x) {
  ImportedRun run;
  run.key.body = "hull";
  run.key.nu_b[0] = 0.2;
  run.key.disturbances = {{"mesh", mesh}, {"cell_size", cell_size}};
  run.tau_b[0] = ForceComponent{x, std::nullopt, std::nullopt, 0.03};
  return run;
}

/// A batch of several sphere runs from one made-up file (`id` makes its hash).
inline ImportBatch sphere_batch(int id, double offset, int runs) {
  std::vector<ImportedRun> list;
  for (int i = 0; i < runs; ++i) {
    const double u = 0.1 * (i + 1) + offset;
    list.push_back(sphere_run(u, -3.0 * u * u - 0.5 * u, 0.25 * u));
  }
  ImportBatch batch = one_run_batch(id, list.front());
  batch.runs = list;
  return batch;
}

inline FitRecord sphere_fit(RunDatabase& db, const std::string& name) {
  FitRecord fit;
  fit.name = name;
  fit.body = "sphere";
  fit.dof = "X";
  fit.variable = "u";
  fit.terms = "u,u|u|";
  fit.loss = "squared";
  fit.sign = SignConvention::OpposingMotion;
  fit.rmse = 0.5;
  fit.r2 = 0.9;
  fit.coefficients = {{"u", 0.5, 0.1}, {"u|u|", 3.0, std::nullopt}};
  fit.covariance = {0.01, 0.0, 0.0, 0.02};
  for (const auto& run : db.runs(RunFilter{std::string("sphere"), {}, std::nullopt})) fit.run_ids.push_back(run.id);
  fit.n = fit.run_ids.size();
  return fit;
}

inline DerivativeModelRecord sphere_derivatives(RunDatabase& db, double rmse) {
  DerivativeModelRecord m;
  m.name = "sphere:X(u, u*|u|)";
  m.body = "sphere";
  m.output = "X";
  m.terms = "u, u*|u|";
  m.rmse = rmse;
  m.condition_number = 3.0;
  m.interval_factor = 2.1;
  m.covariance = {0.01, 0.0, 0.0, 0.02};
  m.warnings = {{"unweighted", "only some runs state an uncertainty"}};
  m.coefficients = {{"u", -0.5, 0.1, -0.7, -0.3, 1.5}, {"u*|u|", -3.0, std::nullopt, std::nullopt, std::nullopt, 1.5}};
  for (const auto& run : db.runs(RunFilter{std::string("sphere"), {}, std::nullopt})) m.run_ids.push_back(run.id);
  m.n = m.run_ids.size();
  return m;
}

inline SurfaceRecord sphere_surface(RunDatabase& db, double scale) {
  SurfaceRecord s;
  s.name = "sphere-X";
  s.body = "sphere";
  s.kind = "grid";
  s.method = "pchip";
  s.definition = R"({"axes":[{"name":"u","breakpoints":[0,0.1,0.2]}],"outputs":["X"]})";
  s.data = {0.0, -0.1 * scale, -0.45 * scale};
  s.quality = R"({"X":{"loo_max":0.01,"loo_rms":0.004}})";
  for (const auto& run : db.runs(RunFilter{std::string("sphere"), {}, std::nullopt})) s.run_ids.push_back(run.id);
  return s;
}

inline PmmRecord pmm_record(double amplitude, double damping) {
  PmmRecord r;
  r.body = "ball";
  r.nu_b = {0.1, 0, 0, 0, 0, 0};
  r.dof = 5;
  r.amplitude = amplitude;
  r.omega = 3.25;
  r.medium = PmmMedium::StillWater;
  r.motion_source = "case/constant/dynamicMeshDict:7";
  r.window_start = 1.5;
  r.window_end = 9.25;
  r.periods = 4;
  r.transient_periods = 1;
  r.samples = 800;
  r.harmonics = 1;
  r.size = 0.3;
  r.rho = 998.2;
  r.source_path = "case";
  r.source_sha256 = std::string(64, 'a');
  r.importer = "openfoam-forces 1";
  r.history = {1.5, 1, 2, 3, 4, 5, 6, 1.6, 1.1, 2.1, 3.1, 4.1, 5.1, 6.1};
  PmmCoefficient n;
  n.component = 5;
  n.added_mass = 0.125;
  n.damping = damping;
  n.explained = 0.999;
  n.harmonics = {0.1, 0.2};
  r.coefficients = {n};
  return r;
}

inline std::vector<NumericalUncertaintyRecord> mesh_study(RunDatabase& db) {
  GridConvergenceRequest request;
  request.body = "hull";
  return numerical_uncertainty_records(grid_convergence_of_runs(db, request));
}

/// The database every write path starts from: runs of two bodies from
/// several imports, a fit, a surface and a forced-oscillation analysis.
inline void fill(const std::filesystem::path& path) {
  RunDatabase db(path);
  db.import({sphere_batch(1, 0.0, 4)}, ConflictPolicy::Error);
  db.import({sphere_batch(2, 0.05, 3)}, ConflictPolicy::Error);
  db.import({one_run_batch(3, mesh_run(1, 0.01, -2.0))}, ConflictPolicy::Error);
  db.import({one_run_batch(4, mesh_run(2, 0.02, -2.1))}, ConflictPolicy::Error);
  db.import({one_run_batch(5, mesh_run(3, 0.04, -2.5))}, ConflictPolicy::Error);
  db.save_fit(sphere_fit(db, "sphere:X"));
  db.save_surface(sphere_surface(db, 1.0));
  db.save_pmm({pmm_record(0.2, 0.5)});
  db.save_derivative_model(sphere_derivatives(db, 0.5));
}

/// A shard as a cluster job makes it: runs new to the database, one run
/// it has, a fit of its own.
inline void fill_shard(const std::filesystem::path& path) {
  RunDatabase db(path);
  db.import({sphere_batch(1, 0.0, 4)}, ConflictPolicy::Error);
  db.import({sphere_batch(7, 1.0, 3)}, ConflictPolicy::Error);
  db.save_fit(sphere_fit(db, "sphere:X-shard"));
}

}  // namespace write_paths

/// One write path: `run` writes into `db` (opened on runs.db in `dir`,
/// which holds shard.db and source.db too).
struct WritePath {
  std::string name;
  std::function<void(RunDatabase& db, const std::filesystem::path& dir)> run;
  bool into_empty = false;  ///< runs.db starts empty (copy), else with write_paths::fill's content
  std::string reads;        ///< the other database it reads ("shard.db", "source.db"), which must not change
};

inline std::vector<WritePath> store_write_paths() {
  using namespace write_paths;
  return {
      {"import",
       [](RunDatabase& db, const std::filesystem::path&) {
         // New runs, and runs of the database that gain a component.
         ImportBatch batch = sphere_batch(10, 0.5, 3);
         ImportedRun extended = sphere_run(0.1, 0, 0);
         extended.tau_b = {};
         extended.tau_b[1] = ForceComponent{0.01, std::nullopt, std::nullopt, std::nullopt};
         batch.runs.push_back(extended);
         db.import({batch}, ConflictPolicy::Error);
       }},
      {"import_replace",
       [](RunDatabase& db, const std::filesystem::path&) {
         ImportBatch batch = sphere_batch(1, 0.0, 4);
         batch.source.settings_key = "id=1;rho=1025";
         for (auto& run : batch.runs) run.fluid.density_kg_m3 = 1025.0;
         ImportPolicy options;
         options.replace = true;
         db.import({batch}, options);
       }},
      {"runs_delete",
       [](RunDatabase& db, const std::filesystem::path&) {
         const auto runs = db.runs(RunFilter{std::string("sphere"), {}, std::nullopt});
         db.delete_runs({runs.at(0).id, runs.at(1).id});
       }},
      {"fit_save",
       [](RunDatabase& db, const std::filesystem::path&) {
         FitRecord fit = sphere_fit(db, "sphere:X");
         fit.rmse = 0.25;
         db.save_fit(fit, RunDatabase::NameTaken::Replace);
       }},
      {"surface_save", [](RunDatabase& db, const std::filesystem::path&) { db.save_surface(sphere_surface(db, 2.0)); }},
      {"gci_store",
       [](RunDatabase& db, const std::filesystem::path&) { db.save_numerical_uncertainties(mesh_study(db)); }},
      {"pmm_store",
       [](RunDatabase& db, const std::filesystem::path&) {
         db.save_pmm({pmm_record(0.2, 0.75), pmm_record(0.4, 0.5)});
       }},
      {"body_reference_set",
       [](RunDatabase& db, const std::filesystem::path&) {
         BodyReferenceRecord reference;
         reference.body = "sphere";
         reference.length = 0.3;
         reference.areas = {{"frontal", 0.0706858}, {"L^2", 0.09}};
         reference.default_area = "frontal";
         reference.moment_point_b = std::array<double, 3>{0.0, 0.0, 0.01};
         db.save_body_reference(reference);
       }},
      {"derivatives_save",
       [](RunDatabase& db, const std::filesystem::path&) {
         db.save_derivative_model(sphere_derivatives(db, 0.25), RunDatabase::NameTaken::Replace);
       }},
      {"derivatives_delete",
       [](RunDatabase& db, const std::filesystem::path&) { db.delete_derivative_model("sphere:X(u, u*|u|)"); }},
      {"merge", [](RunDatabase& db, const std::filesystem::path& dir) { db.merge({(dir / "shard.db").string()}); },
       false, "shard.db"},
      {"copy",
       [](RunDatabase& db, const std::filesystem::path& dir) {
         RunDatabase source(dir / "source.db", RunDatabase::OpenMode::ReadOnly);
         db.copy_from(source);
       },
       true, "source.db"},
  };
}

/// gtest prints a write path by its name.
inline void PrintTo(const WritePath& path, std::ostream* out) { *out << path.name; }

/// Dump text with every UTC timestamp ("2031-01-02T03:04:05Z") replaced: a
/// row written twice a second apart is the same row.
inline std::string without_timestamps(std::string text) {
  const std::string shape = "dddd-dd-ddTdd:dd:ddZ";
  for (std::size_t i = 0; i + shape.size() <= text.size(); ++i) {
    bool match = true;
    for (std::size_t k = 0; k < shape.size() && match; ++k) {
      const char c = text[i + k];
      match = shape[k] == 'd' ? std::isdigit(static_cast<unsigned char>(c)) != 0 : c == shape[k];
    }
    if (match) text.replace(i, shape.size(), "<time>");
  }
  return text;
}

/// The logical content of a database file: its user version, schema and
/// every row of every table (sorted), each value with its type, doubles
/// exactly and blobs in hex; timestamps left out (without_timestamps).
inline std::string content_of(const std::filesystem::path& path) {
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
    sqlite3_close(db);
    return "cannot open " + path.string();
  }
  const auto rows_of = [&](const std::string& sql) {
    std::vector<std::string> rows;
    sqlite3_stmt* statement = nullptr;
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &statement, nullptr) != SQLITE_OK)
      return std::vector<std::string>{std::string("cannot read: ") + sqlite3_errmsg(db)};
    int rc = SQLITE_ROW;
    while ((rc = sqlite3_step(statement)) == SQLITE_ROW) {
      std::string row;
      for (int c = 0; c < sqlite3_column_count(statement); ++c) {
        char number[40];
        switch (sqlite3_column_type(statement, c)) {
          case SQLITE_NULL: row += "NULL"; break;
          case SQLITE_INTEGER: row += std::to_string(sqlite3_column_int64(statement, c)); break;
          case SQLITE_FLOAT:
            std::snprintf(number, sizeof number, "%.17g", sqlite3_column_double(statement, c));
            row += number;
            break;
          case SQLITE_TEXT:
            row += "'" + std::string(reinterpret_cast<const char*>(sqlite3_column_text(statement, c))) + "'";
            break;
          default: {
            const auto* bytes = static_cast<const unsigned char*>(sqlite3_column_blob(statement, c));
            row += "x'";
            for (int i = 0; i < sqlite3_column_bytes(statement, c); ++i) {
              std::snprintf(number, sizeof number, "%02x", bytes[i]);
              row += number;
            }
            row += "'";
          }
        }
        row += "|";
      }
      rows.push_back(std::move(row));
    }
    if (rc != SQLITE_DONE) rows.push_back(std::string("cannot read: ") + sqlite3_errmsg(db));
    sqlite3_finalize(statement);
    return rows;
  };
  std::string out = "user_version=" + rows_of("PRAGMA user_version").at(0) + "\n";
  for (const auto& row : rows_of("SELECT type, name, sql FROM sqlite_schema ORDER BY type, name")) out += row + "\n";
  for (const auto& table : rows_of("SELECT name FROM sqlite_schema WHERE type = 'table' ORDER BY name")) {
    const std::string name = table.substr(1, table.size() - 3);  // 'name'|
    auto rows = rows_of("SELECT * FROM \"" + name + "\"");
    std::sort(rows.begin(), rows.end());
    out += "== " + name + "\n";
    for (const auto& row : rows) out += row + "\n";
  }
  sqlite3_close(db);
  return without_timestamps(out);
}

/// The first line where two contents differ, for messages.
inline std::string first_difference(const std::string& a, const std::string& b) {
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
    if (a[i] != b[i]) {
      const auto end_a = a.find('\n', i), end_b = b.find('\n', i);
      return "'" + a.substr(line_start, end_a - line_start).substr(0, 200) + "' against '" +
             b.substr(line_start, end_b - line_start).substr(0, 200) + "'";
    }
    if (a[i] == '\n') line_start = i + 1;
  }
  return a.size() == b.size() ? "none" : "one ends before the other";
}

/// PRAGMA integrity_check through a connection of its own that may write
/// (it rolls back a hot journal or replays a WAL left behind).
inline std::string integrity_of(const std::filesystem::path& path) {
  sqlite3* db = nullptr;
  std::string out;
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) != SQLITE_OK) {
    out = std::string("cannot open: ") + (db ? sqlite3_errmsg(db) : "no handle");
    sqlite3_close(db);
    return out;
  }
  sqlite3_stmt* statement = nullptr;
  if (sqlite3_prepare_v2(db, "PRAGMA integrity_check", -1, &statement, nullptr) != SQLITE_OK) {
    out = std::string("cannot check: ") + sqlite3_errmsg(db);
  } else {
    int rc = SQLITE_ROW;
    while ((rc = sqlite3_step(statement)) == SQLITE_ROW)
      out += (out.empty() ? "" : "; ") + std::string(reinterpret_cast<const char*>(sqlite3_column_text(statement, 0)));
    if (rc != SQLITE_DONE) out += std::string("; step: ") + sqlite3_errmsg(db);
  }
  sqlite3_finalize(statement);
  sqlite3_close(db);
  return out;
}

/// What the store says when a commit failed after it may have reached the disk.
inline constexpr const char* kCommitMayHaveStored = "the write may or may not have been stored";

/// How a test makes faults: arm the N-th counted event (1-based) to fail
/// (N = 0: count events, fail none), disarm, and say how many events were
/// counted and how many failed since armed (hits is asked once after each N).
struct FaultSwitch {
  std::function<void(long n)> arm;
  std::function<void()> disarm;
  std::function<long()> calls;
  std::function<long()> hits;
  std::function<std::string()> first_fault;  ///< where the first fault was (for messages)
};

/// What a fault loop saw.
struct FaultLoopResult {
  long events = 0;                      ///< the operation's events without a fault
  long stride = 1;                      ///< N went up by this much
  long iterations = 0;                  ///< values of N tried
  long failures = 0;                    ///< of those, the operation threw
  long faults = 0;                      ///< events failed, over all N
  long uncertain_commits = 0;           ///< failures at COMMIT that said the write may have been stored
  long uncertain_commits_stored = 0;    ///< of those, the write was stored
  std::map<std::string, int> messages;  ///< the distinct error messages (160 characters from the file name on)
};

/// The database files of a write path, made once per test: runs.db as it
/// starts (with content, or empty for a copy), shard.db and source.db.
class WritePathFiles {
 public:
  /// `journal_mode`: the mode runs.db is left in ("wal", as hydrocoef
  /// leaves it, or "delete", as an older tool may).
  WritePathFiles(const WritePath& path, const std::string& journal_mode) {
    write_paths::fill(templates_ / "source.db");
    write_paths::fill_shard(templates_ / "shard.db");
    if (path.into_empty) {
      RunDatabase empty(templates_ / "runs.db");
    } else {
      std::filesystem::copy_file(templates_ / "source.db", templates_ / "runs.db");
    }
    sqlite3* db = nullptr;
    sqlite3_open_v2((templates_ / "runs.db").c_str(), &db, SQLITE_OPEN_READWRITE, nullptr);
    const std::string pragma = "PRAGMA journal_mode = " + journal_mode;
    const int rc = sqlite3_exec(db, pragma.c_str(), nullptr, nullptr, nullptr);
    sqlite3_close(db);
    if (rc != SQLITE_OK) throw std::runtime_error("cannot set the journal mode");
    for (const auto* name : {"runs.db", "shard.db", "source.db"}) {
      if (std::filesystem::exists(templates_ / (std::string(name) + "-wal")))
        throw std::runtime_error(std::string(name) + " was left with a WAL");
      before_[name] = content_of(templates_ / name);
    }
  }

  /// A fresh copy of the files in `dir` (emptied first).
  void copy_to(const std::filesystem::path& dir) const {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    for (const auto* name : {"runs.db", "shard.db", "source.db"})
      std::filesystem::copy_file(templates_ / name, dir / name);
  }
  const std::string& before(const std::string& name) const { return before_.at(name); }

 private:
  TempDir templates_;
  std::map<std::string, std::string> before_;
};

/// Runs `path` once counting its events (`faults`' I/O calls or
/// allocations, from the moment the database is open to the moment it is
/// closed), then with the N-th event failing for N = 1, 1 + stride, ... and
/// last for N one past the count, where it must run through without meeting
/// the fault; the stride keeps the values of N tried to `most_iterations`.
/// The database is checked after each.
inline FaultLoopResult run_fault_loop(const WritePath& path, const std::string& journal_mode, const FaultSwitch& faults,
                                      long most_iterations) {
  WritePathFiles files(path, journal_mode);
  TempDir work;
  const auto dir = work / "work";
  const auto runs_db = dir / "runs.db";
  FaultLoopResult result;

  // Without a fault: what the operation writes, and how many events it has.
  files.copy_to(dir);
  {
    std::optional<RunDatabase> db;
    db.emplace(runs_db, RunDatabase::OpenMode::MustExist);
    faults.arm(0);
    path.run(*db, dir);
    db.reset();
    faults.disarm();
    result.events = faults.calls();
  }
  const std::string after = content_of(runs_db);
  if (after == files.before("runs.db")) ADD_FAILURE() << path.name << " wrote nothing: the loop would prove nothing";
  EXPECT_GT(result.events, 0) << path.name << ": no event counted";
  result.stride = std::max(1L, (result.events + most_iterations - 1) / most_iterations);

  for (long n = 1;; n = n > result.events ? n + 1 : std::min(n + result.stride, result.events + 1)) {
    if (n > result.events + 20) {
      ADD_FAILURE() << path.name << ": still meeting faults at N=" << n << ", past its " << result.events << " events";
      break;
    }
    files.copy_to(dir);
    bool threw = false;
    std::string last_message;
    {
      std::optional<RunDatabase> db;
      db.emplace(runs_db, RunDatabase::OpenMode::MustExist);
      faults.arm(n);
      try {
        path.run(*db, dir);
      } catch (const InputError& e) {
        threw = true;
        const std::string message = e.what();
        last_message = message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "N=" << n << ": not one line: " << message;
        EXPECT_FALSE(message.empty()) << "N=" << n;
        // Messages begin with the database's path, a folder of its own each test.
        const auto slash = message.rfind('/', message.find(".db: "));
        ++result.messages[message.substr(slash == std::string::npos ? 0 : slash + 1, 160)];
      } catch (const std::exception& e) {
        threw = true;
        last_message = e.what();
        ADD_FAILURE() << path.name << " N=" << n << ": not an InputError (the CLI's internal error): " << e.what();
      }
      db.reset();  // closing (a checkpoint of the WAL) meets the faults too
      faults.disarm();
    }
    const long hits = faults.hits();
    ++result.iterations;
    result.faults += hits;
    if (threw) ++result.failures;

    const std::string where = path.name + " (" + journal_mode + ") N=" + std::to_string(n) +
                              (threw ? ", failed (" + last_message + ")" : ", succeeded") + " after " +
                              std::to_string(hits) + " faults" + (hits ? ", the first at " + faults.first_fault() : "");
    EXPECT_FALSE(threw && hits == 0) << where << ": failed without a fault";
    EXPECT_EQ(integrity_of(runs_db), "ok") << where;
    const std::string now = content_of(runs_db);
    // A commit the disk failed may have reached it (src/store/sqlite_backend.cpp
    // fail_commit): the store must say so, and the database hold the write
    // whole or not at all.
    const bool commit_uncertain = threw && last_message.find(kCommitMayHaveStored) != std::string::npos;
    if (commit_uncertain) ++result.uncertain_commits;
    if (commit_uncertain && now == after) {
      ++result.uncertain_commits_stored;
    } else if (threw && now != files.before("runs.db")) {
      ADD_FAILURE() << where << ": a failed write changed the database"
                    << (now == after ? " (it holds the write: committed, yet reported as failed)"
                                     : "; first difference " + first_difference(now, files.before("runs.db")));
    }
    if (!threw && now != after)
      ADD_FAILURE() << where << ": a write that succeeded did not leave what it writes; first difference "
                    << first_difference(now, after);
    if (!path.reads.empty() && content_of(dir / path.reads) != files.before(path.reads))
      ADD_FAILURE() << where << ": " << path.reads << ", which it only reads, changed";
    try {
      RunDatabase reopened(runs_db, RunDatabase::OpenMode::MustExist);
    } catch (const std::exception& e) {
      ADD_FAILURE() << where << ": the store refuses the database: " << e.what();
    }
    if (::testing::Test::HasFailure()) break;   // the first N that fails says it all
    if (hits == 0 && n > result.events) break;  // ran through: N is past the operation's last event
  }
  return result;
}

}  // namespace hydrocoef::test
