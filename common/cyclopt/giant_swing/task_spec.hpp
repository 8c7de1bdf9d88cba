#pragma once
// The four motion tasks of seed 000, chapter 5, as plain structs:
//
//   single_swing       (5.1): start in the handstand at omega, return to phi'/omega = 1, alpha = 0,
//                             alpha' = 0 at phi = 2 pi; one round evaluated (eq. 4.10).
//   periodic_sequence  (5.2): the same start and target, R_max rounds evaluated (eq. 4.14).
//   accelerating       (5.3): start at omega/2, reach omega after one swing.
//   decelerating       (5.4): start at 2 omega, reach omega after one swing.
//
// Their JSON form (what users write), with the admissible range of every field, is read and
// written in io/task_spec_json.hpp.

#include "cyclopt/giant_swing/evaluation.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>

namespace cyclopt::giant_swing {

enum class TaskKind { single_swing, periodic_sequence, accelerating, decelerating };
const char* to_string(TaskKind kind);

// Settings of the seed's multistage Nelder-Mead loop (ch. 4.3).
struct OptimiserSettings {
  int support_points = 4;          // 2^n at the start, 4..64
  int max_support_points = 16;     // doubling stops here, <= 64
  double initial_step = 20.0;      // Nm, edge lambda of the start simplex (eq. 4.2)
  double min_step = 1.0;           // Nm, halving of lambda stops below this
  double f_tolerance = 1e-10;      // Nelder-Mead spread tolerance
  // Start and end vector count as equal (ch. 4.3, step 2) when they differ by less than this,
  // relative; the seed compared float vectors (~1e-7).
  double same_vector_tolerance = 1e-6;
  int max_evaluations_per_run = 4000;
  int max_evaluations_per_stage = 8000;  // per value of lambda: then halve it anyway
  int max_evaluations = 60000;     // whole loop
  std::optional<Eigen::VectorXd> start_vector;  // Nm at the support points; default: zero (ch. 5)
};

struct TaskSpec {
  TaskKind kind = TaskKind::single_swing;
  double omega = kReferenceRate;         // rad/s, target phi' in the handstand
  double initial_rate = kReferenceRate;  // rad/s, phi' at the start
  int rounds = 1;                        // rounds evaluated (R_max of eq. 4.14)
  EvaluationWeights weights;
  AdmissibleRanges ranges;
  double relative_tolerance = 1e-9;      // Cash-Karp error tolerance
  OptimiserSettings optimiser;
  std::string name;
};

// The chapter-5 task with the seed's settings (start rate, rounds; weights 100/10/1, no jerk).
TaskSpec default_task(TaskKind kind);

// The start state (handstand, phi = alpha = alpha' = 0) and the simulation settings of a task.
State<double> initial_state(const TaskSpec& spec);
SimulationOptions simulation_options(const TaskSpec& spec);

}  // namespace cyclopt::giant_swing
