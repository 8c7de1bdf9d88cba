#include "cyclopt/nlp/parallel_columns.hpp"

#include "cyclopt/nlp/spare_core.hpp"

#include <atomic>
#include <memory>
#include <optional>

namespace cyclopt::nlp {

bool for_each_column(CachedEvaluator& evaluator, int n, const std::function<bool(int j, CachedEvaluator& at)>& column) {
  std::atomic<bool> ok{true};
  const std::unique_ptr<Problem> copy = evaluator.problem().clone();
  SolverSummary helper_counts;
  std::optional<CachedEvaluator> helper;
  if (copy) helper.emplace(*copy, helper_counts);
  // Worth a thread only for a few columns each (a walker column is a ~1.5 ms Jacobian).
  split_on_spare_core(n, copy ? 4 : n + 1, [&](int begin, int end, bool on_helper) {
    CachedEvaluator& at = on_helper ? *helper : evaluator;
    for (int j = begin; j < end && ok.load(); ++j)
      if (!column(j, at)) ok = false;
  });
  evaluator.add_counts(helper_counts);
  return ok.load();
}

}  // namespace cyclopt::nlp
