// A measured reflectance curve to compare a modelled spectrum with: one column of a CSV file whose
// first column is wavelength in nm (e.g. the NCSU skin database, Vrhel et al. 1994).
#pragma once
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace hylios {

struct MeasuredSpectrum {
  std::string label;                 ///< the column's header
  std::vector<double> wavelengthNm;  ///< ascending
  std::vector<double> value;
  /// Linear interpolation; throws std::out_of_range outside [front, back].
  double at(double wavelengthNm) const;
  bool covers(double wavelengthNm) const;
};

/// Loads "FILE:COLUMN": COLUMN is a header name, a unique header prefix (e.g. "obj113"), or a
/// 1-based column number. Errors say file:line and what is wrong.
MeasuredSpectrum loadMeasuredSpectrum(const std::string& fileAndColumn);
/// Parses CSV text from `csv` as loadMeasuredSpectrum does, taking column `column` (same forms);
/// `sourceName` stands for the file in messages.
MeasuredSpectrum parseMeasuredSpectrum(std::istream& csv, const std::string& column,
                                       const std::string& sourceName);

/// Every data column of a CSV file (same format and errors as loadMeasuredSpectrum), in file order:
/// a set of curves on one wavelength grid, such as a measured population.
std::vector<MeasuredSpectrum> loadMeasuredSpectra(const std::filesystem::path& file);
/// Parses CSV text as loadMeasuredSpectra does; `sourceName` stands for the file in messages.
std::vector<MeasuredSpectrum> parseMeasuredSpectra(std::istream& csv,
                                                   const std::string& sourceName);

/// Root-mean-square of model − measured over the model wavelengths the measurement covers.
/// Returns the number of wavelengths compared through `compared`.
double rmsDifference(const std::vector<double>& wavelengthNm, const std::vector<double>& model,
                     const MeasuredSpectrum& measured, std::size_t* compared = nullptr);

}  // namespace hylios
