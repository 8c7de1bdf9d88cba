#include "cyclopt/service/job_schema.hpp"

#include "cyclopt/errors/spec_error.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace cyclopt::service {

namespace {

// "/feet/1/model" -> "feet[1].model"; "" or "/" -> "".
std::string field_path(const std::string& pointer) {
  std::string path;
  std::size_t at = 0;
  while (at < pointer.size()) {
    const std::size_t next = pointer.find('/', at + 1);
    const std::string token = pointer.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1);
    at = next == std::string::npos ? pointer.size() : next;
    if (token.empty()) continue;
    const bool index = std::all_of(token.begin(), token.end(), [](unsigned char c) { return std::isdigit(c); });
    path += index ? "[" + token + "]" : (path.empty() ? "" : ".") + token;
  }
  return path;
}

}  // namespace

nlohmann::json merged_job_schema(nlohmann::json shared, const std::vector<TaskSchemaFile>& tasks) {
  nlohmann::json& properties = shared.at("properties");
  nlohmann::json names = nlohmann::json::array();
  nlohmann::json rules = nlohmann::json::array();
  for (const TaskSchemaFile& file : tasks) {
    const auto fail = [&](const std::string& why) { throw std::runtime_error(file.path + ": " + why); };
    nlohmann::json part;
    try {
      part = nlohmann::json::parse(file.text);
    } catch (const nlohmann::json::exception& e) {
      fail(std::string("not JSON (") + e.what() + ")");
    }
    for (const auto& [key, value] : part.items())
      if (key != "$comment" && key != "tasks" && key != "properties" && key != "allOf")
        fail("unknown member \"" + key + "\" (a task file holds $comment, tasks, properties, allOf)");
    if (!part.contains("tasks") || !part["tasks"].is_array() || part["tasks"].empty()) fail("\"tasks\" must list its tasks");
    for (const nlohmann::json& task : part["tasks"]) {
      if (!task.is_string()) fail("\"tasks\" must hold names");
      if (std::find(names.begin(), names.end(), task) != names.end()) fail("task " + task.dump() + " is defined twice");
      names.push_back(task);
    }
    const nlohmann::json own = part.value("properties", nlohmann::json::object());
    for (const auto& [field, schema] : own.items()) {
      if (properties.contains(field)) fail("field \"" + field + "\" is defined twice");
      properties[field] = schema;
    }
    const nlohmann::json task_rules = part.value("allOf", nlohmann::json::array());
    for (const nlohmann::json& rule : task_rules) rules.push_back(rule);
  }
  properties.at("task")["enum"] = names;
  shared["allOf"] = rules;
  return shared;
}

const JsonSchemaValidator& job_schema() {
  static const std::string merged =
      merged_job_schema(nlohmann::json::parse(job_schema_file("job.schema.json")), task_schema_files()).dump();
  static const JsonSchemaValidator v(
      [](const std::string& file) { return file == "job.schema.json" ? merged : job_schema_file(file); }, "job.schema.json");
  return v;
}

void check_job_schema(const nlohmann::json& spec) {
  const std::vector<std::string> errors = job_schema().errors(spec);
  if (errors.empty()) return;
  const std::string& first = errors.front();  // "<pointer>: <reason>"
  const std::size_t colon = first.find(": ");
  std::string field = field_path(first.substr(0, colon));
  std::string reason = first.substr(colon + 2);
  if (reason.rfind("requires \"", 0) == 0) {  // a missing member: name it
    const std::string key = reason.substr(10, reason.size() - 11);
    field += (field.empty() ? "" : ".") + key;
    reason = "is required";
  }
  throw SpecError(field.empty() ? "spec_json" : field, reason + " (job.schema.json)");
}

}  // namespace cyclopt::service
