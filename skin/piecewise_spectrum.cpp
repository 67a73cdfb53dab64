#include "skin/piecewise_spectrum.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hylios::skin {

void PiecewiseSpectrum::append(double fromNm, double toNm, std::string origin, Function value) {
  if (!(toNm > fromNm) || !value)
    throw std::invalid_argument(
        fmt::format("{}: piece '{}' needs a function and from < to ({}–{} nm)", substance_, origin,
                    fromNm, toNm));
  if (!pieces_.empty() && fromNm != pieces_.back().toNm)
    throw std::invalid_argument(
        fmt::format("{}: piece '{}' starts at {} nm but the previous piece ends at {} nm",
                    substance_, origin, fromNm, pieces_.back().toNm));
  pieces_.push_back(Piece{fromNm, toNm, std::move(origin), std::move(value)});
}

double PiecewiseSpectrum::operator()(double wavelengthNm) const {
  if (pieces_.empty())
    throw SpectralDataError(fmt::format("{}: the spectrum has no data", substance_));
  const SpectralCoverage range = coverage();
  if (!(wavelengthNm >= range.minNm && wavelengthNm <= range.maxNm))
    throw SpectralDataError(fmt::format(
        "{}: {} nm is outside its covered range {}–{} nm (tables plus declared extensions, see "
        "assets/spectra/SOURCES.md)",
        substance_, wavelengthNm, range.minNm, range.maxNm));
  const auto piece = std::lower_bound(pieces_.begin(), pieces_.end(), wavelengthNm,
                                      [](const Piece& p, double nm) { return p.toNm < nm; });
  const double value = piece->value(wavelengthNm);
  if (!std::isfinite(value) || value < 0)
    throw SpectralDataError(fmt::format("{}: {} gives {} at {} nm; expected finite and >= 0",
                                        substance_, piece->origin, value, wavelengthNm));
  return value;
}

SpectralCoverage PiecewiseSpectrum::coverage() const {
  if (pieces_.empty()) return SpectralCoverage{};
  return SpectralCoverage{pieces_.front().fromNm, pieces_.back().toNm};
}

}  // namespace hylios::skin
