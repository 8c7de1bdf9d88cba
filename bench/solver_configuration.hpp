#pragma once
// The SQP/Ipopt configurations the walker benchmarks compare, by name: sqp (seed Table 6.2,
// W_1 = I then (6.25)), sqp-dh (W_1 from (6.24) on the difference Hessian), ipopt (the adapter's
// defaults), sqp-dhK (as sqp-dh, a fresh (6.24) every K iterations); a suffix -wN sets the SQP's
// progress_window to N (e.g. sqp-dh50-w200; SQP configurations only). MaxIter 3000 as the seed's
// chapter-8 experiments.
#include "cyclopt/nlp/solver_options.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace cyclopt::bench {

inline nlp::SolverOptions solver_configuration(const std::string& name_and_window) {
  const std::size_t w = name_and_window.find("-w");
  const std::string name = name_and_window.substr(0, w);
  nlp::SolverOptions o = nlp::seed_table_6_2_options();
  if (w != std::string::npos) o.sqp.progress_window = std::atoi(name_and_window.c_str() + w + 2);
  o.max_iterations = 3000;  // as the seed for chapter 8 (footnote 1 of section 8.1)
  if (name == "sqp") return o;
  if (name == "sqp-dh") {
    o.sqp.difference_hessian = true;
    return o;
  }
  if (name.rfind("sqp-dh", 0) == 0 && name.size() > 6) {  // sqp-dhK: a fresh (6.24) every K iterations
    o.sqp.difference_hessian = true;
    o.sqp.difference_hessian_every = std::atoi(name.c_str() + 6);
    return o;
  }
  if (name == "ipopt" && w == std::string::npos) {
    o.solver = nlp::SolverKind::ipopt;
    return o;
  }
  std::fprintf(stderr, "configuration '%s': expected sqp, sqp-dh, sqp-dhK (each optionally with -wN) or ipopt\n",
               name_and_window.c_str());
  std::exit(1);
}

}  // namespace cyclopt::bench
