// One walker gait optimisation from the automatic starting gait, per solver, with Ipopt options
// given on the command line: what the Ipopt settings for the walker (ipopt_solver.hpp) were
// measured with. Prints termination, iterations, evaluations, objective, KKT error and time.
//
// usage: walker_solver_bench FOOT SPEED SOLVER [max_iterations] [name=value ...]
//   FOOT: a preset name (cyclopt-foot --list-presets); SOLVER: sqp or ipopt; name=value: Ipopt
//   options (integer, number or string, recognised in that order); the word difference_hessian
//   sets SqpOptions::difference_hessian, difference_start IpoptOptions::difference_hessian_start, refresh=K
//   difference_hessian_every = K of both solvers, band=W the positive_power_band of f_mech (W), the word
//   lbfgs Ipopt's limited-memory Hessian instead of the adapter's damped BFGS, the word f_usq the
//   objective (5.101) instead of f_mech (5.102), the word verbose one line per iteration.
#include "bench_foot.hpp"
#include "cyclopt/walker/gait_optimisation.hpp"
#include "machine_info.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace cyclopt;

namespace {

void add_ipopt_option(nlp::IpoptOptions& o, const std::string& assignment) {
  const std::size_t eq = assignment.find('=');
  const std::string name = assignment.substr(0, eq), value = assignment.substr(eq + 1);
  char* end = nullptr;
  const long integer = std::strtol(value.c_str(), &end, 10);
  if (*end == '\0') {
    o.integer_options[name] = static_cast<int>(integer);
    return;
  }
  const double number = std::strtod(value.c_str(), &end);
  if (*end == '\0')
    o.numeric_options[name] = number;
  else
    o.string_options[name] = value;
}

// FNV-1a (64 bit) of the bytes of v.
std::uint64_t fnv1a(const Eigen::VectorXd& v) {
  std::uint64_t h = 14695981039346656037ull;
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    unsigned char bytes[sizeof(double)];
    std::memcpy(bytes, &v[i], sizeof bytes);
    for (unsigned char b : bytes) h = (h ^ b) * 1099511628211ull;
  }
  return h;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: walker_solver_bench FOOT SPEED SOLVER [max_iterations] [name=value ...]\n");
    return 1;
  }
  const std::string foot_name = argv[1];
  const walker::WalkerModel<double> model = walker::make_walker_model(cyclopt::bench::bench_foot(foot_name));
  walker::GaitProblemOptions po{walker::Objective::mechanical, std::atof(argv[2]), walker::Quadrature::trapezoid, {}};
  nlp::SolverOptions so = nlp::seed_table_6_2_options();
  so.solver = nlp::parse_solver_kind(argv[3]);
  if (argc > 4) so.max_iterations = std::atoi(argv[4]);
  bool bits = false;
  for (int k = 5; k < argc; ++k)
    if (std::string(argv[k]) == "bits")
      bits = true;
    else if (std::string(argv[k]) == "difference_hessian")
      so.sqp.difference_hessian = true;
    else if (std::string(argv[k]) == "difference_start")
      so.ipopt.difference_hessian_start = true;
    else if (std::string(argv[k]).rfind("refresh=", 0) == 0)  // a fresh (6.24) every K iterations, both solvers
      so.sqp.difference_hessian_every = so.ipopt.difference_hessian_every = std::atoi(argv[k] + 8);
    else if (std::string(argv[k]).rfind("band=", 0) == 0)  // GaitProblemOptions::positive_power_band (W)
      po.positive_power_band = std::atof(argv[k] + 5);
    else if (std::string(argv[k]) == "lbfgs")
      so.ipopt.hessian = nlp::IpoptHessian::limited_memory;
    else if (std::string(argv[k]) == "verbose")
      so.print_level = 1;
    else if (std::string(argv[k]) == "f_usq")
      po.objective = walker::Objective::squared_torque;
    else
      add_ipopt_option(so.ipopt, argv[k]);
  const walker::GaitOptimum r = walker::optimise_gait(model, po, so);
  const nlp::SolverSummary& s = r.summary;
  std::printf("%s %s %.2f m/s %s: %s, %d it, %d f + %d J evaluations (%d failed), f %.10f (start %.6f), kkt %.2e, viol %.2e, "
              "%.1f s  [%s]\n",
              cyclopt::bench::machine_line().c_str(), foot_name.c_str(), po.speed, argv[3], nlp::to_string(s.termination),
              s.iterations, s.function_evaluations, s.jacobian_evaluations, s.failed_evaluations, s.objective,
              r.start_objective, s.kkt_error, s.constraint_violation, s.wall_seconds, s.message.c_str());
  if (bits)
    std::printf("bits: f %a, kkt %a, viol %a, z (%ld) fnv1a %016llx\n", s.objective, s.kkt_error, s.constraint_violation,
                static_cast<long>(r.z.size()), static_cast<unsigned long long>(fnv1a(r.z)));
}
