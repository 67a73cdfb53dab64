// How a render reports its progress without drawing anything itself: the caller (app/'s progress
// bar) passes a factory; the integrator makes one display per render and advances it from its
// worker threads, so implementations must be thread-safe in advance().
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace hylios {

class RenderProgress {
 public:
  virtual ~RenderProgress() = default;
  virtual void advance(std::uint64_t steps) = 0;
  /// The render reached its target.
  virtual void finish() = 0;
  /// The render was stopped before its target.
  virtual void stop() = 0;
};

/// Makes the display of one render of `total` steps; empty: no display.
using RenderProgressFactory =
    std::function<std::unique_ptr<RenderProgress>(const std::string& label, std::uint64_t total)>;

}  // namespace hylios
