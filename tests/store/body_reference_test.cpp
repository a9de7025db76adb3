// A body's reference data in the database (schema/0017_body_reference.sql):
// stored and read back to the bit with names of any shape (bound, never
// built into SQL), replaced as a whole, refused (nothing changed) for a body
// that is not there, a value that is not positive and finite or a default
// area that is not one of the body's, carried by merge and copy (a
// conflicting shard refused), refused on a database opened read-only with
// the file byte-identical, and a damaged row refused naming its table and
// row. Runs on both backends (tests/support/backend_under_test.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "src/store/body_reference.hpp"
#include "src/store/connection.hpp"
#include "src/store/database.hpp"
#include "src/store/migrations.hpp"
#include "tests/support/backend_under_test.hpp"
#include "tests/support/expect_input_error.hpp"
#include "tests/support/file_bytes.hpp"
#include "tests/support/import_batch.hpp"
#include "tests/support/sqlite_dump.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::database_display;
using test::database_location;
using test::expect_input_error;
using test::TempDir;

void add_body(RunDatabase& db, const std::string& body, int id = 1) {
  ImportedRun run;
  run.key.body = body;
  run.key.nu_b[0] = 0.1 * id;
  run.tau_b[0] = ForceComponent{-0.1, std::nullopt, std::nullopt};
  db.import({test::one_run_batch(id, run)}, ImportPolicy{});
}

BodyReferenceRecord sphere_reference() {
  BodyReferenceRecord r;
  r.body = "sphere";
  r.length = 0.3;
  r.areas = {{"frontal", 0.070685834705770348},
             {"L*d", 0.09},
             {"L^2", 0.09},
             {"quarter'); DROP TABLE body; --", 0.017671458676442587}};
  r.default_area = "frontal";
  r.draft = 0.15;
  r.displaced_volume = 0.014137166941154069;
  r.moment_point_b = std::array<double, 3>{0.01, -0.0, 1.0 / 3.0};
  return r;
}

TEST(BodyReferenceStore, StoredAndReadBackToTheBitAndReplacedAsAWhole) {
  TempDir dir;
  RunDatabase db(database_location(dir / "ref.db"));
  add_body(db, "sphere");
  add_body(db, "other", 2);
  EXPECT_TRUE(db.body_references().empty());
  const BodyReferenceRecord r = sphere_reference();
  db.save_body_reference(r);
  const auto back = db.body_references();
  ASSERT_EQ(back.size(), 1u);  // "other" has none
  EXPECT_TRUE(back[0].same_data(r));
  EXPECT_EQ(back[0].areas.at("quarter'); DROP TABLE body; --"), 0.017671458676442587);
  EXPECT_EQ(back[0].moment_point_b->at(2), 1.0 / 3.0);
  EXPECT_FALSE(std::signbit(back[0].moment_point_b->at(1)));  // -0 stored as 0
  EXPECT_EQ(back[0].updated_at.size(), 20u);                  // "2026-11-28T06:52:00Z"
  EXPECT_EQ(db.bodies(), (std::vector<std::string>{"other", "sphere"}));
  EXPECT_TRUE(db.body_references(std::string("other")).empty());

  // Saving again replaces the record whole: an area left out is gone, an
  // optional value left out is not given any more.
  BodyReferenceRecord fewer;
  fewer.body = "sphere";
  fewer.length = 0.31;
  fewer.areas = {{"wetted", 0.2827}};
  fewer.default_area = "wetted";
  db.save_body_reference(fewer);
  const auto again = db.body_references(std::string("sphere"));
  ASSERT_EQ(again.size(), 1u);
  EXPECT_TRUE(again[0].same_data(fewer));
  EXPECT_FALSE(again[0].draft);
  EXPECT_FALSE(again[0].moment_point_b);
}

TEST(BodyReferenceStore, BadRecordsAndUnknownBodiesAreRefusedChangingNothing) {
  TempDir dir;
  const auto path = dir / "ref.db";
  {
    RunDatabase db(database_location(path));
    add_body(db, "sphere");
    db.save_body_reference(sphere_reference());
  }
  const std::string before = test::dump_database(path);
  RunDatabase db(database_location(path));
  const auto refused = [&](BodyReferenceRecord r, const std::vector<std::string>& expected) {
    expect_input_error([&] { db.save_body_reference(r); }, expected);
    EXPECT_EQ(test::dump_database(path), before);
  };
  auto r = sphere_reference();
  r.body = "ghost";
  refused(r, {database_display(path), "no body named 'ghost'", "bodies: 'sphere'"});
  r = sphere_reference();
  r.length = -0.3;
  refused(r, {"body 'sphere'", "reference length is -0.3"});
  r = sphere_reference();
  r.areas["frontal"] = std::numeric_limits<double>::quiet_NaN();
  refused(r, {"area 'frontal' is nan"});
  r = sphere_reference();
  r.areas["side"] = 0.0;
  refused(r, {"area 'side' is 0"});
  r = sphere_reference();
  r.areas["bad\nname"] = 1.0;
  refused(r, {"the area name", "control or formatting character"});
  r = sphere_reference();
  r.default_area = "wetted";
  refused(r, {"default area 'wetted' is not one of the body's areas"});
  r = sphere_reference();
  r.displaced_volume = std::numeric_limits<double>::infinity();
  refused(r, {"displaced volume is inf"});
  r = sphere_reference();
  r.moment_point_b = std::array<double, 3>{0.0, std::numeric_limits<double>::quiet_NaN(), 0.0};
  refused(r, {"moment reference point"});
}

