#include "cyclopt/service/spec_fields.hpp"

#include <algorithm>
#include <cmath>

namespace cyclopt::service {

namespace {
std::string child(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }
}  // namespace

std::string join(const std::vector<std::string>& items, const std::string& separator) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : separator) + s;
  return out;
}

double number_value(const nlohmann::json& v, const std::string& path, double lo, double hi) {
  if (!v.is_number()) throw SpecError(path, "must be a number in " + range_text(lo, hi) + ", got " + v.dump());
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < lo || x > hi)
    throw SpecError(path, "must be in " + range_text(lo, hi) + ", got " + v.dump());
  return x;
}

int integer_value(const nlohmann::json& v, const std::string& path, int lo, int hi) {
  if (!v.is_number_integer() && !(v.is_number_float() && std::floor(v.get<double>()) == v.get<double>()))
    throw SpecError(path, "must be an integer in " + range_text(lo, hi) + ", got " + v.dump());
  const double x = v.get<double>();
  if (x < lo || x > hi) throw SpecError(path, "must be in " + range_text(lo, hi) + ", got " + v.dump());
  return static_cast<int>(x);
}

std::string string_value(const nlohmann::json& v, const std::string& path, std::size_t max_length) {
  if (!v.is_string()) throw SpecError(path, "must be a string, got " + v.dump());
  std::string s = v.get<std::string>();
  if (s.size() > max_length)
    throw SpecError(path, "must be at most " + std::to_string(max_length) + " characters, got " + std::to_string(s.size()));
  return s;
}

std::string enum_value(const nlohmann::json& v, const std::string& path, const std::vector<std::string>& admissible) {
  if (!v.is_string()) throw SpecError(path, "must be one of " + join(admissible) + ", got " + v.dump());
  std::string s = v.get<std::string>();
  if (std::find(admissible.begin(), admissible.end(), s) == admissible.end())
    throw SpecError(path, "must be one of " + join(admissible) + ", got " + v.dump());
  return s;
}

const nlohmann::json& object_value(const nlohmann::json& v, const std::string& path) {
  if (!v.is_object()) throw SpecError(path, "must be a JSON object, got " + v.dump().substr(0, 80));
  return v;
}

std::optional<double> optional_number(const nlohmann::json& j, const std::string& path, const std::string& key,
                                      double lo, double hi) {
  if (!j.contains(key)) return std::nullopt;
  return number_value(j.at(key), child(path, key), lo, hi);
}

std::optional<int> optional_integer(const nlohmann::json& j, const std::string& path, const std::string& key, int lo,
                                    int hi) {
  if (!j.contains(key)) return std::nullopt;
  return integer_value(j.at(key), child(path, key), lo, hi);
}

void reject_unknown_keys(const nlohmann::json& j, const std::string& path, const std::vector<std::string>& known) {
  for (const auto& [key, value] : j.items())
    if (std::find(known.begin(), known.end(), key) == known.end())
      throw SpecError(child(path, key), "unknown field (admissible: " + join(known) + ")");
}

}  // namespace cyclopt::service
