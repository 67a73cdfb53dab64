#include "app/progress_bar.h"

#include <cstdio>
#include <unistd.h>

#include "app/mpi_session.h"

namespace hylios {

ProgressBar::ProgressBar(std::string label, std::uint64_t total)
    : label_(std::move(label)),
      total_(total == 0 ? 1 : total),
      enabled_(enabledOnThisTerminal()),
      start_(std::chrono::steady_clock::now()),
      lastDraw_(start_) {}

ProgressBar::~ProgressBar() { finish(); }

bool ProgressBar::enabledOnThisTerminal() {
  return ::isatty(STDERR_FILENO) == 1 && MpiSession::isRoot();  // one bar for an MPI job
}

void ProgressBar::advance(std::uint64_t steps) {
  const std::uint64_t done = done_.fetch_add(steps) + steps;
  if (enabled_) draw(done, false);
}

void ProgressBar::finish() {
  if (!enabled_ || finished_) return;
  draw(total_, true);
  std::fputc('\n', stderr);
  finished_ = true;
}

void ProgressBar::stop() {
  if (!enabled_ || finished_) return;
  draw(done_.load(), true);
  std::fputc('\n', stderr);
  finished_ = true;
}

void ProgressBar::draw(std::uint64_t done, bool force) {
  std::unique_lock<std::mutex> lock(drawMutex_, std::try_to_lock);
  if (!lock.owns_lock() || finished_) return;
  const auto now = std::chrono::steady_clock::now();
  if (!force && now - lastDraw_ < std::chrono::milliseconds(100)) return;
  lastDraw_ = now;
  const double fraction = static_cast<double>(done) / static_cast<double>(total_);
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(fraction * kWidth);
  std::string bar(static_cast<std::size_t>(filled), '=');
  bar.resize(kWidth, ' ');
  std::fprintf(stderr, "\r%s [%s] %5.1f%%  %.0fs elapsed, ETA %.0fs ", label_.c_str(), bar.c_str(),
               100.0 * fraction, elapsed, eta);
  std::fflush(stderr);
}

RenderProgressFactory progressBarFactory() {
  return [](const std::string& label, std::uint64_t total) -> std::unique_ptr<RenderProgress> {
    return std::make_unique<ProgressBar>(label, total);
  };
}

}  // namespace hylios
