#include "cyclopt/service/json_schema.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <stdexcept>

namespace cyclopt::service {

namespace {

using nlohmann::json;

const std::set<std::string>& annotations() {
  static const std::set<std::string> k = {"$schema", "$id", "$comment", "$defs", "title", "description", "default",
                                          "examples"};
  return k;
}

const std::set<std::string>& assertions() {
  static const std::set<std::string> k = {
      "type",     "enum",     "const",   "properties",       "required",         "additionalProperties",
      "items",    "minItems", "maxItems", "minimum",         "maximum",          "exclusiveMinimum",
      "exclusiveMaximum",     "minLength", "maxLength",      "pattern",          "allOf",
      "anyOf",    "oneOf",    "not",     "if",               "then",             "else",
      "$ref",     "propertyNames", "uniqueItems"};
  return k;
}

bool has_type(const json& v, const std::string& type) {
  if (type == "object") return v.is_object();
  if (type == "array") return v.is_array();
  if (type == "string") return v.is_string();
  if (type == "boolean") return v.is_boolean();
  if (type == "null") return v.is_null();
  if (type == "number") return v.is_number();
  if (type == "integer")
    return v.is_number_integer() || (v.is_number_float() && std::floor(v.get<double>()) == v.get<double>());
  throw std::invalid_argument("unknown JSON Schema type '" + type + "'");
}

std::size_t code_points(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s)
    if ((c & 0xC0) != 0x80) ++n;
  return n;
}

std::string child(const std::string& where, const std::string& key) { return where + "/" + key; }

}  // namespace

JsonSchemaValidator::JsonSchemaValidator(SchemaFiles files, const std::string& file)
    : files_(std::move(files)), root_(file) {
  document(root_);
}

JsonSchemaValidator::JsonSchemaValidator(const std::filesystem::path& directory, const std::string& file)
    : JsonSchemaValidator(
          [directory](const std::string& name) {
            std::ifstream in(directory / name);
            if (!in) throw std::runtime_error("cannot read schema " + (directory / name).string());
            return std::string(std::istreambuf_iterator<char>(in), {});
          },
          file) {}

const json& JsonSchemaValidator::document(const std::string& file) const {
  auto it = documents_.find(file);
  if (it != documents_.end()) return it->second;
  json j;
  try {
    j = json::parse(files_(file));
  } catch (const json::exception& e) {
    throw std::runtime_error("schema " + file + " is not JSON: " + e.what());
  }
  return documents_.emplace(file, std::move(j)).first->second;
}

std::vector<std::string> JsonSchemaValidator::errors(const json& instance) const {
  std::vector<std::string> out;
  check(document(root_), root_, instance, "", out);
  return out;
}

bool JsonSchemaValidator::valid(const json& schema, const std::string& file, const json& instance,
                                const std::string& where) const {
  std::vector<std::string> out;
  check(schema, file, instance, where, out);
  return out.empty();
}

