// The worker-thread limit of a command or a render (--threads): TBB runs at most `threads` workers
// while a ThreadLimit lives. Results never depend on it: every estimator is deterministic at any
// thread count.
#pragma once
#include <tbb/global_control.h>

#include <cstddef>
#include <optional>

namespace hylios {

class ThreadLimit {
 public:
  /// threads ≤ 0: no limit (all cores).
  explicit ThreadLimit(int threads) {
    if (threads > 0)
      control_.emplace(tbb::global_control::max_allowed_parallelism,
                       static_cast<std::size_t>(threads));
  }

 private:
  std::optional<tbb::global_control> control_;
};

}  // namespace hylios
