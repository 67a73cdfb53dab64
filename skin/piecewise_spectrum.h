// One substance's spectrum assembled from contiguous pieces, each a table or a declared extension
// (power law, band model, ...), evaluated by the piece whose interval holds the wavelength.
// Outside the union of the pieces it throws SpectralDataError naming the substance and the
// covered range; it never clamps.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "skin/spectral_database.h"

namespace hylios::skin {

class PiecewiseSpectrum {
 public:
  using Function = std::function<double(double wavelengthNm)>;

  struct Piece {
    double fromNm;
    double toNm;
    std::string origin;  ///< e.g. "Prahl 1999 table" or "power-law extension"
    Function value;
  };

  explicit PiecewiseSpectrum(std::string substance) : substance_(std::move(substance)) {}

  /// Appends [fromNm, toNm]; the first piece may start anywhere, every later one must start where
  /// the previous ended (so the pieces tile one interval). Throws std::invalid_argument otherwise.
  void append(double fromNm, double toNm, std::string origin, Function value);

  /// Value at `wavelengthNm` (at a shared end point the earlier piece answers).
  /// Throws SpectralDataError outside coverage().
  double operator()(double wavelengthNm) const;

  SpectralCoverage coverage() const;
  const std::string& substance() const { return substance_; }
  const std::vector<Piece>& pieces() const { return pieces_; }

 private:
  std::string substance_;
  std::vector<Piece> pieces_;
};

}  // namespace hylios::skin
