// libFuzzer harness: the command line's option parsers (app/option_checks.h, app/render_options.h,
// app/wavelength_list.h) on arbitrary strings, the way `--seed`, `--rays`, `--epsilon`,
// `--max-radius-cm`, `--resolution` and `--wavelengths` get them (issue 13). Bad text must be
// refused with a std::exception; what is accepted must keep the promise of its option:
// - a seed or count is exactly the decimal digits given, within its range (never a wrap: "-1"
//   is not 2^64 - 1, an overflow is not clamped);
// - a real option is finite and within its range (never nan or inf);
// - a resolution is within 16384 per side and 64 Mpixel, like scene files;
// - a wavelength is written back as text that reads as the same double, and distinct wavelengths
//   of a list are written distinctly.
// The first byte picks the parser, the rest is the text.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "app/option_checks.h"
#include "app/render_options.h"
#include "app/wavelength_list.h"
#include "fuzz/fuzz_check.h"
#include "renderer/scene/scene_file.h"

namespace {

using namespace hylios;

void unsignedOption(const std::string& text, std::uint64_t min, std::uint64_t max) {
  std::uint64_t value = 0;
  try {
    value = parseUnsigned(text, min, max, "--seed");
  } catch (const std::invalid_argument&) {
    CLI::Validator check = unsignedRange(min, max);
    std::string copy = text;
    fuzz::require(!check(copy).empty(), "the CLI11 check refuses what parseUnsigned refuses");
    return;
  }
  fuzz::require(value >= min && value <= max, "an unsigned option within its range");
  std::string digits = text;
  while (digits.size() > 1 && digits[0] == '0') digits.erase(0, 1);
  fuzz::require(std::to_string(value) == digits,
                "an unsigned option is exactly its digits (no wrap)");
  CLI::Validator check = unsignedRange(min, max);
  std::string copy = text;
  fuzz::require(check(copy).empty(), "the CLI11 check accepts what parseUnsigned accepts");
}

void realOption(const std::string& text, double min, double max) {
  CLI::Validator check = finiteRange(min, max);
  std::string copy = text;
  if (!check(copy).empty()) return;
  const double value = std::strtod(text.c_str(), nullptr);
  fuzz::require(std::isfinite(value) && value >= min && value <= max,
                "a real option finite and in range");
}

void resolution(const std::string& text) {
  std::pair<int, int> wh;
  try {
    wh = parseResolution(text);
  } catch (const std::invalid_argument&) {
    return;
  }
  fuzz::require(wh.first >= 1 && wh.second >= 1 && wh.first <= kMaxFilmSide &&
                    wh.second <= kMaxFilmSide &&
                    static_cast<long long>(wh.first) * wh.second <= kMaxFilmPixels,
                "--resolution within the scene files' limits");
}

void wavelengths(const std::string& text) {
  std::vector<double> list;
  try {
    list = parseWavelengthList(text);
  } catch (const std::invalid_argument&) {
    return;
  }
  for (std::size_t i = 0; i < list.size() && i < 1000; ++i) {
    const std::string written = formatWavelength(list[i]);
    fuzz::require(std::strtod(written.c_str(), nullptr) == list[i],
                  "a written wavelength reads back the same");
    if (i > 0 && list[i] != list[i - 1])
      fuzz::require(written != formatWavelength(list[i - 1]),
                    "distinct wavelengths are written distinctly");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text = hylios::fuzz::asText(data + 1, size - 1);
  switch (data[0] % 7) {
    case 0:
      unsignedOption(text, 0, hylios::kMaxSeed);
      break;  // --seed
    case 1:
      unsignedOption(text, 1, std::uint64_t{1} << 40);
      break;  // --rays
    case 2:
      realOption(text, 0.0, 1.0);
      break;  // --epsilon
    case 3:
      realOption(text, 1e-4, 100);
      break;  // --max-radius-cm
    case 4:
      realOption(text, 0.0, 89.999);
      break;  // --angle
    case 5:
      resolution(text);
      break;  // --resolution
    default:
      wavelengths(text);
      break;  // --wavelengths
  }
  return 0;
}
