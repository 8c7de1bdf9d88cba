#pragma once
// A core nobody computes on right now, and work split onto it. core_is_spare(): the kernel's count
// of runnable threads (/proc/loadavg, 4th field, all processes, this thread included) is below the
// hardware threads. A single-threaded phase (a continuation run, the last long run of a
// multistart) then hands half of a loop of independent evaluations to a helper thread without
// oversubscribing the cores that other threads or processes (the other multistart workers, a
// second job) already use. A snapshot: a thread blocked for a moment can make a core look spare;
// false where /proc is missing.

#include <functional>

namespace cyclopt::nlp {

bool core_is_spare();

// How core_is_spare() decides: from /proc/loadavg (the default), or always / never - for tests
// that compare both ways and benchmarks that measure the difference. Process-wide.
enum class SpareCoreRule { measured, always, never };
void set_spare_core_rule(SpareCoreRule rule);

// Calls work(0, n, false) in this thread; or, when n >= min_split and a core is spare,
// work(0, n / 2, false) here and work(n / 2, n, true) in a helper thread (the flag says which).
// Waits for both; an exception of either is rethrown here. work must touch only state of its own
// range or state it synchronises.
void split_on_spare_core(int n, int min_split, const std::function<void(int begin, int end, bool helper)>& work);

// Lowers the calling thread's scheduling priority (nice + 10; on Linux a per-thread value that the
// threads it starts inherit), so that it and its workers take the cores the process's other
// threads leave idle rather than sharing them equally: for work beside a study's critical path
// (the foot design's sweep of the design beside the free-foot continuation and the low-speed
// design's sweep, studies/foot_design.cpp). Timing only: results do not depend on it. Where the
// OS refuses, nothing changes.
void lower_thread_priority();

}  // namespace cyclopt::nlp
