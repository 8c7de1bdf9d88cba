#include "cyclopt/records/walker_setup_record.hpp"

namespace cyclopt::records {

void to_json(nlohmann::json& j, const WalkerSetupRecord& s) {
  j = {{"foot", s.foot}, {"objective", s.objective}};
  if (s.points) j["points"] = *s.points;
  if (s.bezier_degree) j["bezier_degree"] = *s.bezier_degree;
  if (s.design_speed) j["design_speed"] = *s.design_speed;
}

void from_json(const nlohmann::json& j, WalkerSetupRecord& s) {
  const std::string r = "spec";
  s = WalkerSetupRecord{};
  s.foot = member(j, r, "foot");
  if (j.contains("points")) s.points = integer(j, r, "points");
  if (j.contains("bezier_degree")) s.bezier_degree = integer(j, r, "bezier_degree");
  s.objective = optional_text(j, r, "objective").value_or(s.objective);
  s.design_speed = optional_number(j, r, "design_speed");
}

}  // namespace cyclopt::records
