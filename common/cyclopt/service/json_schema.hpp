#pragma once
// A validator for the subset of JSON Schema (draft 2020-12) that proto/schemas/*.json use
// (nlohmann-json has none): type, enum, const, properties, required,
// additionalProperties, propertyNames, items, minItems / maxItems, minimum / maximum /
// exclusiveMinimum / exclusiveMaximum, minLength / maxLength, pattern, allOf / anyOf / oneOf /
// not, if / then / else, boolean schemas and $ref (a JSON pointer into the same file,
// "#/$defs/x", or another file of the schema's set, "foot.schema.json[#/pointer]").
// A keyword outside this subset throws std::invalid_argument, so a schema that grows one fails
// its test instead of passing unchecked.

#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace cyclopt::service {

class JsonSchemaValidator {
 public:
  // The text of a schema file by name; throws std::runtime_error when there is none.
  using SchemaFiles = std::function<std::string(const std::string& file)>;
  // `file` of `files`, its $refs from there; throws std::runtime_error when one is missing or not JSON.
  JsonSchemaValidator(SchemaFiles files, const std::string& file);
  // `file` of `directory`, its $refs from there.
  JsonSchemaValidator(const std::filesystem::path& directory, const std::string& file);

  // The violations of `instance`, each "<JSON pointer>: <reason>"; empty when it is valid.
  std::vector<std::string> errors(const nlohmann::json& instance) const;

  const nlohmann::json& schema() const { return document(root_); }

 private:
  const nlohmann::json& document(const std::string& file) const;
  void check(const nlohmann::json& schema, const std::string& file, const nlohmann::json& instance,
             const std::string& where, std::vector<std::string>& out) const;
  bool valid(const nlohmann::json& schema, const std::string& file, const nlohmann::json& instance,
             const std::string& where) const;

  SchemaFiles files_;
  std::string root_;
  mutable std::map<std::string, nlohmann::json> documents_;  // loaded on first $ref
};

}  // namespace cyclopt::service
