// Checks every subcommand applies to its options before any work (issue 13, "hostile use"):
// numbers are parsed strictly (a seed or a count never wraps, NaN and infinities are refused),
// and every output path is validated up front (its folder exists and is writable, it is not a
// folder, it is not one of the command's inputs, two outputs are not the same file).
#pragma once
#include <CLI/CLI.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace hylios {

/// The largest seed: scene files keep seeds in a TOML integer (int64), so the command line takes
/// the same range, [0, 2^63 - 1], everywhere.
constexpr std::uint64_t kMaxSeed = 9223372036854775807ull;

/// Strict decimal parse of an unsigned integer in [min, max]: digits only (no sign, no spaces,
/// no exponent), no overflow. Throws std::invalid_argument naming `option`.
std::uint64_t parseUnsigned(const std::string& text, std::uint64_t min, std::uint64_t max,
                            const std::string& option);
/// A CLI11 check: the text is a decimal integer in [min, max] (runs before CLI11 converts it, so
/// "-1" or "99999999999999999999999" never reach an unsigned option wrapped).
CLI::Validator unsignedRange(std::uint64_t min, std::uint64_t max);
/// unsignedRange(0, kMaxSeed).
CLI::Validator seedRange();
/// A CLI11 check: a finite number (not nan, inf) in [min, max].
CLI::Validator finiteRange(double min, double max);
/// A CLI11 check: a finite number > 0 and <= max.
CLI::Validator positiveFinite(double max);

/// An output path with the option that names it, for messages ("--out 'x.csv'").
struct NamedPath {
  std::string option;
  std::string path;
  bool optional = false;  ///< an optional output left empty is not asked for (and not checked)
};

/// An input to compare outputs with: {option, path} when `path` names an existing file, else an
/// empty optional entry (a specimen name such as "S1" is not a file of the folder).
NamedPath inputFile(const std::string& option, const std::string& path);

/// Refuses, before any work, an output that cannot be written: an empty path, one ending in '/',
/// an existing folder, a missing folder, a folder the user cannot write in, or an existing file
/// the user cannot write. Throws std::invalid_argument naming the option.
void checkWritableOutput(const NamedPath& output);
/// checkWritableOutput for each (but optional empty ones); then refuses an output that is the same
/// file as one of `inputs` or as another output (same canonical path, or the same file through
/// another name or a link).
void checkOutputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs = {});
/// Whether two paths name the same file (both existing: the same device and inode; otherwise the
/// same path after resolving the links and '..' of the part that exists).
bool sameFile(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace hylios
