#include "app/mpi_session.h"

#include <chrono>
#include <cstdlib>
#include <fcntl.h>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <thread>
#include <unistd.h>

#if HYLIOS_HAVE_MPI
#define OMPI_SKIP_MPICXX 1  // the C API only
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace hylios {
namespace {

int gRank = 0;
int gSize = 1;

#if HYLIOS_HAVE_MPI
bool gStarted = false;               ///< MPI_Init_thread was called here (and MPI_Finalize is due)
MPI_Comm gFailComm = MPI_COMM_NULL;  ///< a copy of the world for failCommand's barrier only

/// Whether a launcher started this process (mpirun/mpiexec of Open MPI or MPICH, srun with PMI or
/// PMIx); hylios started by hand never initialises MPI. HYLIOS_MPI_INIT=1 forces it.
bool startedByLauncher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(name)) return true;
  const char* forced = std::getenv("HYLIOS_MPI_INIT");
  return forced && std::string(forced) == "1";
}

/// Waits until every rank has arrived, sleeping between polls: a rank that finished its share
/// early leaves the cores to the others' threads instead of spinning in a blocking collective.
void quietBarrier() {
  MPI_Request request;
  MPI_Ibarrier(MPI_COMM_WORLD, &request);
  int done = 0;
  while (true) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

/// Counts above INT_MAX do not fit MPI's int arguments: collectives go in pieces of this many.
constexpr std::size_t kMaxPiece = std::size_t{1} << 28;

template <class T>
void sumPieces(std::vector<T>& values, MPI_Datatype type) {
  quietBarrier();
  for (std::size_t first = 0; first < values.size(); first += kMaxPiece) {
    const int count = static_cast<int>(std::min(kMaxPiece, values.size() - first));
    if (gRank == 0)
      MPI_Reduce(MPI_IN_PLACE, values.data() + first, count, type, MPI_SUM, 0, MPI_COMM_WORLD);
    else
      MPI_Reduce(values.data() + first, nullptr, count, type, MPI_SUM, 0, MPI_COMM_WORLD);
  }
}

void checkFitsInt(std::size_t bytes, const char* what) {
  if (bytes > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::length_error(std::string(what) + ": " + std::to_string(bytes) +
                            " bytes exceed one MPI message (2 GiB)");
}

void sleepBriefly() { std::this_thread::sleep_for(std::chrono::milliseconds(1)); }
#endif

}  // namespace

MpiSession::MpiSession(int& argc, char**& argv) {
#if HYLIOS_HAVE_MPI
  if (!startedByLauncher()) return;
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  gStarted = true;
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_ARE_FATAL);
  MPI_Comm_rank(MPI_COMM_WORLD, &gRank);
  MPI_Comm_size(MPI_COMM_WORLD, &gSize);
  MPI_Comm_dup(MPI_COMM_WORLD, &gFailComm);
  if (gRank != 0) {  // only rank 0 prints; errors still reach standard error
    const int devNull = ::open("/dev/null", O_WRONLY);
    if (devNull >= 0) {
      std::cout.flush();
      ::dup2(devNull, STDOUT_FILENO);
      ::close(devNull);
    }
  }
#else
  (void)argc;
  (void)argv;
  const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
  if (!size) size = std::getenv("PMI_SIZE");
  if (size && std::atoi(size) > 1)
    std::cerr << "hylios: warning: started as one of " << size
              << " MPI processes, but built without MPI (HYLIOS_MPI=OFF): every process runs the "
                 "whole command\n";
#endif
}

MpiSession::~MpiSession() {
#if HYLIOS_HAVE_MPI
  if (!gStarted) return;
  std::cout.flush();
  MPI_Comm_free(&gFailComm);
  MPI_Finalize();
  gStarted = false;
  gRank = 0;
  gSize = 1;
#endif
}

int MpiSession::rank() { return gRank; }
int MpiSession::size() { return gSize; }

bool MpiSession::available() {
#if HYLIOS_HAVE_MPI
  return true;
#else
  return false;
#endif
}

bool MpiSession::dividesWork(const std::string& name) {
  for (const char* divided :
       {"spectrum", "brdf", "forward-profile", "radial-profile", "render", "sweep"})
    if (name == divided) return true;
  return false;
}

int MpiSession::failCommand(const std::string& message, double waitSeconds) {
  if (!distributed()) {
    std::cerr << "hylios: error: " << message << "\n";
    return 1;
  }
#if HYLIOS_HAVE_MPI
  std::cout.flush();
  MPI_Request request;
  MPI_Ibarrier(gFailComm, &request);
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(waitSeconds));
  int everyone = 0;
  while (true) {
    MPI_Test(&request, &everyone, MPI_STATUS_IGNORE);
    if (everyone || std::chrono::steady_clock::now() > deadline) break;
    sleepBriefly();
  }
  if (everyone) {  // the same error everywhere (a shared verdict, a bad input): say it once
    if (isRoot()) std::cerr << "hylios: error: " << message << "\n";
    return 1;
  }
  std::cerr << "hylios: error on rank " << gRank << " of " << gSize << ": " << message
            << "; aborting the job" << std::endl;
  MPI_Abort(MPI_COMM_WORLD, 1);
