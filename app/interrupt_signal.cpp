#include "app/interrupt_signal.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include "renderer/tracing/exit_table_cache.h"

namespace hylios {
namespace {

// Written by the signal handler, read by the render loop. Lock-free, so the store is
// async-signal-safe.
std::atomic<int> pendingSignal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal flag must be lock-free");
std::atomic<bool> scopeAlive{false};

/// Keeps the first signal (a later one of the other kind is not recorded over it).
/// write(2) of a literal, ignoring the result (async-signal-safe).
template <std::size_t N>
void say(const char (&text)[N]) {
  const ssize_t ignored = ::write(STDERR_FILENO, text, N - 1);
  (void)ignored;
}

/// Keeps the first signal, and says at once what happens now: the work stops at the next safe
/// point, after the exit table being built if there is one (a build is not cut short: the table
/// is cached for the next run). A second signal of the same kind stops at once (SA_RESETHAND).
extern "C" void recordInterruptSignal(int signal) {
  int none = 0;
  if (!pendingSignal.compare_exchange_strong(none, signal, std::memory_order_relaxed)) return;
  if (signal == SIGINT)
    say("\nhylios: SIGINT received");
  else
    say("\nhylios: SIGTERM received");
  if (ExitTableCache::buildsInProgress() > 0)
    say("; finishing the exit table being built (it is cached for the next run), then stopping; "
        "send it again to stop at once\n");
  else
    say("; stopping after the current sample pass; send it again to stop at once\n");
}

void install(int signal, struct sigaction* previous) {
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = recordInterruptSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  if (::sigaction(signal, &action, previous) != 0)
    throw std::runtime_error(std::string("cannot install the handler of ") +
                             InterruptSignalScope::signalName(signal) + ": " +
                             std::strerror(errno));
}

}  // namespace

InterruptSignalScope::InterruptSignalScope() {
  if (scopeAlive.exchange(true))
    throw std::logic_error("InterruptSignalScope: another scope is alive");
  pendingSignal.store(0);
  try {
    install(SIGINT, &previousInt_);
    try {
      install(SIGTERM, &previousTerm_);
    } catch (...) {
      ::sigaction(SIGINT, &previousInt_, nullptr);
      throw;
    }
  } catch (...) {
    scopeAlive.store(false);
    throw;
  }
}

InterruptSignalScope::~InterruptSignalScope() {
  ::sigaction(SIGTERM, &previousTerm_, nullptr);
  ::sigaction(SIGINT, &previousInt_, nullptr);
  scopeAlive.store(false);
}

int InterruptSignalScope::signalNumber() const {
  return pendingSignal.load(std::memory_order_relaxed);
}

const char* InterruptSignalScope::signalName(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "a signal";
}

}  // namespace hylios