TEST(BodyReferenceStore, ADatabaseOpenedReadOnlyRefusesAndStaysByteIdentical) {
  HYDROCOEF_SQLITE_FILE_ONLY("the file's bytes");
  TempDir dir;
  const auto path = dir / "ref.db";
  {
    RunDatabase db(path);
    add_body(db, "sphere");
  }
  const std::string bytes = test::read_bytes(path);
  RunDatabase db(path, RunDatabase::OpenMode::ReadOnly);
  expect_input_error([&] { db.save_body_reference(sphere_reference()); }, {path.string(), "read-only"});
  EXPECT_TRUE(db.body_references().empty());
  EXPECT_EQ(test::read_bytes(path), bytes);
}

TEST(BodyReferenceStore, MergeAndCopyCarryItAndAConflictingShardIsRefused) {
  TempDir dir;
  {
    RunDatabase shard(database_location(dir / "shard.db"));
    add_body(shard, "sphere");
    shard.save_body_reference(sphere_reference());
  }
  RunDatabase merged(database_location(dir / "merged.db"));
  const auto outcome = merged.merge({database_location(dir / "shard.db")});
  ASSERT_EQ(outcome.size(), 1u);
  EXPECT_EQ(outcome[0].body_references_added, 1u);
  ASSERT_EQ(merged.body_references().size(), 1u);
  EXPECT_TRUE(merged.body_references()[0].same_data(sphere_reference()));
  // Merging the same shard again adds nothing.
  EXPECT_EQ(merged.merge({database_location(dir / "shard.db")})[0].body_references_already, 1u);

  RunDatabase copy(database_location(dir / "copy.db"));
  copy.copy_from(merged);
  ASSERT_EQ(copy.body_references().size(), 1u);
  EXPECT_TRUE(copy.body_references()[0].same_data(sphere_reference()));
  EXPECT_EQ(copy.body_references()[0].updated_at, merged.body_references()[0].updated_at);

  {
    RunDatabase other(database_location(dir / "other.db"));
    add_body(other, "sphere");
    auto r = sphere_reference();
    r.length = 0.31;
    other.save_body_reference(r);
  }
  const std::string before = test::dump_database(dir / "merged.db");
  expect_input_error([&] { merged.merge({database_location(dir / "other.db")}); },
                     {"body 'sphere' has reference data that differs"});
  EXPECT_EQ(test::dump_database(dir / "merged.db"), before);
}

TEST(BodyReferenceStore, ADamagedRowIsRefusedNamingItsTableAndRow) {
  TempDir dir;
  const auto path = dir / "ref.db";
  const auto refused = [&](const std::string& sql, const std::string& table, const std::string& expected) {
    SCOPED_TRACE(sql);
    {
      auto connection = test::connect_database(path);
      connection.execute("DELETE FROM body_reference_area; DELETE FROM body_reference");
    }
    std::int64_t id = 0;
    {
      RunDatabase db(database_location(path));
      db.save_body_reference(sphere_reference());
      auto connection = test::connect_database(path);
      auto row = connection.prepare("SELECT body_id FROM body_reference");
      ASSERT_TRUE(row.step());
      id = row.get_int(0);
    }
    test::connect_database(path).execute(sql);
    RunDatabase db(database_location(path), RunDatabase::OpenMode::ReadOnly);
    expect_input_error([&] { (void)db.body_references(); },
                       {"table '" + table + "', row " + std::to_string(id), expected});
  };
  {
    RunDatabase db(database_location(path));
    add_body(db, "sphere");
  }
  refused("UPDATE body_reference SET default_area = 'gone'", "body_reference", "default area 'gone'");
  refused("UPDATE body_reference SET default_area = ''", "body_reference", "default_area");
  if (!test::on_postgresql()) {  // PostgreSQL's columns are typed: no text where a number belongs
    refused("UPDATE body_reference SET moment_y = 'y'", "body_reference", "moment_y");
    refused("UPDATE body_reference SET reference_length = 'long'", "body_reference", "reference_length");
    refused("UPDATE body_reference_area SET area = 'big' WHERE name = 'L^2'", "body_reference_area", "area");
  }
}

TEST(BodyReferenceStore, ASchema16DatabaseIsMigrated) {
  HYDROCOEF_SQLITE_FILE_ONLY("an older SQLite file");
  TempDir dir;
  {
    store::Connection old((dir / "old.db").string(), store::Access::ReadWriteCreate);
    for (int i = 0; i < 16; ++i) old.execute(store::migrations()[static_cast<std::size_t>(i)].sql);
    old.execute("PRAGMA user_version = 16");
  }
  RunDatabase db(dir / "old.db");
  EXPECT_EQ(db.opened_at_version(), 16);
  EXPECT_EQ(db.schema_version(), RunDatabase::latest_schema_version());
  EXPECT_TRUE(db.body_references().empty());
}

}  // namespace
}  // namespace hydrocoef
