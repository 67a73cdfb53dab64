#include "app/option_checks.h"

#include <fmt/format.h>
#include <sys/stat.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace hylios {

namespace fs = std::filesystem;

std::uint64_t parseUnsigned(const std::string& text, std::uint64_t min, std::uint64_t max,
                            const std::string& option) {
  const std::string range = fmt::format("an integer in [{}, {}]", min, max);
  if (text.empty())
    throw std::invalid_argument(fmt::format("{}: empty value; expected {}", option, range));
  for (char c : text)
    if (c < '0' || c > '9')
      throw std::invalid_argument(
          fmt::format("{} '{}': expected {} (digits only{})", option, text, range,
                      text[0] == '-' ? "; negative values are refused" : ""));
  std::uint64_t value = 0;
  for (char c : text) {
    const std::uint64_t digit = static_cast<std::uint64_t>(c - '0');
    if (value > (max - digit) / 10)
      throw std::invalid_argument(
          fmt::format("{} '{}': too large; expected {}", option, text, range));
    value = value * 10 + digit;
  }
  if (value < min)
    throw std::invalid_argument(
        fmt::format("{} '{}': too small; expected {}", option, text, range));
  return value;
}

CLI::Validator unsignedRange(std::uint64_t min, std::uint64_t max) {
  return CLI::Validator(
      [min, max](std::string& text) -> std::string {
        try {
          parseUnsigned(text, min, max, "value");
        } catch (const std::invalid_argument& e) {
          return std::string(e.what()).substr(6);  // without "value "
        }
        return {};
      },
      fmt::format("INT in [{} - {}]", min, max), "UNSIGNED");
}

CLI::Validator seedRange() { return unsignedRange(0, kMaxSeed); }

namespace {

/// The number `text` is, or an explanation of why it is not a finite number.
bool finiteNumber(const std::string& text, double& value, std::string& why) {
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size()) {
    why = "'" + text + "' is not a number";
    return false;
  }
  if (!std::isfinite(value) || (errno == ERANGE && std::fabs(value) > 1)) {
    why = "'" + text + "' is not a finite number";
    return false;
  }
  return true;
}

}  // namespace

CLI::Validator finiteRange(double min, double max) {
  return CLI::Validator(
      [min, max](std::string& text) -> std::string {
        double value = 0;
        std::string why;
        if (!finiteNumber(text, value, why)) return why;
        if (!(value >= min && value <= max))
          return fmt::format("{} is not in [{}, {}]", text, min, max);
        return {};
      },
      fmt::format("FINITE in [{} - {}]", min, max), "FINITE_RANGE");
}

CLI::Validator positiveFinite(double max) {
  return CLI::Validator(
      [max](std::string& text) -> std::string {
        double value = 0;
        std::string why;
        if (!finiteNumber(text, value, why)) return why;
        if (!(value > 0 && value <= max)) return fmt::format("{} is not in (0, {}]", text, max);
        return {};
      },
      fmt::format("FINITE in (0 - {}]", max), "POSITIVE_FINITE");
}

namespace {

[[noreturn]] void refuse(const NamedPath& output, const std::string& why) {
  throw std::invalid_argument(fmt::format("{} '{}': {}", output.option, output.path, why));
}

/// The path with its links resolved as far as it exists (a missing tail kept as written).
fs::path resolved(const fs::path& path) {
  std::error_code error;
  const fs::path absolute = fs::absolute(path, error);
  if (error) return path.lexically_normal();
  const fs::path canonical = fs::weakly_canonical(absolute, error);
  return error ? absolute.lexically_normal() : canonical;
}

}  // namespace

bool sameFile(const fs::path& a, const fs::path& b) {
  struct stat sa {
  }, sb{};
  if (::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0)
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  return resolved(a) == resolved(b);
}

NamedPath inputFile(const std::string& option, const std::string& path) {
  std::error_code error;
  if (!path.empty() && fs::exists(path, error) && !fs::is_directory(path, error))
    return {option, path, true};
  return {option, "", true};
}

void checkWritableOutput(const NamedPath& output) {
  const std::string& text = output.path;
  if (text.empty()) refuse(output, "empty path; give a file name");
  if (text.back() == '/') refuse(output, "names a folder (it ends in '/'); give a file name");
  std::error_code error;
  // A link is followed: its target is what gets written (skin/core/atomic_file.h).
  const fs::path target = resolved(text);
  const fs::file_status status = fs::status(target, error);
  if (fs::exists(status)) {
    if (fs::is_directory(status)) refuse(output, "is a folder; give a file name");
    if (::access(target.c_str(), W_OK) != 0)
      refuse(output, fmt::format("cannot be written: {}", std::strerror(errno)));
    if (!fs::is_regular_file(status)) return;  // a device or FIFO is written in place
  }
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  const fs::file_status folderStatus = fs::status(folder, error);
  if (!fs::exists(folderStatus))
    refuse(output, fmt::format("its folder '{}' does not exist", folder.string()));
  if (!fs::is_directory(folderStatus))
    refuse(output, fmt::format("'{}' is not a folder", folder.string()));
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    refuse(output, fmt::format("cannot write in its folder '{}': {}", folder.string(),
                               std::strerror(errno)));
}

void checkOutputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs) {
  for (const NamedPath& output : outputs) {
    if (output.path.empty() && output.optional) continue;  // not asked for
    checkWritableOutput(output);
  }
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (outputs[i].path.empty()) continue;
    for (const NamedPath& input : inputs)
      if (!input.path.empty() && sameFile(outputs[i].path, input.path))
        refuse(outputs[i], fmt::format("is the input {} '{}'; refusing to overwrite an input",
                                       input.option, input.path));
    for (std::size_t j = 0; j < i; ++j)
      if (!outputs[j].path.empty() && sameFile(outputs[i].path, outputs[j].path))
        refuse(outputs[i],
               fmt::format("is the same file as {} '{}'", outputs[j].option, outputs[j].path));
  }
}

}  // namespace hylios
