#include "app/measured_spectrum.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace hylios {
namespace {

/// Splits one CSV line on commas outside double quotes; quotes are removed.
std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (char c : line) {
    if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      fields.emplace_back();
    else if (c != '\r')
      fields.back() += c;
  }
  return fields;
}

std::size_t findColumn(const std::vector<std::string>& header, const std::string& column,
                       const std::string& where) {
  char* end = nullptr;
  const long number = std::strtol(column.c_str(), &end, 10);
  if (!column.empty() && *end == '\0') {
    if (number < 2 || static_cast<std::size_t>(number) > header.size())
      throw std::runtime_error(where + ": column " + column + " is not a data column (2.." +
                               std::to_string(header.size()) + ")");
    return static_cast<std::size_t>(number - 1);
  }
  std::vector<std::size_t> matches;
  for (std::size_t i = 1; i < header.size(); ++i) {
    if (header[i] == column) return i;
    if (header[i].rfind(column, 0) == 0) matches.push_back(i);
  }
  if (matches.size() == 1) return matches.front();
  throw std::runtime_error(
      where + ": " + (matches.empty() ? "no column named '" : "several columns start with '") +
      column + "'");
}

double parseValue(const std::string& field, const std::string& where) {
  char* end = nullptr;
  const double value = std::strtod(field.c_str(), &end);
  if (field.empty() || *end != '\0' || !std::isfinite(value))
    throw std::runtime_error(where + ": '" + field + "' is not a finite number");
  return value;
}

}  // namespace

bool MeasuredSpectrum::covers(double w) const {
  return !wavelengthNm.empty() && w >= wavelengthNm.front() && w <= wavelengthNm.back();
}

double MeasuredSpectrum::at(double w) const {
  if (!covers(w))
    throw std::out_of_range("measured spectrum '" + label + "' does not cover " +
                            std::to_string(w) + " nm");
  const auto upper = std::lower_bound(wavelengthNm.begin(), wavelengthNm.end(), w);
  const std::size_t i = static_cast<std::size_t>(upper - wavelengthNm.begin());
  if (wavelengthNm[i] == w) return value[i];
  const double t = (w - wavelengthNm[i - 1]) / (wavelengthNm[i] - wavelengthNm[i - 1]);
  return value[i - 1] + t * (value[i] - value[i - 1]);
}

MeasuredSpectrum loadMeasuredSpectrum(const std::string& fileAndColumn) {
  const auto colon = fileAndColumn.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == fileAndColumn.size())
    throw std::runtime_error("--measured '" + fileAndColumn + "': expected FILE:COLUMN");
  const std::string file = fileAndColumn.substr(0, colon);
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file + ": cannot open measured spectrum");
  return parseMeasuredSpectrum(in, fileAndColumn.substr(colon + 1), file);
}

namespace {

/// The columns `columns` (indices into the header) of CSV text, checked row by row.
std::vector<MeasuredSpectrum> parseColumns(std::istream& in, const std::vector<std::string>& header,
                                           const std::vector<std::size_t>& columns,
                                           const std::string& file) {
  std::vector<MeasuredSpectrum> spectra(columns.size());
  for (std::size_t k = 0; k < columns.size(); ++k) spectra[k].label = header[columns[k]];
  std::vector<double> wavelengths;
  std::string line;
  for (int lineNumber = 2; std::getline(in, line); ++lineNumber) {
    if (line.empty() || line == "\r") continue;
    const std::string where = file + ":" + std::to_string(lineNumber);
    const auto fields = splitCsvLine(line);
    if (fields.size() != header.size())
      throw std::runtime_error(where + ": " + std::to_string(fields.size()) +
                               " fields, header has " + std::to_string(header.size()));
    const double w = parseValue(fields[0], where);
    if (!wavelengths.empty() && w <= wavelengths.back())
      throw std::runtime_error(where + ": wavelengths must ascend");
    wavelengths.push_back(w);
    for (std::size_t k = 0; k < columns.size(); ++k)
      spectra[k].value.push_back(parseValue(fields[columns[k]], where));
  }
  if (wavelengths.size() < 2) throw std::runtime_error(file + ": fewer than two data rows");
  for (auto& s : spectra) s.wavelengthNm = wavelengths;
  return spectra;
}

std::vector<std::string> readHeader(std::istream& in, const std::string& file) {
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(file + ":1: empty file");
  return splitCsvLine(line);
}

}  // namespace

MeasuredSpectrum parseMeasuredSpectrum(std::istream& in, const std::string& columnName,
                                       const std::string& file) {
  const auto header = readHeader(in, file);
  const std::size_t column = findColumn(header, columnName, file + ":1");
  return parseColumns(in, header, {column}, file).front();
}

std::vector<MeasuredSpectrum> parseMeasuredSpectra(std::istream& in, const std::string& file) {
  const auto header = readHeader(in, file);
  if (header.size() < 2) throw std::runtime_error(file + ":1: no data column after the wavelength");
  std::vector<std::size_t> columns;
  for (std::size_t i = 1; i < header.size(); ++i) columns.push_back(i);
  return parseColumns(in, header, columns, file);
}

std::vector<MeasuredSpectrum> loadMeasuredSpectra(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot open measured spectra");
  return parseMeasuredSpectra(in, file.string());
}

double rmsDifference(const std::vector<double>& wavelengthNm, const std::vector<double>& model,
                     const MeasuredSpectrum& measured, std::size_t* compared) {
  double sumSquares = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < wavelengthNm.size(); ++i) {
    if (!measured.covers(wavelengthNm[i])) continue;
    const double difference = model[i] - measured.at(wavelengthNm[i]);
    sumSquares += difference * difference;
    ++count;
  }
  if (compared) *compared = count;
  if (count == 0)
    throw std::runtime_error("measured spectrum '" + measured.label +
                             "' covers none of the modelled wavelengths");
  return std::sqrt(sumSquares / static_cast<double>(count));
}

}  // namespace hylios
