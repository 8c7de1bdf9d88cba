// Ipopt as continuation corrector (issue 5, "Ipopt warm start"): the SQP optimum at one speed is
// the start of an Ipopt solve at the next speed, cold (x only: Ipopt's own initial multipliers
// and mu) and warm (x and the SQP's multipliers, IpoptOptions::warm_start), with the SQP from
// the same x for reference. Prints termination, iterations, evaluations, objective and time.
//
// usage: walker_warm_start_bench [foot = point] [from = 1.3] [to = 1.4] [f_usq]
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/walker/gait_optimisation.hpp"
#include "machine_info.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

using namespace cyclopt;

namespace {

void print(const char* what, const nlp::SolverSummary& s) {
  std::printf("  %-28s %-15s %4d it  %4d f + %4d J  f %.10f  kkt %.1e  viol %.1e  %.2f s\n", what,
              nlp::to_string(s.termination), s.iterations, s.function_evaluations, s.jacobian_evaluations, s.objective,
              s.kkt_error, s.constraint_violation, s.wall_seconds);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string foot_name = argc > 1 ? argv[1] : "point";
  const double from = argc > 2 ? std::atof(argv[2]) : 1.3, to = argc > 3 ? std::atof(argv[3]) : 1.4;
  const bool usq = argc > 4 && std::string(argv[4]) == "f_usq";
  const walker::WalkerModel<double> model = walker::make_walker_model(foot::foot_preset(foot_name).spec);
  walker::GaitProblemOptions po{usq ? walker::Objective::squared_torque : walker::Objective::mechanical, from,
                                walker::Quadrature::trapezoid, {}};
  const nlp::SolverOptions sqp = nlp::seed_table_6_2_options();
  const walker::GaitOptimum start = walker::optimise_gait(model, po, sqp);
  std::printf("%s; %s %s, SQP at %.2f m/s from the starting gait: %s, f %.10f, %d it\n",
              cyclopt::bench::machine_line().c_str(), foot_name.c_str(), usq ? "f_usq" : "f_mech", from,
              nlp::to_string(start.summary.termination), start.summary.objective, start.summary.iterations);
  if (!start.summary.success()) return 1;
  po.speed = to;
  const Eigen::VectorXd x = start.z;  // no free parameters: z = x
  std::printf("from that optimum at %.2f m/s:\n", to);
  print("SQP", walker::optimise_gait(model, po, sqp, x).summary);
  nlp::SolverOptions ipopt = sqp;
  ipopt.solver = nlp::SolverKind::ipopt;
  print("Ipopt cold (x only)", walker::optimise_gait(model, po, ipopt, x).summary);
  ipopt.ipopt.warm_start = nlp::IpoptWarmStart{start.summary.equality_multipliers, start.summary.inequality_multipliers,
                                               start.summary.bound_multipliers};
  print("Ipopt warm (x, multipliers)", walker::optimise_gait(model, po, ipopt, x).summary);
  ipopt.ipopt.difference_hessian_start = true;
  print("  + difference Hessian start", walker::optimise_gait(model, po, ipopt, x).summary);
}
