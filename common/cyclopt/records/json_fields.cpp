#include "cyclopt/records/json_fields.hpp"

#include <cmath>
#include <limits>

namespace cyclopt::records {

namespace {

[[noreturn]] void fail(const std::string& record, const std::string& key, const std::string& why) {
  throw RecordError(record + "." + key + ": " + why);
}

double as_number(const nlohmann::json& v, const std::string& record, const std::string& key) {
  if (v.is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (!v.is_number()) fail(record, key, "must be a number, got " + v.dump());
  return v.get<double>();
}

}  // namespace

const nlohmann::json& member(const nlohmann::json& j, const std::string& record, const std::string& key) {
  if (!j.is_object()) throw RecordError(record + ": must be an object, got " + std::string(j.type_name()));
  const auto it = j.find(key);
  if (it == j.end()) fail(record, key, "is missing");
  return *it;
}

double number(const nlohmann::json& j, const std::string& record, const std::string& key) {
  return as_number(member(j, record, key), record, key);
}

int integer(const nlohmann::json& j, const std::string& record, const std::string& key) {
  const nlohmann::json& v = member(j, record, key);
  if (!v.is_number_integer()) fail(record, key, "must be an integer, got " + v.dump());
  return v.get<int>();
}

bool boolean(const nlohmann::json& j, const std::string& record, const std::string& key) {
  const nlohmann::json& v = member(j, record, key);
  if (!v.is_boolean()) fail(record, key, "must be true or false, got " + v.dump());
  return v.get<bool>();
}

std::string text(const nlohmann::json& j, const std::string& record, const std::string& key) {
  const nlohmann::json& v = member(j, record, key);
  if (!v.is_string()) fail(record, key, "must be a string, got " + v.dump());
  return v.get<std::string>();
}

std::vector<double> numbers(const nlohmann::json& j, const std::string& record, const std::string& key) {
  const nlohmann::json& v = member(j, record, key);
  if (!v.is_array()) fail(record, key, "must be an array of numbers, got " + std::string(v.type_name()));
  std::vector<double> out;
  out.reserve(v.size());
  for (const nlohmann::json& x : v) out.push_back(as_number(x, record, key));
  return out;
}

std::vector<std::string> texts(const nlohmann::json& j, const std::string& record, const std::string& key) {
  const nlohmann::json& v = member(j, record, key);
  std::vector<std::string> out;
  if (!v.is_array()) fail(record, key, "must be an array of strings, got " + v.dump());
  for (const nlohmann::json& s : v) {
    if (!s.is_string()) fail(record, key, "must be an array of strings, got " + v.dump());
    out.push_back(s.get<std::string>());
  }
  return out;
}

std::vector<std::vector<double>> rows(const nlohmann::json& j, const std::string& record, const std::string& key) {
  const nlohmann::json& v = member(j, record, key);
  if (!v.is_array()) fail(record, key, "must be an array of rows, got " + std::string(v.type_name()));
  std::vector<std::vector<double>> out;
  for (std::size_t r = 0; r < v.size(); ++r) {
    const std::string row_key = key + "[" + std::to_string(r) + "]";
    if (!v[r].is_array()) fail(record, row_key, "must be an array of numbers");
    std::vector<double>& row = out.emplace_back();
    for (const nlohmann::json& x : v[r]) row.push_back(as_number(x, record, row_key));
  }
  return out;
}

std::optional<double> optional_number(const nlohmann::json& j, const std::string& record, const std::string& key) {
  if (!j.contains(key) || j[key].is_null()) return std::nullopt;
  return number(j, record, key);
}

std::optional<std::string> optional_text(const nlohmann::json& j, const std::string& record, const std::string& key) {
  if (!j.contains(key) || j[key].is_null()) return std::nullopt;
  return text(j, record, key);
}

nlohmann::json finite_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

}  // namespace cyclopt::records
