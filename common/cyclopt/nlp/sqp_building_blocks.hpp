#pragma once
// The pieces of the seed's SQP (seed 001 ch. 6) that other modules may reuse, e.g. the QP predictor
// of continuation/ (Algorithm 2 takes two SQP steps on the QP of eq. 7.5): the optimality measures
// (kkt_measures.hpp), the l1 merit function and its model (l1_merit.hpp, section 6.2.1), the QP
// and LP subproblems (sqp_subproblems.hpp, section 6.2.1), the least-squares projections onto the
// active constraints (active_set_projections.hpp, sections 6.2.2-6.2.3), the damped BFGS update
// (damped_bfgs.hpp, section 6.2.3) and the nonsmooth stationarity test of the objective's kinked terms
// (clarke_stationarity.hpp, issue 52). Modules outside nlp include this header, not the pieces,
// and reach the solvers themselves through solve.hpp.

#include "cyclopt/nlp/active_set_projections.hpp"
#include "cyclopt/nlp/clarke_stationarity.hpp"
#include "cyclopt/nlp/damped_bfgs.hpp"
#include "cyclopt/nlp/kkt_measures.hpp"
#include "cyclopt/nlp/l1_merit.hpp"
#include "cyclopt/nlp/sqp_subproblems.hpp"
