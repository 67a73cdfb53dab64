#include "app/sweep_journal.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

#include "skin/core/atomic_file.h"
#include "skin/core/content_hash.h"

namespace hylios {
namespace {

std::string headerLine(std::uint64_t definition) {
  return "# hylios sweep journal 1; definition " + skin::hex64(definition) + "\n";
}

std::string record(std::size_t index, const std::string& rows) {
  return "case " + std::to_string(index) + "\n" + rows + "end " + std::to_string(index) + " " +
         skin::hex64(skin::fnv1a64(rows.data(), rows.size())) + "\n";
}

}  // namespace

std::filesystem::path sweepJournalPath(const std::filesystem::path& out) {
  return std::filesystem::path(out.string() + ".partial");
}

std::map<std::size_t, std::string> readSweepJournal(const std::filesystem::path& path,
                                                    std::uint64_t definition,
                                                    std::size_t caseCount) {
  std::map<std::size_t, std::string> cases;
  std::ifstream in(path, std::ios::binary);
  if (!in) return cases;
  std::string line;
  if (!std::getline(in, line) || line + "\n" != headerLine(definition))
    throw std::runtime_error("'" + path.string() +
                             "' is the journal of another sweep (other cases, wavelengths, "
                             "angles, rays, seed or specimen); run that sweep's command with "
                             "--resume, or delete the file to start afresh (nothing was changed)");
  // Records: "case I", rows, "end I HASH"; anything else (a torn tail) ends the reading.
  while (std::getline(in, line)) {
    if (line.rfind("case ", 0) != 0) break;
    const std::string index = line.substr(5);
    std::string rows;
    bool complete = false;
    while (std::getline(in, line)) {
      if (line.rfind("end ", 0) == 0) {
        std::istringstream end(line.substr(4));
        std::string endIndex, hash;
        end >> endIndex >> hash;
        complete = in.good() && endIndex == index &&
                   hash == skin::hex64(skin::fnv1a64(rows.data(), rows.size()));
        break;
      }
      rows += line + "\n";
    }
    if (!complete) break;
    std::size_t parsed = 0;
    try {
      parsed = std::stoull(index);
    } catch (const std::exception&) {
      break;
    }
    if (parsed >= caseCount)
      throw std::runtime_error("'" + path.string() + "' records case " + index + " of a sweep of " +
                               std::to_string(caseCount) + " cases");
    cases[parsed] = rows;
  }
  return cases;
}

SweepJournal::SweepJournal(std::filesystem::path path, std::uint64_t definition,
                           const std::map<std::size_t, std::string>& kept)
    : path_(std::move(path)) {
  std::string text = headerLine(definition);
  for (const auto& [index, rows] : kept) text += record(index, rows);
  writeTextAtomically(path_, text);
  fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0)
    throw std::runtime_error("cannot open the sweep journal '" + path_.string() +
                             "': " + std::strerror(errno));
}

SweepJournal::~SweepJournal() {
  if (fd_ >= 0) ::close(fd_);
}

void SweepJournal::append(std::size_t index, const std::string& rows) {
  const std::string text = record(index, rows);
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd_, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw std::runtime_error("cannot append to the sweep journal '" + path_.string() +
                               "': " + std::strerror(errno));
    written += static_cast<std::size_t>(n);
  }
  ::fsync(fd_);
}

void SweepJournal::remove() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  std::error_code ignored;
  std::filesystem::remove(path_, ignored);
}

}  // namespace hylios
