#pragma once
// The giant-swing fields of a job spec (scene "giant_swing", task "giant_swing"; seed 000):
//
//   {"scene": "giant_swing", "task": "giant_swing", "motion": "accelerating", "method": "bezier",
//    "options": {"free_coefficients": 8}, "solver": {"solver": "ipopt"}}
//
// motion: single | periodic | accelerating | decelerating (the four tasks of ch. 5);
// method: seed (part A: piecewise-linear M_alpha(phi), multistage Nelder-Mead, eq. 4.9/4.10/4.14)
// or bezier (part B: minimum jerk on alpha = b(phi), Ipopt by default; periodic: the closed swing
// repeated in the full model). options (all optional): the task fields of
// giant_swing_task.schema.json except "task" (omega_deg_s, initial_rate_deg_s, rounds,
// alpha_min_deg, alpha_max_deg; for seed also weights, alpha_ddot_max_deg_s2, relative_tolerance,
// optimiser), and for bezier free_coefficients [4, 12] (default 8), steps [10, 2000] (default 200),
// min_rate_fraction [0, 0.9] (default 0.05). Errors name the field as "options.<key>".

#include "cyclopt/giant_swing/minimum_jerk_swing.hpp"
#include "cyclopt/giant_swing/task_spec.hpp"
#include "cyclopt/service/common_job_fields.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace cyclopt::jobs {

enum class GiantSwingMethod { seed, bezier };

struct GiantSwingJob {
  std::string motion;          // as in the spec
  GiantSwingMethod method = GiantSwingMethod::bezier;
  giant_swing::TaskSpec task;  // the chapter-5 task with the options applied
  giant_swing::MinimumJerkSettings bezier;  // method bezier: problem options and solver
};

const std::vector<std::string>& giant_swing_job_fields();  // motion, method, options

// The giant-swing fields, with the solver of the common fields; throws SpecError naming the first
// invalid field.
GiantSwingJob parse_giant_swing_job(const nlohmann::json& spec, const service::CommonJobFields& common);

// The parsed job back in the spec's form with every default filled in (the kind's part of the
// resolved spec, resolved_spec.hpp): motion, method, every option of the method (the task fields
// as io/task_spec_json.hpp writes them) and, for bezier, the whole solver block. Parsing it again
// gives the same job.
nlohmann::json giant_swing_job_json(const GiantSwingJob& job);

}  // namespace cyclopt::jobs
