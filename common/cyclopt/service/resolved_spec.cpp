#include "cyclopt/service/resolved_spec.hpp"

#include <string>

namespace cyclopt::service {

namespace {

void collect_seeds(const nlohmann::json& j, const std::string& path, nlohmann::json& out) {
  if (!j.is_object()) return;
  for (const auto& [key, value] : j.items()) {
    const std::string field = path.empty() ? key : path + "." + key;
    if ((key == "seed" && value.is_number_integer()) || (key == "seeds" && value.is_array()))
      out[field] = value;
    else
      collect_seeds(value, field, out);
  }
}

}  // namespace

nlohmann::json resolved_spec(const ValidatedJobSpec& v) {
  nlohmann::json r = {{"scene", v.scene}, {"task", v.task}};
  if (!v.common.name.empty()) r["name"] = v.common.name;
  nlohmann::json limits = nlohmann::json::object();
  if (v.common.limits.max_wall_seconds) limits["max_wall_seconds"] = *v.common.limits.max_wall_seconds;
  if (v.common.limits.max_iterations) limits["max_iterations"] = *v.common.limits.max_iterations;
  if (!limits.empty()) r["limits"] = limits;
  r.update(v.kind->resolve(*v.spec));
  return r;
}

nlohmann::json random_seeds(const nlohmann::json& resolved) {
  nlohmann::json seeds = nlohmann::json::object();
  collect_seeds(resolved, "", seeds);
  return seeds;
}

}  // namespace cyclopt::service
