#pragma once
// What a walker multistart job stores beside each distinct optimum's walker point
// (walker_point_record.hpp; curve 0, best first): which runs reached it and what the multistart
// as a whole did.

#include "cyclopt/records/json_fields.hpp"
#include "cyclopt/records/point_record.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace cyclopt::records {

struct MultistartOptimumRecord {
  std::vector<int> reached_by_starts;  // the runs (0-based) that ended at this optimum
  int kkt_successes = 0;               // runs that reached a KKT point, of `starts`
  int starts = 0;
  double wall_seconds = kUnset;        // of the whole multistart
  bool operator==(const MultistartOptimumRecord&) const = default;
};

void to_json(nlohmann::json& j, const MultistartOptimumRecord& m);
void from_json(const nlohmann::json& j, MultistartOptimumRecord& m);  // throws RecordError naming the field

template <>
inline constexpr bool is_point_values<MultistartOptimumRecord> = true;

}  // namespace cyclopt::records
