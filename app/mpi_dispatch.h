// Dynamic load balancing of independent work items over the MPI ranks (app/mpi_session.h), for
// items of unequal cost (the sweep's cases): rank 0 hands out one item at a time to whichever rank
// asks (each rank asks again when it sends a result), and also computes items itself on a second
// thread; results reach rank 0 in completion order, `onResult` runs there (on the main thread) for
// each. Without distribution the items run one after another on this process (each may use every
// thread inside). What a result is does not depend on who computed it, so the caller's output can
// be put together in item order and be the same at any number of ranks.
#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace hylios {

/// Every rank calls it with the same `items`. `compute(item)` runs on any rank; `onResult(item,
/// result)` on rank 0 only. An exception on rank 0 is rethrown after its compute thread has ended
/// (the job is then aborted by main, app/mpi_session.h); one on another rank propagates there.
void dispatchAcrossRanks(const std::vector<std::size_t>& items,
                         const std::function<std::string(std::size_t item)>& compute,
                         const std::function<void(std::size_t item, const std::string&)>& onResult);

}  // namespace hylios
