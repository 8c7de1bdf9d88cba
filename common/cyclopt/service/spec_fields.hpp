#pragma once
// Typed, range-checked reads of JSON spec fields. Every failure throws SpecError whose field is
// the JSON path (e.g. "limits.max_wall_seconds") and whose message gives the admissible range.
// Job kinds use these for their own fields.

#include "cyclopt/errors/spec_error.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace cyclopt::service {

// `path` is the JSON path of the field itself.
double number_value(const nlohmann::json& v, const std::string& path, double lo, double hi);
int integer_value(const nlohmann::json& v, const std::string& path, int lo, int hi);
std::string string_value(const nlohmann::json& v, const std::string& path, std::size_t max_length);
std::string enum_value(const nlohmann::json& v, const std::string& path, const std::vector<std::string>& admissible);
const nlohmann::json& object_value(const nlohmann::json& v, const std::string& path);

// Optional members of an object `j` at `path`: nullopt when the key is absent.
std::optional<double> optional_number(const nlohmann::json& j, const std::string& path, const std::string& key,
                                      double lo, double hi);
std::optional<int> optional_integer(const nlohmann::json& j, const std::string& path, const std::string& key, int lo,
                                    int hi);

// Throws for the first key of `j` not in `known`, listing the admissible keys.
void reject_unknown_keys(const nlohmann::json& j, const std::string& path, const std::vector<std::string>& known);

std::string join(const std::vector<std::string>& items, const std::string& separator = ", ");

}  // namespace cyclopt::service
