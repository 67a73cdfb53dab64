#include "app/wavelength_list.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "skin/spectral_database.h"

namespace hylios {
namespace {

[[noreturn]] void fail(const std::string& text, const std::string& why) {
  throw std::invalid_argument("--wavelengths '" + text + "': " + why);
}

double parseNumber(const std::string& text, const std::string& token) {
  if (token.empty()) fail(text, "empty value");
  char* end = nullptr;
  const double value = std::strtod(token.c_str(), &end);
  if (end != token.c_str() + token.size()) fail(text, "'" + token + "' is not a number");
  if (!std::isfinite(value)) fail(text, "'" + token + "' is not finite");
  if (value <= 0) fail(text, "'" + token + "' is not a positive wavelength in nm");
  return value;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, separator)) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

/// Digits after the decimal point of a plain decimal number ("0.0025" -> 4); -1 for one with an
/// exponent (not snapped).
int decimals(const std::string& token) {
  if (token.find_first_of("eE") != std::string::npos) return -1;
  const auto point = token.find('.');
  return point == std::string::npos ? 0 : static_cast<int>(token.size() - point - 1);
}

std::vector<double> parseRange(const std::string& text) {
  const auto parts = split(text, ':');
  if (parts.size() != 3) fail(text, "a range is start:stop:step");
  const double start = parseNumber(text, parts[0]);
  const double stop = parseNumber(text, parts[1]);
  const double step = parseNumber(text, parts[2]);
  if (stop < start) fail(text, "stop is below start");
  const double count = std::floor((stop - start) / step + 1e-9) + 1;
  if (count > 1e6) fail(text, "more than a million wavelengths");
  // Grid points are snapped to the decimals the range is written with (400:700:0.1 gives 400.3,
  // not 400.29999999999995), so that they print as written.
  const int places = std::max({decimals(parts[0]), decimals(parts[2])});
  const bool snap = decimals(parts[0]) >= 0 && decimals(parts[2]) >= 0 && places <= 12;
  std::vector<double> wavelengths;
  for (long i = 0; i < static_cast<long>(count); ++i) {
    const double exact = start + static_cast<double>(i) * step;
    wavelengths.push_back(snap ? std::stod(fmt::format("{:.{}f}", exact, places)) : exact);
    // A step below the spacing of doubles near start would repeat wavelengths.
    if (i > 0 && !(wavelengths.back() > wavelengths[wavelengths.size() - 2]))
      fail(text, "step is too small to separate wavelengths near " + parts[0]);
  }
  return wavelengths;
}

/// Every wavelength inside the model's domain; the first outside is named.
void requireModelDomain(const std::string& text, const std::vector<double>& wavelengths) {
  for (double w : wavelengths)
    if (!(w >= skin::kModelMinWavelengthNm && w <= skin::kModelMaxWavelengthNm))
      fail(text, fmt::format("{} nm is outside the model's range {}–{} nm", w,
                             skin::kModelMinWavelengthNm, skin::kModelMaxWavelengthNm));
}

}  // namespace

std::vector<double> parseWavelengthList(const std::string& text) {
  if (text.empty()) fail(text, "no wavelengths given");
  std::vector<double> wavelengths;
  if (text.find(':') != std::string::npos) {
    wavelengths = parseRange(text);
  } else {
    for (const auto& token : split(text, ',')) wavelengths.push_back(parseNumber(text, token));
  }
  requireModelDomain(text, wavelengths);
  return wavelengths;
}

std::string formatWavelength(double nm) { return fmt::format("{}", nm); }

}  // namespace hylios
