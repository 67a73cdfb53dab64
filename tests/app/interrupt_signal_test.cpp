// InterruptSignalScope: SIGINT/SIGTERM are recorded instead of terminating; the first signal is
// kept; a second signal of the same kind would take the default action (SA_RESETHAND); the
// previous handlers come back when the scope ends; one scope at a time.
#include <gtest/gtest.h>

#include <csignal>
#include <optional>
#include <stdexcept>
#include <string>

#include "app/interrupt_signal.h"
#include "renderer/tracing/exit_table_cache.h"

using hylios::InterruptSignalScope;

namespace {

void (*handlerOf(int signal))(int) {
  struct sigaction current;
  sigaction(signal, nullptr, &current);
  return current.sa_handler;
}

/// What an InterruptSignalScope prints on stderr when `signal` arrives (during an exit-table
/// build when `building`).
std::string acknowledgementOf(int signal, bool building) {
  testing::internal::CaptureStderr();
  {
    std::optional<hylios::ExitTableCache::BuildInProgress> build;
    if (building) build.emplace();
    const InterruptSignalScope scope;
    EXPECT_EQ(std::raise(signal), 0);
  }
  return testing::internal::GetCapturedStderr();
}

}  // namespace

TEST(InterruptSignalScope, RecordsTheFirstSignalAndResetsItsHandler) {
  const auto before = handlerOf(SIGINT);
  {
    const InterruptSignalScope scope;
    EXPECT_FALSE(scope.requested());
    EXPECT_EQ(scope.signalNumber(), 0);
    EXPECT_NE(handlerOf(SIGINT), SIG_DFL);
    ASSERT_EQ(std::raise(SIGINT), 0);  // handled synchronously in this thread
    EXPECT_TRUE(scope.requested());
    EXPECT_EQ(scope.signalNumber(), SIGINT);
    EXPECT_EQ(handlerOf(SIGINT), SIG_DFL);  // a second Ctrl-C terminates
    ASSERT_EQ(std::raise(SIGTERM), 0);
    EXPECT_EQ(scope.signalNumber(), SIGINT);  // the first signal is kept
  }
  EXPECT_EQ(handlerOf(SIGINT), before);
}

TEST(InterruptSignalScope, SigtermAndRestoringPreviousHandlers) {
  std::signal(SIGTERM, SIG_IGN);
  {
    const InterruptSignalScope scope;
    EXPECT_NE(handlerOf(SIGTERM), SIG_IGN);
    ASSERT_EQ(std::raise(SIGTERM), 0);
    EXPECT_EQ(scope.signalNumber(), SIGTERM);
  }
  EXPECT_EQ(handlerOf(SIGTERM), SIG_IGN);
  std::signal(SIGTERM, SIG_DFL);
  const InterruptSignalScope fresh;  // a new scope starts without a request
  EXPECT_FALSE(fresh.requested());
}

TEST(InterruptSignalScope, OneScopeAtATime) {
  const InterruptSignalScope scope;
  EXPECT_THROW(InterruptSignalScope second, std::logic_error);
}

TEST(InterruptSignalScope, ExitStatusAndNames) {
  EXPECT_EQ(InterruptSignalScope::exitStatusFor(SIGINT), 130);
  EXPECT_EQ(InterruptSignalScope::exitStatusFor(SIGTERM), 143);
  EXPECT_STREQ(InterruptSignalScope::signalName(SIGINT), "SIGINT");
  EXPECT_STREQ(InterruptSignalScope::signalName(SIGTERM), "SIGTERM");
}

// Issue 13 row 8: the first signal is acknowledged at once, and during an exit-table build it
// says that the table is finished (and cached) before the command stops.
TEST(InterruptSignalScope, SaysAtOnceWhatItFinishesBeforeStopping) {
  const std::string duringBuild = acknowledgementOf(SIGINT, true);
  EXPECT_NE(duringBuild.find("SIGINT received; finishing the exit table being built"),
            std::string::npos)
      << duringBuild;
  const std::string otherwise = acknowledgementOf(SIGTERM, false);
  EXPECT_NE(otherwise.find("SIGTERM received; stopping after the current sample pass"),
            std::string::npos)
      << otherwise;
}
