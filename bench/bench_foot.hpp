#pragma once
// The foot a benchmark runs on: a preset name (foot_presets.hpp) or the path of a JSON foot
// specification (io/foot_spec_json.hpp), e.g. bench/feet/large_rolling_hm.json.

#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/io/foot_spec_json.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <stdexcept>
#include <string>

namespace cyclopt::bench {

inline foot::FootSpec bench_foot(const std::string& name_or_path) {
  if (!name_or_path.ends_with(".json")) return foot::foot_preset(name_or_path).spec;
  std::ifstream in(name_or_path);
  if (!in) throw std::runtime_error("cannot read foot specification " + name_or_path);
  return io::foot_spec_from_json(nlohmann::json::parse(in));
}

}  // namespace cyclopt::bench
