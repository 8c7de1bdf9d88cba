#include "cyclopt/records/multistart_record.hpp"

namespace cyclopt::records {

void to_json(nlohmann::json& j, const MultistartOptimumRecord& m) {
  j = {{"reached_by_starts", m.reached_by_starts},
       {"kkt_successes", m.kkt_successes},
       {"starts", m.starts},
       {"wall_seconds", m.wall_seconds}};
}

void from_json(const nlohmann::json& j, MultistartOptimumRecord& m) {
  const std::string r = "values";
  m = MultistartOptimumRecord{};
  for (const double s : numbers(j, r, "reached_by_starts")) m.reached_by_starts.push_back(static_cast<int>(s));
  m.kkt_successes = integer(j, r, "kkt_successes");
  m.starts = integer(j, r, "starts");
  m.wall_seconds = number(j, r, "wall_seconds");
}

}  // namespace cyclopt::records
