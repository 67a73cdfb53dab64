// A progress bar with ETA on stderr, drawn only when stderr is a terminal (quiet otherwise, e.g.
// in CI or when piped). Thread-safe: workers call advance(); redraws are rate-limited.
#pragma once
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

#include "renderer/tracing/render_progress.h"

namespace hylios {

class ProgressBar final : public RenderProgress {
 public:
  ProgressBar(std::string label, std::uint64_t total);
  ~ProgressBar() override;
  void advance(std::uint64_t steps = 1) override;
  /// Draws 100 % and ends the line (also done by the destructor).
  void finish() override;
  /// Ends the line where the bar stands (a stopped render), without drawing 100 %.
  void stop() override;
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

/// Makes a ProgressBar per render (RenderSettings::progress, RenderOptions::progress).
RenderProgressFactory progressBarFactory();

}  // namespace hylios
