// proto/schemas/job.schema.json against the server's validator (issue 14 item 6): every job spec
// of the README, of the guides in docs/ and of the shell scripts (tests/service/*.sh, deploy/run-main-job.sh) is valid
// under the schema and accepted by the server, specs the server refuses are refused by the schema
// at the same field, and the schema's enums and per-task fields are the server's. The C++ validator is the truth: the
// schema may accept more (it cannot count a start vector's length), never less. The schema is the
// one the build embeds (service/job_schema.hpp), which clients check specs against.
#include "spec_snippets.hpp"

#include "cyclopt/jobs/builtin_job_kinds.hpp"
#include "cyclopt/service/job_schema.hpp"
#include "cyclopt/service/job_spec.hpp"
#include "cyclopt/service/resolved_spec.hpp"
#include "cyclopt/service/stored_references.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>

#include <unistd.h>

namespace cyclopt::testing {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

const fs::path kSource = CYCLOPT_SOURCE_DIR;

using service::job_schema;
using service::JsonSchemaValidator;

const service::JobKindRegistry& registry() {
  static const service::JobKindRegistry r = jobs::builtin_job_kinds();
  return r;
}

// The server's verdict: "" when it accepts `spec`, else its error. A "start" naming a stored point
// is checked for its form only (the server resolves it from its database, stored_start.hpp).
std::string server_error(const json& spec) {
  try {
    service::validate_job_spec(service::without_stored_start(spec), registry());
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += "\n  " + l;
  return s;
}

// Every snippet must be a spec the server accepts and the schema too.
void expect_valid_specs(const std::vector<SpecSnippet>& snippets) {
  for (const SpecSnippet& s : snippets) {
    json spec;
    try {
      spec = json::parse(s.text);
    } catch (const json::exception& e) {
      ADD_FAILURE() << s.where << ": not JSON (" << e.what() << "):\n" << s.text;
      continue;
    }
    EXPECT_EQ(server_error(spec), "") << s.where << ": the server refuses " << s.text;
    const auto errors = job_schema().errors(spec);
    EXPECT_TRUE(errors.empty()) << s.where << ": the schema refuses " << s.text << joined(errors);
    if (!server_error(spec).empty()) continue;
    // Its resolved spec (service/resolved_spec.hpp) is a spec to submit again: valid as well.
    const json resolved =
        service::resolved_spec(service::validate_job_spec(service::without_stored_start(spec), registry()));
    EXPECT_EQ(server_error(resolved), "") << s.where << ": the server refuses the resolved " << resolved.dump();
    const auto resolved_errors = job_schema().errors(resolved);
    EXPECT_TRUE(resolved_errors.empty()) << s.where << ": the schema refuses the resolved " << resolved.dump()
                                         << joined(resolved_errors);
  }
}

TEST(JobSchema, TheDocumentationsExamplesAreValid) {
  std::vector<SpecSnippet> snippets = spec_snippets(kSource / "README.md");
  for (const auto& entry : fs::directory_iterator(kSource / "docs"))
    if (entry.path().extension() == ".md")
      for (SpecSnippet& s : spec_snippets(entry.path())) snippets.push_back(std::move(s));
  EXPECT_GE(snippets.size(), 8u) << "README.md and docs/: fewer job-spec examples than the 8 there were when this "
                                     "test was written";
  expect_valid_specs(snippets);
}

TEST(JobSchema, TheShellScriptsSpecsAreValid) {
  // Values for the scripts' expansions (their own defaults where they have one); a script that
  // adds an expansion fails below with a '$' left in its spec until it is listed here.
  const std::map<std::string, std::string> values = {
      {"%d", "10"},          {"$FOOT_JSON", "\"P2-shoes-left-HMT\""}, {"$FOOT", "P2-shoes-left-HMT"},
      {"$SPEEDS", "0.8:0.1:1.4"}, {"$SEED_SPEED", "1.2"}, {"$COMPARISON", "1"}, {"$STARTS", "4"}};
  std::vector<fs::path> scripts = {kSource / "deploy/run-main-job.sh"};
  for (const auto& entry : fs::directory_iterator(kSource / "tests/service"))
    if (entry.path().extension() == ".sh") scripts.push_back(entry.path());
  std::size_t count = 0;
  for (const fs::path& script : scripts) {
    std::vector<SpecSnippet> snippets = spec_snippets(script);
    for (SpecSnippet& s : snippets) {
      s.text = expand(s.text, values);
      EXPECT_EQ(s.text.find('$'), std::string::npos) << s.where << ": an expansion without a value in this test: " << s.text;
    }
    count += snippets.size();
    expect_valid_specs(snippets);
  }
  EXPECT_GE(count, 9u) << "fewer script specs than the 9 there were when this test was written";
}

json spec(const std::string& text) { return json::parse(text); }

TEST(JobSchema, RefusesWhatTheServerRefuses) {
  // Each invalid in one field; the schema's error names it as the server's does.
  const std::vector<std::pair<std::string, std::string>> invalid = {
      {R"({"task": "optimise", "foot": "point", "speed": 1.0})", "requires \"scene\""},
      {R"({"scene": "robot", "task": "optimise", "foot": "point", "speed": 1.0})", "/scene"},
      {R"({"scene": "walker", "task": "walk", "foot": "point", "speed": 1.0})", "/task"},
      {R"({"scene": "walker", "task": "optimise", "foot": "point", "speed": 1.0, "colour": "red"})", "/colour"},
      {R"({"scene": "walker", "task": "optimise", "foot": "point", "speed": 9})", "/speed"},
      {R"({"scene": "walker", "task": "optimise", "foot": "point"})", "requires \"speed\""},
      {R"({"scene": "walker", "task": "optimise", "foot": "point", "speed": 1.0, "objective": "energy"})", "/objective"},
      {R"({"scene": "walker", "task": "optimise", "foot": "point", "speed": 1.0, "solver": {"max_iterations": 0}})",
       "/solver/max_iterations"},
      {R"({"scene": "walker", "task": "optimise", "foot": "point", "speed": 1.0, "limits": {"max_wall_seconds": 0}})",
       "/limits/max_wall_seconds"},
      {R"({"scene": "walker", "task": "optimise", "foot": "point", "speed": 1.0, "speeds": "0.3:0.1:2.3"})", "/speeds"},
      {R"({"scene": "walker", "task": "multistart", "foot": "point", "speed": 1.0, "multistart": {"tries": 3}})",
       "/multistart/tries"},
      {R"({"scene": "walker", "task": "foot_sweep", "foot": {"model": "HM", "h_F": 0.05}, "sweep": {"parameter": "density", "values": 5}})",
       "/foot"},
      {R"({"scene": "walker", "task": "foot_sweep", "foot": "P2-shoes-left-HMT"})", "requires \"sweep\""},
      {R"({"scene": "walker", "task": "foot_sweep", "foot": "P2-shoes-left-HMT", "sweep": {"parameter": "density", "values": "1:2"}})",
       "/sweep/values"},
      {R"({"scene": "walker", "task": "foot_comparison", "speeds": "0.3:0.1:2.3", "foot": "point"})", "/foot"},
      {R"({"scene": "walker", "task": "foot_comparison", "speeds": "0.3:0.1:2.3", "continuation": {"parameter": "l_HM"}})",
       "/continuation/parameter"},
      {R"({"scene": "walker", "task": "giant_swing", "motion": "single"})", "/scene"},
      {R"({"scene": "giant_swing", "task": "giant_swing", "motion": "single", "options": {"steps": 5}})", "/options/steps"},
      {R"({"scene": "giant_swing", "task": "giant_swing", "motion": "single", "method": "seed", "options": {"steps": 50}})",
       "/options"},
      {R"({"scene": "giant_swing", "task": "giant_swing", "motion": "single", "options": {"weights": {"jerk": 1}}})",
       "/options"},
      {R"({"scene": "giant_swing", "task": "giant_swing", "motion": "single", "options": {"omega_deg_s": 0}})",
       "/options/omega_deg_s"},
  };
  for (const auto& [text, field] : invalid) {
    EXPECT_NE(server_error(spec(text)), "") << "the server accepts " << text;
    const auto errors = job_schema().errors(spec(text));
    EXPECT_TRUE(std::any_of(errors.begin(), errors.end(), [&](const std::string& e) { return e.find(field) != std::string::npos; }))
        << text << ": expected an error at " << field << "; got" << joined(errors);
  }
}

// The schema's rule for `task` (allOf entry whose "if" selects it).
const json& task_rule(const std::string& task) {
  for (const json& rule : job_schema().schema().at("allOf")) {
    const json& selector = rule.at("if").at("properties").at("task");
    const json tasks = selector.contains("const") ? json::array({selector["const"]}) : selector.at("enum");
    if (std::find(tasks.begin(), tasks.end(), json(task)) != tasks.end()) return rule.at("then");
  }
  throw std::out_of_range("job.schema.json has no rule for task " + task);
}

std::vector<std::string> sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}

TEST(JobSchema, EnumsAndTaskFieldsAreTheServers) {
  const json& properties = job_schema().schema().at("properties");
  EXPECT_EQ(properties.at("scene").at("enum").get<std::vector<std::string>>(), service::known_scenes());
  EXPECT_EQ(properties.at("objective").at("enum").get<std::vector<std::string>>(), service::known_objectives());
  const std::vector<std::string>& common = service::common_job_field_names();
  for (const std::string& task : registry().tasks()) {
    const service::JobKind* kind = registry().find(task);
    EXPECT_NE(std::find(service::known_tasks().begin(), service::known_tasks().end(), task), service::known_tasks().end())
        << task << " is missing from the schema's task enum";
    std::vector<std::string> fields = common;
    fields.insert(fields.end(), kind->fields.begin(), kind->fields.end());
    const json& rule = task_rule(task);
    EXPECT_EQ(sorted(rule.at("propertyNames").at("enum").get<std::vector<std::string>>()), sorted(fields)) << task;
    EXPECT_EQ(rule.at("properties").at("scene").at("const").get<std::string>(), kind->scenes.at(0)) << task;
    for (const std::string& field : fields) EXPECT_TRUE(properties.contains(field)) << task << ": " << field;
  }
}

// What a client tells before it sends a spec: the field the schema refuses, as a path.
TEST(JobSchema, NamesTheFieldItRefuses) {
  const auto field = [](const json& spec) {
    try {
      service::check_job_schema(spec);
    } catch (const SpecError& e) {
      return e.field();
    }
    return std::string("accepted");
  };
  const json optimise = {{"scene", "walker"}, {"task", "optimise"}, {"foot", "point"}, {"speed", 1.0}};
  EXPECT_EQ(field(optimise), "accepted");
  json s = optimise;
  s["speed"] = 9;
  EXPECT_EQ(field(s), "speed");
  s = optimise;
  s.erase("foot");
  EXPECT_EQ(field(s), "foot");
  s = optimise;
  s["multistart"] = {{"starts", 0}};
  EXPECT_EQ(field(s), "multistart.starts");
  s = {{"scene", "walker"}, {"task", "foot_comparison"}, {"speeds", "1:0.1:1.2"}, {"feet", {"point", 3}}};
  EXPECT_EQ(field(s), "feet[1]");
  s = {{"scene", "walker"}, {"task", "sweep"}, {"foot", "point"}, {"speeds", "1:0.1:1.2"}, {"multistart", {{"seeds", {1, 2, 3}}}}};
  EXPECT_EQ(field(s), "accepted");
  s["multistart"]["seeds"] = {1, 2, 1};
  EXPECT_EQ(field(s), "multistart.seeds");
}

// The schema is job.schema.json with each folder's task file merged in (service/job_schema.hpp):
// every file's rules select only its own tasks, and a task or a field defined twice, or a file
// of another form, stops the merge naming the file.
TEST(JobSchema, EachFolderOfKindsAddsItsOwnTasks) {
  const std::vector<service::TaskSchemaFile>& files = service::task_schema_files();
  ASSERT_GE(files.size(), 3u);
  for (const service::TaskSchemaFile& file : files) {
    const json part = json::parse(file.text);
    const json& tasks = part.at("tasks");
    for (const json& rule : part.at("allOf")) {
      const json& selector = rule.at("if").at("properties").at("task");
      for (const json& t : selector.contains("const") ? json::array({selector["const"]}) : selector.at("enum"))
        EXPECT_NE(std::find(tasks.begin(), tasks.end(), t), tasks.end()) << file.path << " has a rule for " << t;
    }
  }
  const json shared = json::parse(service::job_schema_file("job.schema.json"));
  EXPECT_FALSE(shared.at("properties").at("task").contains("enum")) << "the tasks come from the folders' files";
  const auto merge_error = [&](const std::vector<service::TaskSchemaFile>& parts) -> std::string {
    try {
      service::merged_job_schema(shared, parts);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "merged";
  };
  const service::TaskSchemaFile toy{"jobs/toy/toy_tasks.schema.json", R"({"tasks": ["toy"], "properties": {"toy_size": {"type": "integer"}}})"};
  EXPECT_EQ(merge_error({toy}), "merged");
  EXPECT_EQ(merge_error({toy, {"b.json", R"({"tasks": ["toy"]})"}}), "b.json: task \"toy\" is defined twice");
  EXPECT_EQ(merge_error({toy, {"b.json", R"({"tasks": ["b"], "properties": {"toy_size": {}}})"}}),
            "b.json: field \"toy_size\" is defined twice");
  EXPECT_EQ(merge_error({{"c.json", R"({"tasks": ["c"], "properties": {"foot": {}}})"}}), "c.json: field \"foot\" is defined twice");
  EXPECT_EQ(merge_error({{"d.json", R"({"tasks": []})"}}), "d.json: \"tasks\" must list its tasks");
  EXPECT_NE(merge_error({{"e.json", R"({"tasks": ["e"], "rules": []})"}}).find("e.json: unknown member \"rules\""), std::string::npos);
  const json merged = service::merged_job_schema(shared, {toy});
  EXPECT_EQ(merged.at("properties").at("task").at("enum"), json::array({"toy"}));
  EXPECT_TRUE(merged.at("properties").contains("toy_size"));
}

// The validator itself, on small schemas: each keyword can refuse.
TEST(JsonSchemaValidator, EachKeywordRefuses) {
  const fs::path dir = fs::temp_directory_path() / ("contract-schema-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const auto check = [&](const json& schema, const json& good, const json& bad) {
    std::ofstream(dir / "s.json") << schema.dump();
    const JsonSchemaValidator v(dir, "s.json");
    EXPECT_TRUE(v.errors(good).empty()) << schema.dump() << " refuses " << good.dump() << joined(v.errors(good));
    EXPECT_FALSE(v.errors(bad).empty()) << schema.dump() << " accepts " << bad.dump();
  };
  check(spec(R"({"type": "integer"})"), 3, 3.5);
  check(spec(R"({"type": ["string", "null"]})"), nullptr, 1);
  check(spec(R"({"enum": [1, "a"]})"), "a", "b");
  check(spec(R"({"const": 2})"), 2, 3);
  check(spec(R"({"minimum": 1, "maximum": 2})"), 2, 2.5);
  check(spec(R"({"exclusiveMinimum": 0})"), 1e-9, 0);
  check(spec(R"({"exclusiveMaximum": 1})"), 0.5, 1);
  check(spec(R"({"minLength": 2, "maxLength": 3})"), "\u00e9\u00e9\u00e9", "abcd");
  check(spec(R"({"pattern": "^a:b$"})"), "a:b", "a:bc");
  check(spec(R"({"minItems": 1, "maxItems": 2, "items": {"type": "number"}})"), json::array({1, 2}), json::array({1, "x"}));
  check(spec(R"({"required": ["a"], "properties": {"a": {"type": "string"}}})"), spec(R"({"a": "x"})"), spec(R"({"a": 1})"));
  check(spec(R"({"properties": {"a": true}, "additionalProperties": false})"), spec(R"({"a": 1})"), spec(R"({"b": 1})"));
  check(spec(R"({"propertyNames": {"enum": ["a"]}})"), spec(R"({"a": 1})"), spec(R"({"b": 1})"));
  check(spec(R"({"allOf": [{"minimum": 0}, {"maximum": 1}]})"), 0.5, 2);
  check(spec(R"({"anyOf": [{"type": "string"}, {"minimum": 5}]})"), 6, 4);
  check(spec(R"({"oneOf": [{"type": "number"}, {"type": "integer"}]})"), 1.5, 1);
  check(spec(R"({"not": {"required": ["a"]}})"), spec(R"({"b": 1})"), spec(R"({"a": 1})"));
  check(spec(R"({"if": {"required": ["a"]}, "then": {"required": ["b"]}, "else": {"required": ["c"]}})"),
        spec(R"({"c": 1})"), spec(R"({"a": 1})"));
  check(spec(R"({"$defs": {"n": {"type": "number"}}, "properties": {"x": {"$ref": "#/$defs/n"}}})"), spec(R"({"x": 1})"),
        spec(R"({"x": "1"})"));
  std::ofstream(dir / "other.json") << R"({"properties": {"y": {"maximum": 3}}})";
  check(spec(R"({"properties": {"x": {"$ref": "other.json#/properties/y"}}})"), spec(R"({"x": 3})"), spec(R"({"x": 4})"));
  check(spec(R"({"uniqueItems": true})"), json::array({1, 2}), json::array({1, 2, 1}));
  std::ofstream(dir / "s.json") << R"({"multipleOf": 2})";
  EXPECT_THROW(JsonSchemaValidator(dir, "s.json").errors(1), std::invalid_argument);  // outside the subset
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cyclopt::testing
