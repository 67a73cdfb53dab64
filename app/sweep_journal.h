// The journal of `hylios sweep`, beside its output (OUT.partial): the cases completed so far, so
// that an interrupted sweep (a kill, a node lost, a job out of time) continues with --resume. The
// first line names the sweep's definition (a hash of every input that changes a row); then one
// record per completed case, appended in the order cases complete and flushed to disk:
//
//   case <index>
//   <the case's CSV rows>
//   end <index> <FNV-1a 64 of the rows, hex>
//
// A record is taken only whole and with its hash; a torn last record (the process died while
// writing it) is dropped when the journal is reopened.
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

namespace hylios {

/// The journal path of an output: OUT + ".partial".
std::filesystem::path sweepJournalPath(const std::filesystem::path& out);

/// The complete records of the journal at `path` by case index (empty when there is no file).
/// Throws std::runtime_error when it belongs to another sweep (another definition hash) or names a
/// case >= caseCount.
std::map<std::size_t, std::string> readSweepJournal(const std::filesystem::path& path,
                                                    std::uint64_t definition,
                                                    std::size_t caseCount);

class SweepJournal {
 public:
  /// Writes the journal anew (atomically): the header and the records of `kept`; then appends.
  SweepJournal(std::filesystem::path path, std::uint64_t definition,
               const std::map<std::size_t, std::string>& kept);
  ~SweepJournal();
  SweepJournal(const SweepJournal&) = delete;
  SweepJournal& operator=(const SweepJournal&) = delete;
  /// Appends one case's record in one write and flushes it to disk (fsync). Throws on failure.
  void append(std::size_t index, const std::string& rows);
  /// Closes and deletes the journal (the sweep's output is written).
  void remove();

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

}  // namespace hylios
