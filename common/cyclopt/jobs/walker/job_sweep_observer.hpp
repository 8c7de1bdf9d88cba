#pragma once
// The observer (studies/speed_sweep_observer.hpp) a job attaches to a speed sweep it runs: the
// sweep resumes from the job's journal (sweep_checkpoints.hpp), its points go to `point` (false
// stops the sweep) and its progress to `progress` (one call at a time, speed_sweep.hpp).

#include "cyclopt/jobs/walker/sweep_checkpoints.hpp"
#include "cyclopt/service/job_context.hpp"
#include "cyclopt/studies/speed_sweep_observer.hpp"

#include <functional>
#include <utility>

namespace cyclopt::jobs {

class JobSweepObserver final : public studies::SpeedSweepObserver {
 public:
  using Progress = std::function<void(const studies::SweepProgress&)>;
  JobSweepObserver(service::JobContext& ctx, continuation::PointCallback point, Progress progress)
      : ctx_(ctx), point_(std::move(point)), progress_(std::move(progress)) {}
  bool on_point(const continuation::CurvePoint& c) override { return point_(c); }
  void on_progress(const studies::SweepProgress& p) override { progress_(p); }
  studies::SweepJournal journal() override { return sweep_journal(ctx_); }

 private:
  service::JobContext& ctx_;
  const continuation::PointCallback point_;
  const Progress progress_;
};

}  // namespace cyclopt::jobs
