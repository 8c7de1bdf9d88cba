#pragma once
// The columns of a difference matrix (an n-column loop of evaluations with derivatives, such as
// the Hessian of the Lagrangian by differences, eq. (6.23) of seed 001) split between this thread
// and one helper thread when a core is spare (spare_core.hpp) and the problem can be copied
// (Problem::clone). Each column is a pure function of its evaluation point, so the result is
// bitwise the same as the loop's in one thread; the helper's evaluations are counted into the
// caller's evaluator. Measured on the walker (bench/results/speed_sweep_bench.txt): one SQP run
// alone on two cores (P2-shoes HMT, 1.3 m/s, 2416 iterations, a difference Hessian every 50)
// 12.4 s -> 9.7-10.4 s wall.

#include "cyclopt/nlp/cached_evaluator.hpp"

#include <functional>

namespace cyclopt::nlp {

// Calls column(j, evaluator) for j = 0 .. n-1 - with `evaluator`, or for the upper half of the
// columns with a helper's evaluator on a copy of its problem - until a call returns false. True if
// none did. Columns may run concurrently: column must only write state of its own column.
bool for_each_column(CachedEvaluator& evaluator, int n, const std::function<bool(int j, CachedEvaluator& at)>& column);

}  // namespace cyclopt::nlp
