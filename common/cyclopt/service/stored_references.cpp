#include "cyclopt/service/stored_references.hpp"

#include "cyclopt/service/spec_fields.hpp"

#include <limits>

namespace cyclopt::service {

namespace {

constexpr int kMaxId = std::numeric_limits<int>::max();

bool names_stored_point(const nlohmann::json& spec) { return spec.contains("start") && spec["start"].is_object(); }

bool is_fit_reference(const nlohmann::json& foot) { return foot.is_object() && foot.contains("fit"); }

// The feet of `spec` that name a stored fit, unchecked: (pointer, field path).
std::vector<std::pair<nlohmann::json::json_pointer, std::string>> fit_references(const nlohmann::json& spec) {
  std::vector<std::pair<nlohmann::json::json_pointer, std::string>> out;
  if (!spec.is_object()) return out;
  for (const char* key : {"foot", "reference"})
    if (spec.contains(key) && is_fit_reference(spec[key])) out.emplace_back(nlohmann::json::json_pointer() / key, key);
  if (spec.contains("feet") && spec["feet"].is_array())
    for (std::size_t i = 0; i < spec["feet"].size(); ++i)
      if (is_fit_reference(spec["feet"][i]))
        out.emplace_back(nlohmann::json::json_pointer("/feet") / i, "feet[" + std::to_string(i) + "]");
  return out;
}

}  // namespace

std::optional<StoredPointReference> stored_point_reference(const nlohmann::json& spec) {
  if (!names_stored_point(spec)) return std::nullopt;
  const nlohmann::json& s = spec["start"];
  reject_unknown_keys(s, "start", {"job", "curve", "point"});
  if (!s.contains("job")) throw SpecError("start.job", "is required: the id of the job that stored the point");
  if (!s.contains("point")) throw SpecError("start.point", "is required: the point's index on its curve (>= 0)");
  return StoredPointReference{*optional_integer(s, "start", "job", 1, kMaxId),
                              {optional_integer(s, "start", "curve", 0, kMaxId).value_or(0),
                               *optional_integer(s, "start", "point", 0, kMaxId)},
                              s.contains("curve")};
}

std::vector<StoredFitReference> stored_fit_references(const nlohmann::json& spec) {
  std::vector<StoredFitReference> out;
  for (const auto& [where, path] : fit_references(spec)) {
    const nlohmann::json& foot = spec[where];
    reject_unknown_keys(foot, path, {"fit"});
    const std::string at = path + ".fit";
    const nlohmann::json& fit = object_value(foot["fit"], at);
    reject_unknown_keys(fit, at, {"job", "model"});
    if (!fit.contains("job")) throw SpecError(at + ".job", "is required: the id of a foot_fit job");
    StoredFitReference r{where, path, *optional_integer(fit, at, "job", 1, kMaxId), "HMT"};
    if (fit.contains("model")) r.model = enum_value(fit["model"], at + ".model", {"HM", "HMT"});
    out.push_back(std::move(r));
  }
  return out;
}

nlohmann::json without_stored_start(nlohmann::json spec) {
  if (!stored_point_reference(spec)) return spec;
  spec.erase("start");
  return spec;
}

std::string runnable_spec_text(const storage::JobRecord& job) {
  const nlohmann::json spec = nlohmann::json::parse(job.spec_json, nullptr, false);
  const bool references = spec.is_object() && (names_stored_point(spec) || !fit_references(spec).empty());
  return references && !job.resolved_spec_json.empty() ? job.resolved_spec_json : job.spec_json;
}

}  // namespace cyclopt::service
