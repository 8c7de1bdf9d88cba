#pragma once
// Reading the members of a stored record: each failure throws RecordError naming the record and
// the member, so a reader never sees a silently defaulted field. NaN and infinities have no JSON
// form: they are written as null and read back as NaN.

#include <nlohmann/json.hpp>

#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace cyclopt::records {

// A number a record does not have (yet): NaN, stored as null.
inline constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();

class RecordError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The member `key` of `j` (an object), or RecordError "<record>.<key>: ...".
const nlohmann::json& member(const nlohmann::json& j, const std::string& record, const std::string& key);
double number(const nlohmann::json& j, const std::string& record, const std::string& key);  // null -> NaN
int integer(const nlohmann::json& j, const std::string& record, const std::string& key);
bool boolean(const nlohmann::json& j, const std::string& record, const std::string& key);
std::string text(const nlohmann::json& j, const std::string& record, const std::string& key);
std::vector<double> numbers(const nlohmann::json& j, const std::string& record, const std::string& key);
std::vector<std::string> texts(const nlohmann::json& j, const std::string& record, const std::string& key);
std::vector<std::vector<double>> rows(const nlohmann::json& j, const std::string& record, const std::string& key);

// nullopt when `key` is absent (or null); else as above.
std::optional<double> optional_number(const nlohmann::json& j, const std::string& record, const std::string& key);
std::optional<std::string> optional_text(const nlohmann::json& j, const std::string& record, const std::string& key);

// A number as JSON: null when not finite.
nlohmann::json finite_or_null(double x);

}  // namespace cyclopt::records
