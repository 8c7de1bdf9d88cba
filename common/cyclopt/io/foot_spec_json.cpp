#include "cyclopt/io/foot_spec_json.hpp"

#include "cyclopt/foot/foot_presets.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cyclopt::io {

using foot::FootModel;
using foot::FootSpec;
using foot::ParameterInfo;

namespace {

double number_field(const nlohmann::json& j, const std::string& key, const std::string& path, double lo, double hi,
                    std::string_view unit) {
  const std::string field = path + "." + key;
  const nlohmann::json& v = j.at(key);
  if (!v.is_number()) throw SpecError(field, "must be a number in " + range_text(lo, hi, unit) + ", got " + v.dump());
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw SpecError(field, "must be a finite number in " + range_text(lo, hi, unit));
  if (x < lo || x > hi) throw SpecError(field, "must be in " + range_text(lo, hi, unit) + ", got " + v.dump());
  return x;
}

}  // namespace

FootSpec foot_spec_from_json(const nlohmann::json& j, const std::string& path) {
  if (!j.is_object()) throw SpecError(path, "must be a JSON object with a \"model\" field, got " + std::string(j.type_name()));
  if (!j.contains("model")) throw SpecError(path + ".model", "is required: one of \"point\", \"HM\", \"HMT\"");
  const nlohmann::json& m = j.at("model");
  if (!m.is_string()) throw SpecError(path + ".model", "must be a string: one of \"point\", \"HM\", \"HMT\"");
  FootSpec spec;
  try {
    spec.model = foot::foot_model_from_string(m.get<std::string>());
  } catch (const std::invalid_argument&) {
    throw SpecError(path + ".model", "must be one of \"point\", \"HM\", \"HMT\", got " + m.dump());
  }
  const auto layout = foot::parameter_layout(spec.model);
  std::string allowed = "model, periodic_terms, density, theta_F0, name";
  for (const ParameterInfo& info : layout) allowed += ", " + std::string(info.name);
  for (const auto& [key, value] : j.items()) {
    const bool known = key == "model" || key == "periodic_terms" || key == "density" || key == "theta_F0" ||
                       key == "name" || std::any_of(layout.begin(), layout.end(), [&](const ParameterInfo& p) {
                         return p.name == key;
                       });
    if (!known)
      throw SpecError(path + "." + key, "is not a field of a " + std::string(to_string(spec.model)) +
                                            " foot; allowed: " + allowed);
  }
  spec.parameters.resize(static_cast<Eigen::Index>(layout.size()));
  for (std::size_t i = 0; i < layout.size(); ++i) {
    const std::string key(layout[i].name);
    if (!j.contains(key))
      throw SpecError(path + "." + key, "is required for a " + std::string(to_string(spec.model)) + " foot (" +
                                            std::string(layout[i].meaning) + "), range " +
                                            range_text(layout[i].min, layout[i].max, layout[i].unit));
    spec.parameters[static_cast<Eigen::Index>(i)] = number_field(j, key, path, layout[i].min, layout[i].max, layout[i].unit);
  }
  if (j.contains("periodic_terms")) {
    const nlohmann::json& v = j.at("periodic_terms");
    if (!v.is_number_integer())
      throw SpecError(path + ".periodic_terms",
                      "must be an integer in [0, " + std::to_string(foot::kMaxPeriodicTerms) + "], got " + v.dump());
    spec.periodic_terms = v.get<int>();
  }
  if (j.contains("density")) spec.density = number_field(j, "density", path, foot::kMinDensity, foot::kMaxDensity, "kg/m^2");
  if (j.contains("theta_F0"))
    spec.theta_F0 = number_field(j, "theta_F0", path, -std::numbers::pi, std::numbers::pi, "rad");
  if (j.contains("name")) {
    if (!j.at("name").is_string()) throw SpecError(path + ".name", "must be a string");
    spec.name = j.at("name").get<std::string>();
  }
  foot::validate(spec, path);
  return spec;
}

nlohmann::json to_json(const FootSpec& spec) {
  nlohmann::json j;
  j["model"] = std::string(to_string(spec.model));
  const auto layout = foot::parameter_layout(spec.model);
  for (std::size_t i = 0; i < layout.size(); ++i)
    j[std::string(layout[i].name)] = spec.parameters[static_cast<Eigen::Index>(i)];
  if (spec.periodic_terms != 0) j["periodic_terms"] = spec.periodic_terms;
  if (spec.density) j["density"] = *spec.density;
  if (spec.theta_F0) j["theta_F0"] = *spec.theta_F0;
  if (!spec.name.empty()) j["name"] = spec.name;
  return j;
}

FootSpec foot_value(const nlohmann::json& v, const std::string& path) {
  if (v.is_string()) try {
      return foot::foot_preset(v.get<std::string>()).spec;
    } catch (const SpecError& e) {
      throw SpecError(path, e.what());
    }
  if (!v.is_object()) throw SpecError(path, "must be a JSON object, got " + v.dump().substr(0, 80));
  return foot_spec_from_json(v, path);
}

}  // namespace cyclopt::io
