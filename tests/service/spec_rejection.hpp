#pragma once
// The built-in job kinds' verdict on a spec, for every kind's refusal tests: rejection() gives
// the SpecError's what() ("field: message", errors/spec_error.hpp), rejected_field() its field;
// both "accepted" when the spec passes.
#include "cyclopt/service/job_spec.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace cyclopt::testing {

inline std::optional<SpecError> spec_error(const nlohmann::json& spec) {
  static const service::JobKindRegistry kinds = jobs::builtin_job_kinds();
  try {
    service::validate_job_spec(spec, kinds);
  } catch (const SpecError& e) {
    return e;
  }
  return std::nullopt;
}

inline std::string rejection(const nlohmann::json& spec) {
  const std::optional<SpecError> e = spec_error(spec);
  return e ? e->what() : "accepted";
}

inline std::string rejected_field(const nlohmann::json& spec) {
  const std::optional<SpecError> e = spec_error(spec);
  return e ? e->field() : "accepted";
}

}  // namespace cyclopt::testing
