// The results schema version (storage_read/schema_version.hpp): a new file records kSchemaVersion; a
// version-1 file (the first deployed layout) is migrated by a read-write open and refused by a
// read-only one; a newer or unreadable version is refused without touching the file; every
// refusal names both versions.
#include "cyclopt/storage/result_store.hpp"
#include "cyclopt/storage_read/result_queries.hpp"
#include "cyclopt/storage_read/results_schema.hpp"
#include "cyclopt/storage_read/sqlite_handle.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include <unistd.h>

namespace cyclopt::storage {
namespace {

class SchemaVersionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("contract_schema_version_" + std::to_string(::getpid()) + "_" +
                                                     ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    path_ = (dir_ / "results.db").string();
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string version() {
    Connection c(path_, true);
    Statement q(c, "SELECT value FROM schema_info WHERE key = 'version'");
    return q.step() ? q.text(0) : "";
  }
  void set_version(const std::string& v) {
    Connection c(path_, false);
    Statement(c, "UPDATE schema_info SET value = ? WHERE key = 'version'").bind(1, std::string_view(v)).run();
  }
  // The error of opening the file with a ResultStore (read_write) or a ResultReader, "" if it opens.
  enum class OpenMode { read_write, read_only };
  std::string open_error(OpenMode mode) {
    try {
      if (mode == OpenMode::read_only)
        ResultReader r(path_);
      else
        ResultStore s(path_);
    } catch (const StorageError& e) {
      return e.what();
    }
    return "";
  }

  std::filesystem::path dir_;
  std::string path_;
};

TEST_F(SchemaVersionTest, ANewFileRecordsThisBuildsVersion) {
  { ResultStore s(path_); }
  EXPECT_EQ(version(), std::to_string(kSchemaVersion));
  EXPECT_EQ(open_error(OpenMode::read_only), "");
  EXPECT_EQ(open_error(OpenMode::read_write), "");
}

TEST_F(SchemaVersionTest, AVersionOneFileIsMigratedByAServerAndRefusedReadOnly) {
  {  // the first deployed layout: no sender, estimated_seconds, points_converged, required,
     // checkpoints, and no state 'incomplete'
    Connection c(path_, false);
    c.exec(R"sql(
CREATE TABLE schema_info (key TEXT PRIMARY KEY, value TEXT NOT NULL);
INSERT INTO schema_info (key, value) VALUES ('version', '1');
CREATE TABLE jobs (
  id INTEGER PRIMARY KEY, request_id TEXT NOT NULL UNIQUE, scene TEXT NOT NULL, task TEXT NOT NULL,
  spec_json TEXT NOT NULL,
  state TEXT NOT NULL DEFAULT 'queued' CHECK (state IN ('queued', 'running', 'done', 'failed', 'cancelled')),
  cancel_requested INTEGER NOT NULL DEFAULT 0, attempts INTEGER NOT NULL DEFAULT 0, submitted_at REAL NOT NULL,
  started_at REAL, finished_at REAL, points_total INTEGER, run_seconds REAL NOT NULL DEFAULT 0,
  publish_seconds REAL NOT NULL DEFAULT 0, error TEXT);
CREATE TABLE solutions (
  id INTEGER PRIMARY KEY, job_id INTEGER NOT NULL REFERENCES jobs (id), curve_index INTEGER NOT NULL,
  point_index INTEGER NOT NULL, parameter REAL, objective REAL, constraint_violation REAL, iterations INTEGER,
  status TEXT NOT NULL, values_json TEXT NOT NULL, solved_at REAL NOT NULL, UNIQUE (job_id, curve_index, point_index));
INSERT INTO jobs (request_id, scene, task, spec_json, state, submitted_at) VALUES ('old', 'walker', 'sweep', '{}', 'done', 1.0);
INSERT INTO solutions (job_id, curve_index, point_index, status, values_json, solved_at) VALUES (1, 0, 0, 'ok', '{}', 1.0);
)sql");
  }
  const std::string refused = open_error(OpenMode::read_only);
  EXPECT_NE(refused.find("schema version 1"), std::string::npos) << refused;
  EXPECT_NE(refused.find("version " + std::to_string(kSchemaVersion)), std::string::npos) << refused;
  EXPECT_EQ(version(), "1");
  {
    ResultStore s(path_);  // migrates
    EXPECT_EQ(s.job(1)->state, JobState::done);
    EXPECT_EQ(run_query(s, query_for("solutions", 1)).total, 1);
    const auto id = s.submit("new", "walker", "sweep", "{}").job_id;
    ASSERT_EQ(s.claim_next()->id, id);
    s.finish(id, JobState::incomplete, "speeds without a gait", 0.0, 0.0, 0);
    EXPECT_EQ(s.job(id)->state, JobState::incomplete);
  }
  EXPECT_EQ(version(), std::to_string(kSchemaVersion));
  EXPECT_EQ(open_error(OpenMode::read_only), "");
}

// Version 3 added what reproduces a job (jobs.program_version, seeds_json, resolved_spec_json): a
// version-2 file gets them, its jobs with '' (unknown), and new jobs store them.
TEST_F(SchemaVersionTest, AVersionTwoFileGetsTheReproducibilityColumns) {
  {
    ResultStore s(path_);
    s.submit("old", "walker", "optimise", "{}");
  }
  {  // back to the version-2 layout
    Connection c(path_, false);
    c.exec("ALTER TABLE jobs DROP COLUMN program_version");
    c.exec("ALTER TABLE jobs DROP COLUMN seeds_json");
    c.exec("ALTER TABLE jobs DROP COLUMN resolved_spec_json");
    c.exec("ALTER TABLE jobs DROP COLUMN isa_level");
    c.exec("ALTER TABLE jobs DROP COLUMN build_flags");
  }
  set_version("2");
  EXPECT_NE(open_error(OpenMode::read_only).find("schema version 2"), std::string::npos);
  {
    ResultStore s(path_);  // migrates
    const JobRecord old = *s.job(1);
    EXPECT_EQ(old.program_version, "");
    EXPECT_EQ(old.resolved_spec_json, "");
    EXPECT_EQ(old.seeds_json, "{}");
    const nlohmann::json row = run_query(s, query_for("job", 1)).rows.at(0);
    EXPECT_EQ(row["resolved_spec"], nullptr);
    EXPECT_EQ(row["seeds"], nlohmann::json::object());
    Submission sub{"new", "walker", "multistart", "{}", "", 0.0, "abc1234", R"({"multistart.seed": 3})", R"({"speed": 1})", "", ""};
    const auto id = s.submit(sub, SenderQuota{}).job_id;
    const JobRecord j = *s.job(id);
    EXPECT_EQ(j.program_version, "abc1234");
    EXPECT_EQ(j.seeds_json, R"({"multistart.seed": 3})");
    const nlohmann::json new_row = run_query(s, query_for("job", id)).rows.at(0);
    EXPECT_EQ(new_row["program_version"], "abc1234");
    EXPECT_EQ(new_row["seeds"], (nlohmann::json{{"multistart.seed", 3}}));
    EXPECT_EQ(new_row["resolved_spec"], (nlohmann::json{{"speed", 1}}));
  }
  EXPECT_EQ(version(), std::to_string(kSchemaVersion));
}

// Version 4 added the build's instruction-set level and flags (a job's results are reproducible by
// builds of its level): a version-3 file gets them empty, new jobs store them.
TEST_F(SchemaVersionTest, AVersionThreeFileGetsTheBuildColumns) {
  {
    ResultStore s(path_);
    s.submit("old", "walker", "optimise", "{}");
  }
  {
    Connection c(path_, false);
    c.exec("ALTER TABLE jobs DROP COLUMN isa_level");
    c.exec("ALTER TABLE jobs DROP COLUMN build_flags");
  }
  set_version("3");
  EXPECT_NE(open_error(OpenMode::read_only).find("schema version 3"), std::string::npos);
  {
    ResultStore s(path_);
    EXPECT_EQ(s.job(1)->isa_level, "");
    EXPECT_EQ(s.job(1)->build_flags, "");
    Submission sub{"new", "walker", "optimise", "{}", "", 0.0, "abc1234", "{}", "{}", "x86-64-v3", "GNU 12.2.0 -O3"};
    const auto id = s.submit(sub, SenderQuota{}).job_id;
    const nlohmann::json row = run_query(s, query_for("job", id)).rows.at(0);
    EXPECT_EQ(row["isa_level"], "x86-64-v3");
    EXPECT_EQ(row["build_flags"], "GNU 12.2.0 -O3");
  }
  EXPECT_EQ(version(), std::to_string(kSchemaVersion));
}

TEST_F(SchemaVersionTest, ANewerFileIsRefusedAndLeftAsItIs) {
  { ResultStore s(path_); }
  const std::string newer = std::to_string(kSchemaVersion + 1);
  set_version(newer);
  for (OpenMode mode : {OpenMode::read_write, OpenMode::read_only}) {
    const std::string e = open_error(mode);
    EXPECT_NE(e.find("schema version " + newer + ", newer than this build's " + std::to_string(kSchemaVersion)),
              std::string::npos)
        << e;
  }
  EXPECT_EQ(version(), newer);
}

TEST_F(SchemaVersionTest, AnUnreadableVersionIsRefused) {
  { ResultStore s(path_); }
  set_version("two");
  const std::string e = open_error(OpenMode::read_write);
  EXPECT_NE(e.find("schema_info.version is 'two'"), std::string::npos) << e;
  EXPECT_EQ(version(), "two");
}

}  // namespace
}  // namespace cyclopt::storage