#else
  (void)waitSeconds;
#endif
  return 1;
}

void shareRootVerdict(const std::function<void()>& check) {
  if (!MpiSession::distributed()) {
    check();
    return;
  }
  std::string verdict;  // empty: fine; else "!" + the error
  if (MpiSession::isRoot()) {
    try {
      check();
    } catch (const std::exception& e) {
      verdict = std::string("!") + e.what();
    }
  }
  broadcastFromRoot(verdict);
  if (!verdict.empty()) throw std::invalid_argument(verdict.substr(1));
}

std::vector<std::string> gatherToRoot(const std::string& bytes) {
  if (!MpiSession::distributed()) return {bytes};
#if HYLIOS_HAVE_MPI
  checkFitsInt(bytes.size(), "gatherToRoot");
  quietBarrier();
  const int mine = static_cast<int>(bytes.size());
  std::vector<int> sizes(MpiSession::isRoot() ? gSize : 0);
  MPI_Gather(&mine, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<int> offsets(sizes.size(), 0);
  std::string all;
  if (MpiSession::isRoot()) {
    std::size_t total = 0;
    for (std::size_t r = 0; r < sizes.size(); ++r) {
      offsets[r] = static_cast<int>(total);
      total += static_cast<std::size_t>(sizes[r]);
      checkFitsInt(total, "gatherToRoot");
    }
    all.resize(total);
  }
  MPI_Gatherv(bytes.data(), mine, MPI_BYTE, all.data(), sizes.data(), offsets.data(), MPI_BYTE, 0,
              MPI_COMM_WORLD);
  std::vector<std::string> result;
  for (std::size_t r = 0; r < sizes.size(); ++r)
    result.push_back(
        all.substr(static_cast<std::size_t>(offsets[r]), static_cast<std::size_t>(sizes[r])));
  return result;
#else
  return {bytes};
#endif
}

void broadcastFromRoot(std::string& bytes) {
  if (!MpiSession::distributed()) return;
#if HYLIOS_HAVE_MPI
  checkFitsInt(bytes.size(), "broadcastFromRoot");
  quietBarrier();
  std::uint64_t size = bytes.size();
  MPI_Bcast(&size, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  bytes.resize(size);
  MPI_Bcast(bytes.data(), static_cast<int>(size), MPI_BYTE, 0, MPI_COMM_WORLD);
#else
  (void)bytes;
#endif
}

void sumToRoot(std::vector<double>& values) {
  if (!MpiSession::distributed()) return;
#if HYLIOS_HAVE_MPI
  sumPieces(values, MPI_DOUBLE);
#else
  (void)values;
#endif
}

void sumToRoot(std::vector<std::uint32_t>& values) {
  if (!MpiSession::distributed()) return;
#if HYLIOS_HAVE_MPI
  sumPieces(values, MPI_UINT32_T);
#else
  (void)values;
#endif
}

void sumToRoot(std::vector<std::uint64_t>& values) {
  if (!MpiSession::distributed()) return;
#if HYLIOS_HAVE_MPI
  sumPieces(values, MPI_UINT64_T);
#else
  (void)values;
#endif
}

void sendTo(int rank, int tag, const std::string& bytes) {
#if HYLIOS_HAVE_MPI
  if (!MpiSession::distributed()) throw std::logic_error("sendTo: a single process");
  checkFitsInt(bytes.size(), "sendTo");
  MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, rank, tag, MPI_COMM_WORLD);
#else
  (void)rank;
  (void)tag;
  (void)bytes;
  throw std::logic_error("sendTo: hylios was built without MPI");
#endif
}

bool receiveIfAny(MpiMessage& message) {
#if HYLIOS_HAVE_MPI
  if (!MpiSession::distributed()) return false;
  int waiting = 0;
  MPI_Status status;
  MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &waiting, &status);
  if (!waiting) return false;
  int count = 0;
  MPI_Get_count(&status, MPI_BYTE, &count);
  message.source = status.MPI_SOURCE;
  message.tag = status.MPI_TAG;
  message.bytes.assign(static_cast<std::size_t>(count), '\0');
  MPI_Recv(message.bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return true;
#else
  (void)message;
  return false;
#endif
}

MpiMessage receiveFrom(int rank) {
#if HYLIOS_HAVE_MPI
  if (!MpiSession::distributed()) throw std::logic_error("receiveFrom: a single process");
  MPI_Status status;
  int waiting = 0;
  while (true) {
    MPI_Iprobe(rank, MPI_ANY_TAG, MPI_COMM_WORLD, &waiting, &status);
    if (waiting) break;
    sleepBriefly();
  }
  int count = 0;
  MPI_Get_count(&status, MPI_BYTE, &count);
  MpiMessage message;
  message.source = status.MPI_SOURCE;
  message.tag = status.MPI_TAG;
  message.bytes.assign(static_cast<std::size_t>(count), '\0');
  MPI_Recv(message.bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return message;
#else
  (void)rank;
  throw std::logic_error("receiveFrom: hylios was built without MPI");
#endif
}

}  // namespace hylios
