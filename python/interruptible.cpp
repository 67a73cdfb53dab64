#include "python/interruptible.h"

#include <pybind11/pybind11.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

namespace py = pybind11;

namespace hylios::python {

void runInterruptible(const std::function<void(const StopFlag&)>& work, bool cancelTasks) {
  StopFlag stop;
  tbb::task_group_context context;
  std::exception_ptr failure;
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    std::mutex mutex;
    std::condition_variable doneSignal;
    bool done = false;
    std::thread worker([&] {
      try {
        // One outer task with its own context: nested parallel algorithms bind to it, so
        // cancel_group_execution() skips their tasks that have not started.
        tbb::parallel_for(
            tbb::blocked_range<int>(0, 1), [&](const tbb::blocked_range<int>&) { work(stop); },
            context);
      } catch (...) {
        failure = std::current_exception();
      }
      const std::lock_guard<std::mutex> lock(mutex);
      done = true;
      doneSignal.notify_all();
    });
    std::unique_lock<std::mutex> lock(mutex);
    while (!done) {
      doneSignal.wait_for(lock, std::chrono::milliseconds(50));
      if (done || interrupted) continue;
      lock.unlock();
      {
        py::gil_scoped_acquire acquire;
        if (PyErr_CheckSignals() != 0) interrupted = true;  // the error stays set on this thread
      }
      if (interrupted) {
        stop.requested = true;
        if (cancelTasks) context.cancel_group_execution();
      }
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  if (interrupted) throw py::error_already_set();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace hylios::python
