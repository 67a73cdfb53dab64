// Running a computation of the Python module without the GIL, interruptibly: the work runs on a
// worker thread while the calling thread polls Python's signal handlers every 50 ms.
#pragma once
#include <atomic>
#include <functional>

namespace hylios::python {

/// What a computation may ask while it runs: whether Python has a pending interrupt.
struct StopFlag {
  std::atomic<bool> requested{false};
  bool operator()() const { return requested.load(std::memory_order_relaxed); }
};

/// Runs `work` on a worker thread with the GIL released, polling Python's signal handlers from the
/// calling thread. On a pending signal (Ctrl-C: KeyboardInterrupt) the stop flag is raised and,
/// when `cancelTasks`, the TBB tasks of the work that have not started are cancelled (only for work
/// whose partial results are thrown away and that fills no cache); the Python error is raised once
/// the worker has returned. An exception of the work is rethrown (pybind11 translates it).
void runInterruptible(const std::function<void(const StopFlag&)>& work, bool cancelTasks);

}  // namespace hylios::python
