#pragma once
// The job spec's JSON schema, embedded at build time: proto/schemas/job.schema.json (the fields
// every task shares) merged with the task rules of every folder of job kinds
// (common/cyclopt/jobs/<scene>/<scene>_tasks.schema.json), and the foot and giant-swing task
// schemas it refers to. It is what a client checks a spec against before it sends it, without the
// job kinds. The server's validation (job_spec.hpp) is the full one; the schema may accept more
// (it cannot count a start vector's length), never less (tests/service/test_job_schema holds the
// two together).

#include "cyclopt/service/json_schema.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace cyclopt::service {

// The text of an embedded schema file ("job.schema.json", "foot.schema.json",
// "giant_swing_task.schema.json"); std::runtime_error for any other name.
std::string job_schema_file(const std::string& name);

// A folder's task rules: {"tasks": [names], "properties": {the fields only they take},
// "allOf": [a rule per task: if task is one of them, then the fields it takes]}.
struct TaskSchemaFile {
  std::string path;  // from the source root, for errors
  std::string text;
};
const std::vector<TaskSchemaFile>& task_schema_files();

// job.schema.json with every task file merged in: their tasks become the `task` enum, their
// properties join the shared ones, their rules the schema's allOf. std::runtime_error naming the
// file when a task or a field is defined twice or a file is not of that form.
nlohmann::json merged_job_schema(nlohmann::json shared, const std::vector<TaskSchemaFile>& tasks);

const JsonSchemaValidator& job_schema();

// Throws SpecError for the first violation of the schema, naming its field as a path
// ("multistart.starts", "feet[1].model") and what the schema asks there.
void check_job_schema(const nlohmann::json& spec);

}  // namespace cyclopt::service
