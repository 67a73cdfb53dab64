// A progress bar with ETA on stderr, drawn only when stderr is a terminal (quiet otherwise, e.g.
// in CI or when piped). Thread-safe: workers call advance(); redraws are rate-limited.
#pragma once
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace hylios {

class ProgressBar {
 public:
  ProgressBar(std::string label, std::uint64_t total);
  ~ProgressBar();
  void advance(std::uint64_t steps = 1);
  /// Draws 100 % and ends the line (also done by the destructor).
  void finish();
  /// Ends the line where the bar stands (a stopped render), without drawing 100 %.
  void stop();
  static bool enabledOnThisTerminal();

 private:
  void draw(std::uint64_t done, bool force);
  std::string label_;
  std::uint64_t total_;
  std::atomic<std::uint64_t> done_{0};
  bool enabled_;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_, lastDraw_;
  std::mutex drawMutex_;
};

}  // namespace hylios
