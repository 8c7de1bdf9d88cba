#pragma once
// The one error type for invalid input, wherever it is found: a JSON spec (io/, service/), a
// typed spec built in code (foot::validate), a preset name, a server setting. field() is the
// input's path, as a JSON path such as "foot.k_HM" or "options.weights.jerk"; the message gives
// the admissible range or the reason. what() is "<field>: <message>".

#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace cyclopt {

class SpecError : public std::invalid_argument {
 public:
  SpecError(std::string field, const std::string& message)
      : std::invalid_argument(field + ": " + message), field_(std::move(field)) {}
  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

// An admissible range as the messages write it: "[lo, hi]", or "[lo, hi] unit" with a unit.
template <class T>
std::string range_text(T lo, T hi, std::string_view unit = {}) {
  std::ostringstream os;
  os << "[" << lo << ", " << hi << "]";
  if (!unit.empty()) os << " " << unit;
  return os.str();
}

}  // namespace cyclopt
