// Interrupt requests from the terminal or a process manager: while an InterruptSignalScope is
// alive, the first SIGINT or SIGTERM does not terminate the process but is recorded, so that a
// long computation (the `render` command) can stop at a safe point, save its work and exit with
// exitStatusFor(signal) = 128 + signal (130 for SIGINT, 143 for SIGTERM, the shells' convention).
//
// The handler is async-signal-safe: it only records the signal number in a lock-free atomic. It is
// installed with SA_RESETHAND, so a second signal of the same kind takes the default action and
// terminates the process at once. The destructor restores the handlers that were there before.
#pragma once
#include <csignal>

namespace hylios {

class InterruptSignalScope {
 public:
  /// Installs the handlers; throws std::logic_error if another scope is alive, std::runtime_error
  /// if sigaction fails. Clears any earlier request.
  InterruptSignalScope();
  ~InterruptSignalScope();
  InterruptSignalScope(const InterruptSignalScope&) = delete;
  InterruptSignalScope& operator=(const InterruptSignalScope&) = delete;

  /// Whether SIGINT or SIGTERM arrived since the scope began (safe to call from any thread).
  bool requested() const { return signalNumber() != 0; }
  /// The first signal that arrived (SIGINT or SIGTERM), 0 when none.
  int signalNumber() const;

  /// The exit status of a program stopped by `signal`: 128 + signal.
  static int exitStatusFor(int signal) { return 128 + signal; }
  /// "SIGINT", "SIGTERM", or "a signal".
  static const char* signalName(int signal);

 private:
  struct sigaction previousInt_, previousTerm_;
};

}  // namespace hylios
