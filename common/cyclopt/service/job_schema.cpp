#include "cyclopt/service/job_schema.hpp"

#include "cyclopt/errors/spec_error.hpp"

#include <algorithm>
#include <cctype>

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

const JsonSchemaValidator& job_schema() {
  static const JsonSchemaValidator v(job_schema_file, "job.schema.json");
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
