#include "cyclopt/giant_swing/task_spec.hpp"

namespace cyclopt::giant_swing {

const char* to_string(TaskKind kind) {
  switch (kind) {
    case TaskKind::single_swing: return "single_swing";
    case TaskKind::periodic_sequence: return "periodic_sequence";
    case TaskKind::accelerating: return "accelerating";
    case TaskKind::decelerating: return "decelerating";
  }
  return "unknown";
}

TaskSpec default_task(TaskKind kind) {
  TaskSpec s;
  s.kind = kind;
  s.name = to_string(kind);
  if (kind == TaskKind::periodic_sequence) s.rounds = 10;                   // ch. 5.2: 10 rounds evaluated
  if (kind == TaskKind::accelerating) s.initial_rate = 0.5 * s.omega;       // ch. 5.3: 20 deg/s
  if (kind == TaskKind::decelerating) s.initial_rate = 2.0 * s.omega;       // ch. 5.4: 80 deg/s
  return s;
}

State<double> initial_state(const TaskSpec& spec) { return State<double>(0.0, 0.0, spec.initial_rate, 0.0); }

SimulationOptions simulation_options(const TaskSpec& spec) {
  SimulationOptions o;
  o.integrator.relative_tolerance = spec.relative_tolerance;
  o.integrator.absolute_tolerance = 1e-3 * spec.relative_tolerance;
  o.ranges = spec.ranges;
  return o;
}

}  // namespace cyclopt::giant_swing
