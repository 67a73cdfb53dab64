#include "app/mpi_dispatch.h"

#include <chrono>
#include <cstdint>
#include <cstring>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>

#include "app/mpi_session.h"

namespace hylios {
namespace {

enum Tag : int { kReady = 1, kResult = 2, kItem = 3, kStop = 4 };

std::string indexBytes(std::uint64_t index) {
  return std::string(reinterpret_cast<const char*>(&index), sizeof index);
}

std::uint64_t indexOf(const std::string& bytes) {
  std::uint64_t index = 0;
  std::memcpy(&index, bytes.data(), sizeof index);
  return index;
}

void runWorker(const std::function<std::string(std::size_t)>& compute) {
  sendTo(0, kReady, "");
  while (true) {
    const MpiMessage message = receiveFrom(0);
    if (message.tag == kStop) return;
    const std::uint64_t item = indexOf(message.bytes);
    sendTo(0, kResult, indexBytes(item) + compute(static_cast<std::size_t>(item)));
  }
}

void runRoot(const std::vector<std::size_t>& items,
             const std::function<std::string(std::size_t)>& compute,
             const std::function<void(std::size_t, const std::string&)>& onResult) {
  std::mutex mutex;
  std::deque<std::size_t> queue(items.begin(), items.end());
  std::deque<std::pair<std::size_t, std::string>> localResults;
  std::exception_ptr localError;
  auto next = [&](std::size_t& item) {
    std::lock_guard<std::mutex> lock(mutex);
    if (queue.empty() || localError) return false;
    item = queue.front();
    queue.pop_front();
    return true;
  };
  std::thread local([&] {  // rank 0's own share, computed beside the dispatching main thread
    try {
      std::size_t item = 0;
      while (next(item)) {
        std::string result = compute(item);
        std::lock_guard<std::mutex> lock(mutex);
        localResults.emplace_back(item, std::move(result));
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      localError = std::current_exception();
    }
  });
  std::size_t received = 0;
  int stopped = 0;
  const int workers = MpiSession::size() - 1;
  try {
    while (received < items.size() || stopped < workers) {
      bool busy = false;
      std::deque<std::pair<std::size_t, std::string>> results;
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (localError) std::rethrow_exception(localError);
        results.swap(localResults);
      }
      for (const auto& [item, result] : results) {
        onResult(item, result);
        ++received;
        busy = true;
      }
      MpiMessage message;
      if (receiveIfAny(message)) {
        busy = true;
        if (message.tag == kResult) {
          onResult(static_cast<std::size_t>(indexOf(message.bytes)),
                   message.bytes.substr(sizeof(std::uint64_t)));
          ++received;
        }
        std::size_t item = 0;
        if (next(item)) {
          sendTo(message.source, kItem, indexBytes(item));
        } else {
          sendTo(message.source, kStop, "");
          ++stopped;
        }
      }
      if (!busy) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  } catch (...) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      queue.clear();  // the compute thread stops after its current item
    }
    local.join();
    throw;
  }
  local.join();
  if (localError) std::rethrow_exception(localError);
}

}  // namespace

void dispatchAcrossRanks(const std::vector<std::size_t>& items,
                         const std::function<std::string(std::size_t item)>& compute,
                         const std::function<void(std::size_t, const std::string&)>& onResult) {
  if (!MpiSession::distributed()) {
    for (std::size_t item : items) onResult(item, compute(item));
    return;
  }
  if (MpiSession::isRoot())
    runRoot(items, compute, onResult);
  else
    runWorker(compute);
}

}  // namespace hylios
