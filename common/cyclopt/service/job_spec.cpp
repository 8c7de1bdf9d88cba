#include "cyclopt/service/job_spec.hpp"

#include "cyclopt/service/job_schema.hpp"
#include "cyclopt/service/spec_fields.hpp"

#include <algorithm>

namespace cyclopt::service {

namespace {

// Follows the JSON path while parsing, so a number the lexer cannot represent (1e400) is reported
// under its field ("speed", "start[3]") rather than as an internal error.
class FieldPathTracker final : public nlohmann::json_sax<nlohmann::json> {
 public:
  std::string path;     // of the value being parsed when parse_error was called
  std::string token;    // its text

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(false); }
  bool key(string_t& k) override {
    frames_.back().key = k;
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string& last_token, const nlohmann::detail::exception&) override {
    token = last_token;
    for (std::size_t i = 0; i < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      const bool innermost = i + 1 == frames_.size();  // its value was not counted yet
      if (f.array) {
        path += '[';
        path += std::to_string(f.index + (innermost ? 1 : 0));
        path += ']';
      } else {
        if (!path.empty()) path += '.';
        path += f.key;
      }
    }
    return false;
  }

 private:
  struct Frame {
    bool array = false;
    std::string key;
    long index = -1;
  };
  bool value() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
    return true;
  }
  bool open(bool array) {
    value();
    frames_.push_back({array, "", -1});
    return true;
  }
  bool close() {
    frames_.pop_back();
    return true;
  }
  std::vector<Frame> frames_;
};

}  // namespace

const std::vector<std::string>& known_scenes() {
  static const std::vector<std::string> v = {"walker", "giant_swing"};
  return v;
}
const std::vector<std::string>& known_tasks() {
  static const std::vector<std::string> v =
      job_schema().schema().at("properties").at("task").at("enum").get<std::vector<std::string>>();
  return v;
}
const std::vector<std::string>& known_objectives() {
  static const std::vector<std::string> v = {"f_mech", "f_usq"};
  return v;
}

nlohmann::json parse_job_spec_text(const std::string& text) {
  nlohmann::json spec;
  try {
    spec = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw SpecError("spec_json", std::string("malformed JSON: ") + e.what());
  } catch (const nlohmann::json::out_of_range&) {  // a number beyond the range of a double
    FieldPathTracker where;
    nlohmann::json::sax_parse(text, &where);
    throw SpecError(where.path.empty() ? "spec_json" : where.path,
                    where.token + " is outside the range of a double (magnitude at most 1.8e308)");
  }
  if (!spec.is_object()) throw SpecError("spec_json", "must be a JSON object, got " + std::string(spec.type_name()));
  return spec;
}

ValidatedJobSpec validate_job_spec(const nlohmann::json& spec, const JobKindRegistry& registry) {
  if (!spec.is_object()) throw SpecError("spec_json", "must be a JSON object, got " + std::string(spec.type_name()));
  ValidatedJobSpec v;
  if (!spec.contains("scene")) throw SpecError("scene", "is required (" + join(known_scenes()) + ")");
  if (!spec.contains("task")) throw SpecError("task", "is required (" + join(known_tasks()) + ")");
  v.scene = enum_value(spec["scene"], "scene", known_scenes());
  v.task = enum_value(spec["task"], "task", known_tasks());
  v.kind = registry.find(v.task);
  if (!v.kind) throw SpecError("task", "'" + v.task + "' is not available on this server (available: " + join(registry.tasks()) + ")");
  if (std::find(v.kind->scenes.begin(), v.kind->scenes.end(), v.scene) == v.kind->scenes.end())
    throw SpecError("scene", "task '" + v.task + "' needs scene " + join(v.kind->scenes, " or ") + ", got '" + v.scene + "'");
  std::vector<std::string> fields = common_job_field_names();
  fields.insert(fields.end(), v.kind->fields.begin(), v.kind->fields.end());
  reject_unknown_keys(spec, "", fields);
  v.common = parse_common_job_fields(spec);
  v.spec = v.kind->parse(spec, v.common);
  return v;
}

ValidatedJobSpec validate_job_spec_text(const std::string& text, const JobKindRegistry& registry) {
  return validate_job_spec(parse_job_spec_text(text), registry);
}

}  // namespace cyclopt::service
