#include "cyclopt/nlp/spare_core.hpp"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <exception>
#include <thread>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace cyclopt::nlp {

namespace {
std::atomic<SpareCoreRule> rule{SpareCoreRule::measured};
}  // namespace

void set_spare_core_rule(SpareCoreRule r) { rule = r; }

bool core_is_spare() {
  if (rule.load() != SpareCoreRule::measured) return rule.load() == SpareCoreRule::always;
  const unsigned cores = std::thread::hardware_concurrency();
  if (cores < 2) return false;
  std::FILE* f = std::fopen("/proc/loadavg", "r");
  if (!f) return false;
  double one, five, fifteen;
  unsigned runnable = 0, total = 0;
  const bool read = std::fscanf(f, "%lf %lf %lf %u/%u", &one, &five, &fifteen, &runnable, &total) == 5;
  std::fclose(f);
  return read && runnable >= 1 && runnable < cores;
}

void split_on_spare_core(int n, int min_split, const std::function<void(int begin, int end, bool helper)>& work) {
  if (n < min_split || n < 2 || !core_is_spare()) {
    work(0, n, false);
    return;
  }
  const int half = n / 2;
  std::exception_ptr helper_failure;
  std::thread helper([&] {
    try {
      work(half, n, true);
    } catch (...) {
      helper_failure = std::current_exception();
    }
  });
  std::exception_ptr own_failure;
  try {
    work(0, half, false);
  } catch (...) {
    own_failure = std::current_exception();
  }
  helper.join();
  if (own_failure) std::rethrow_exception(own_failure);
  if (helper_failure) std::rethrow_exception(helper_failure);
}

void lower_thread_priority() {
  const auto thread = static_cast<id_t>(::syscall(SYS_gettid));
  errno = 0;
  const int nice = ::getpriority(PRIO_PROCESS, thread);
  if (errno == 0) ::setpriority(PRIO_PROCESS, thread, nice + 10);
}

}  // namespace cyclopt::nlp
