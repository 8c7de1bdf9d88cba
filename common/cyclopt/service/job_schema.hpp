#pragma once
// The job spec's JSON schema (proto/schemas/job.schema.json and the foot and giant-swing task
// schemas it refers to), embedded at build time: what a client checks a spec against before it
// sends it, without the job kinds. The server's validation (job_spec.hpp) is the full one; the
// schema may accept more (it cannot count a start vector's length), never less
// (tests/service/test_job_schema holds the two together).

#include "cyclopt/service/json_schema.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace cyclopt::service {

// The text of an embedded schema file ("job.schema.json", "foot.schema.json",
// "giant_swing_task.schema.json"); std::runtime_error for any other name.
std::string job_schema_file(const std::string& name);

const JsonSchemaValidator& job_schema();

// Throws SpecError for the first violation of the schema, naming its field as a path
// ("multistart.starts", "feet[1].model") and what the schema asks there.
void check_job_schema(const nlohmann::json& spec);

}  // namespace cyclopt::service