void JsonSchemaValidator::check(const json& schema, const std::string& file, const json& v, const std::string& where,
                                std::vector<std::string>& out) const {
  if (schema.is_boolean()) {
    if (!schema.get<bool>()) out.push_back(where + ": is not allowed here");
    return;
  }
  if (!schema.is_object()) throw std::invalid_argument(file + ": a schema must be an object or a boolean");
  for (const auto& [keyword, value] : schema.items())
    if (!annotations().count(keyword) && !assertions().count(keyword))
      throw std::invalid_argument(file + ": unsupported JSON Schema keyword '" + keyword + "'");
  const auto fail = [&](const std::string& reason) { out.push_back((where.empty() ? "/" : where) + ": " + reason); };

  if (schema.contains("$ref")) {
    const std::string ref = schema["$ref"].get<std::string>();
    const std::size_t hash = ref.find('#');
    const std::string target_file = hash == 0 ? file : ref.substr(0, hash);
    const std::string pointer = hash == std::string::npos ? "" : ref.substr(hash + 1);
    const json& target = document(target_file).at(json::json_pointer(pointer));
    check(target, target_file, v, where, out);
  }
  if (schema.contains("type")) {
    const json& t = schema["type"];
    bool ok = false;
    for (const json& type : t.is_array() ? t : json::array({t})) ok = ok || has_type(v, type.get<std::string>());
    if (!ok) fail("must be of type " + t.dump() + ", got " + v.dump());
  }
  if (schema.contains("enum")) {
    bool ok = false;
    for (const json& e : schema["enum"]) ok = ok || e == v;
    if (!ok) fail("must be one of " + schema["enum"].dump() + ", got " + v.dump());
  }
  if (schema.contains("const") && schema["const"] != v) fail("must be " + schema["const"].dump() + ", got " + v.dump());

  if (v.is_number()) {
    const double x = v.get<double>();
    if (schema.contains("minimum") && x < schema["minimum"].get<double>()) fail("must be >= " + schema["minimum"].dump());
    if (schema.contains("maximum") && x > schema["maximum"].get<double>()) fail("must be <= " + schema["maximum"].dump());
    if (schema.contains("exclusiveMinimum") && !(x > schema["exclusiveMinimum"].get<double>()))
      fail("must be > " + schema["exclusiveMinimum"].dump());
    if (schema.contains("exclusiveMaximum") && !(x < schema["exclusiveMaximum"].get<double>()))
      fail("must be < " + schema["exclusiveMaximum"].dump());
  }
  if (v.is_string()) {
    const std::string s = v.get<std::string>();
    if (schema.contains("minLength") && code_points(s) < schema["minLength"].get<std::size_t>())
      fail("must have at least " + schema["minLength"].dump() + " characters");
    if (schema.contains("maxLength") && code_points(s) > schema["maxLength"].get<std::size_t>())
      fail("must have at most " + schema["maxLength"].dump() + " characters");
    if (schema.contains("pattern") && !std::regex_search(s, std::regex(schema["pattern"].get<std::string>())))
      fail("must match " + schema["pattern"].dump() + ", got " + v.dump());
  }
  if (v.is_array()) {
    if (schema.contains("minItems") && v.size() < schema["minItems"].get<std::size_t>())
      fail("must have at least " + schema["minItems"].dump() + " items");
    if (schema.contains("maxItems") && v.size() > schema["maxItems"].get<std::size_t>())
      fail("must have at most " + schema["maxItems"].dump() + " items");
    if (schema.value("uniqueItems", false))
      for (std::size_t i = 1; i < v.size(); ++i)
        for (std::size_t k = 0; k < i; ++k)
          if (v[i] == v[k]) fail("must have unique items, item " + std::to_string(i) + " repeats item " + std::to_string(k));
    if (schema.contains("items"))
      for (std::size_t i = 0; i < v.size(); ++i) check(schema["items"], file, v[i], child(where, std::to_string(i)), out);
  }
  if (v.is_object()) {
    if (schema.contains("required"))
      for (const json& key : schema["required"])
        if (!v.contains(key.get<std::string>())) fail("requires " + key.dump());
    const json properties = schema.value("properties", json::object());
    for (const auto& [key, value] : v.items()) {
      if (schema.contains("propertyNames")) check(schema["propertyNames"], file, key, child(where, key), out);
      if (properties.contains(key))
        check(properties[key], file, value, child(where, key), out);
      else if (schema.contains("additionalProperties"))
        check(schema["additionalProperties"], file, value, child(where, key), out);
    }
  }

  if (schema.contains("allOf"))
    for (const json& s : schema["allOf"]) check(s, file, v, where, out);
  if (schema.contains("anyOf")) {
    bool ok = false;
    for (const json& s : schema["anyOf"]) ok = ok || valid(s, file, v, where);
    if (!ok) fail("matches none of the anyOf alternatives");
  }
  if (schema.contains("oneOf")) {
    std::vector<std::string> reasons;
    int matches = 0;
    for (const json& s : schema["oneOf"]) {
      std::vector<std::string> e;
      check(s, file, v, where, e);
      if (e.empty()) ++matches;
      else reasons.push_back(e.front());
    }
    if (matches == 0) {
      std::string text;
      for (const std::string& r : reasons) text += (text.empty() ? "" : "; ") + r;
      fail("matches none of the oneOf alternatives (" + text + ")");
    } else if (matches > 1) {
      fail("matches " + std::to_string(matches) + " of the oneOf alternatives, needs exactly one");
    }
  }
  if (schema.contains("not") && valid(schema["not"], file, v, where)) fail("must not match " + schema["not"].dump());
  if (schema.contains("if")) {
    const char* branch = valid(schema["if"], file, v, where) ? "then" : "else";
    if (schema.contains(branch)) check(schema[branch], file, v, where, out);
  }
}

}  // namespace cyclopt::service
