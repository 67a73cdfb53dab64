// The processes of one hylios job started by an MPI launcher (mpirun, srun; Open MPI), or this
// process alone: when hylios was built without MPI (HYLIOS_MPI=OFF, cmake/Mpi.cmake) every call
// here is the one-process case (rank 0 of 1) and no MPI library is linked. Only app/ knows of MPI;
// skin/ and renderer/ take plain work-division hooks (skin/spectral_simulation.h,
// renderer/tracing/integrator.h's RenderDivision), docs/cluster.md describes the design.
//
// Rules the commands follow: every rank runs the same command on the same inputs (a shared file
// system); only rank 0 prints (the other ranks' standard output goes to /dev/null) and writes
// files; outputs are checked on rank 0 before any work and the verdict is shared (shareRootVerdict)
// so that every rank stops with the same error. Collectives must be called by every rank in the
// same order.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace hylios {

class MpiSession {
 public:
  /// Starts MPI when built with it (MPI_Init_thread, funneled: only the main thread calls MPI);
  /// one per process, in main(). Errors of MPI calls abort the whole job (MPI_ERRORS_ARE_FATAL).
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  static int rank();
  static int size();
  static bool isRoot() { return rank() == 0; }
  /// More than one process.
  static bool distributed() { return size() > 1; }
  /// Whether this build has MPI.
  static bool available();
  /// Whether the subcommand `name` divides its work among the ranks (spectrum, brdf,
  /// forward-profile, radial-profile, render, sweep); main() refuses the others under distribution.
  static bool dividesWork(const std::string& name);

  /// What main() does with an exception of a command on a rank: when every rank failed (each
  /// reaches this within `waitSeconds`), rank 0 prints the message and every rank returns 1; when
  /// only this rank failed, it prints the message with its rank and aborts the whole job
  /// (MPI_Abort), so that no rank waits forever on it. Without distribution: prints, returns 1.
  static int failCommand(const std::string& message, double waitSeconds = 5.0);
};

/// Runs `check` on rank 0 and shares its verdict: when it throws, every rank throws
/// std::invalid_argument with its message (so all stop at the same point, before any work).
void shareRootVerdict(const std::function<void()>& check);

/// The bytes of every rank on rank 0 (index = rank; empty on the other ranks).
std::vector<std::string> gatherToRoot(const std::string& bytes);
/// Rank 0's `bytes` on every rank.
void broadcastFromRoot(std::string& bytes);
/// Element-wise sums over the ranks, on rank 0 (the others' vectors are left as they were). All
/// ranks pass vectors of the same size.
void sumToRoot(std::vector<double>& values);
void sumToRoot(std::vector<std::uint32_t>& values);
void sumToRoot(std::vector<std::uint64_t>& values);

/// Point-to-point messages (the sweep's case dispatch). Tags are the caller's.
struct MpiMessage {
  int source = -1;
  int tag = 0;
  std::string bytes;
};
void sendTo(int rank, int tag, const std::string& bytes);
/// A waiting message from any rank, or false at once when none is there.
bool receiveIfAny(MpiMessage& message);
/// Waits for a message from `rank` (sleeping between polls, so a waiting rank leaves its cores
/// to the computing threads).
MpiMessage receiveFrom(int rank);

}  // namespace hylios
