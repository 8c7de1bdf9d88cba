#pragma once
// The setup of a walker job: the walker its points were solved on - the foot, the model constants
// P (eq. 5.93, "points") and M (the Bezier degree, "bezier_degree") - the objective, and for a
// foot design the design speed. Every walker job stores it at submission, as these members of its
// resolved spec (service/resolved_spec.hpp), written through this record by the walker kinds'
// resolver (jobs/walker/walker_job_json.hpp); the figures read the walker from it.

#include "cyclopt/records/json_fields.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace cyclopt::records {

struct WalkerSetupRecord {
  // A foot spec (foot.schema.json); a preset name in specs stored before resolved specs were.
  nlohmann::json foot;
  std::optional<int> points, bezier_degree;  // absent (specs stored before resolved ones): the model's defaults
  std::string objective = "f_mech";          // f_mech (eq. 5.102) | f_usq (eq. 5.101)
  std::optional<double> design_speed;        // m/s, foot_design jobs
  bool operator==(const WalkerSetupRecord&) const = default;
};

void to_json(nlohmann::json& j, const WalkerSetupRecord& s);
// Reads the members of a spec object (others are ignored); throws RecordError naming the field.
void from_json(const nlohmann::json& j, WalkerSetupRecord& s);

}  // namespace cyclopt::records
