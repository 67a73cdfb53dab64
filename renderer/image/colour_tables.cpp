#include "renderer/image/colour_tables.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "renderer/scene/data_paths.h"

namespace hylios {
namespace {

/// A CSV table: '#' comment lines, one header line, then rows of numbers.
struct CsvTable {
  std::vector<std::vector<double>> rows;
};

CsvTable readCsv(const std::filesystem::path& path, std::size_t columns) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open colour table '" + path.string() + "'");
  CsvTable table;
  std::string line;
  int lineNumber = 0;
  bool headerSeen = false;
  while (std::getline(in, line)) {
    ++lineNumber;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    if (!headerSeen) {
      headerSeen = true;
      continue;
    }
    std::vector<double> row;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) {
      std::size_t used = 0;
      double value = 0;
      try {
        value = std::stod(cell, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != cell.size() || !std::isfinite(value)) {
        throw std::runtime_error(path.string() + ":" + std::to_string(lineNumber) +
                                 ": not a number: '" + cell + "'");
      }
      row.push_back(value);
    }
    if (row.size() != columns) {
      throw std::runtime_error(path.string() + ":" + std::to_string(lineNumber) + ": expected " +
                               std::to_string(columns) + " columns, found " +
                               std::to_string(row.size()));
    }
    table.rows.push_back(std::move(row));
  }
  if (table.rows.size() < 2)
    throw std::runtime_error("colour table '" + path.string() + "' is empty");
  return table;
}

/// Rows sampled on a uniform grid: checks the first column is first + i·step.
void requireUniformGrid(const CsvTable& table, const std::filesystem::path& path, double first,
                        double last, double step) {
  const auto expected = static_cast<std::size_t>(std::lround((last - first) / step)) + 1;
  if (table.rows.size() != expected) {
    throw std::runtime_error("colour table '" + path.string() + "': expected " +
                             std::to_string(expected) + " rows from " + std::to_string(first) +
                             " to " + std::to_string(last) + ", found " +
                             std::to_string(table.rows.size()));
  }
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    if (std::fabs(table.rows[i][0] - (first + step * static_cast<double>(i))) > 1e-9) {
      throw std::runtime_error("colour table '" + path.string() + "': row " + std::to_string(i) +
                               " is at " + std::to_string(table.rows[i][0]) + ", not on the grid " +
                               std::to_string(first) + " + k·" + std::to_string(step));
    }
  }
}

struct ColourTables {
  double cmfStepNm = 1;
  std::vector<std::array<double, 3>> cmf;  ///< kCie1931MinNm + i·cmfStepNm
  double d65StepNm = 5;
  std::vector<double> d65;  ///< kD65MinNm + i·d65StepNm
  std::vector<std::array<double, 3>> colourMap;
  std::array<std::array<double, 3>, 3> xyzToSrgb{};
};

/// Inverse of a 3×3 matrix (Cramer's rule); throws if singular.
std::array<std::array<double, 3>, 3> inverse(const std::array<std::array<double, 3>, 3>& m) {
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  if (std::fabs(det) < 1e-12) throw std::logic_error("singular colour matrix");
  std::array<std::array<double, 3>, 3> r{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const int a = (j + 1) % 3, b = (j + 2) % 3, c = (i + 1) % 3, d = (i + 2) % 3;
      r[i][j] = (m[a][c] * m[b][d] - m[a][d] * m[b][c]) / det;
    }
  }
  return r;
}

/// XYZ → linear sRGB from the sRGB primaries' and the D65 white's chromaticities
/// (IEC 61966-2-1: R 0.64/0.33, G 0.30/0.60, B 0.15/0.06, white 0.3127/0.3290): the columns of
/// RGB → XYZ are the primaries' XYZ scaled so that RGB (1,1,1) is the white with Y = 1.
std::array<std::array<double, 3>, 3> srgbMatrix() {
  const double xy[3][2] = {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}};
  const double whiteX = 0.3127, whiteY = 0.3290;
  std::array<std::array<double, 3>, 3> primaries{};  // columns: primaries' XYZ with Y = 1
  for (int p = 0; p < 3; ++p) {
    primaries[0][p] = xy[p][0] / xy[p][1];
    primaries[1][p] = 1.0;
    primaries[2][p] = (1.0 - xy[p][0] - xy[p][1]) / xy[p][1];
  }
  const std::array<double, 3> white{whiteX / whiteY, 1.0, (1.0 - whiteX - whiteY) / whiteY};
  const auto inv = inverse(primaries);
  std::array<double, 3> scale{};
  for (int i = 0; i < 3; ++i)
    scale[i] = inv[i][0] * white[0] + inv[i][1] * white[1] + inv[i][2] * white[2];
  std::array<std::array<double, 3>, 3> rgbToXyz{};
  for (int r = 0; r < 3; ++r)
    for (int p = 0; p < 3; ++p) rgbToXyz[r][p] = primaries[r][p] * scale[p];
  return inverse(rgbToXyz);
}

ColourTables loadColourTables() {
  const std::filesystem::path folder = dataRoot() / "assets" / "colour";
  ColourTables tables;

  const auto cmfPath = folder / "cie1931_2deg_cmf_1nm.csv";
  const CsvTable cmf = readCsv(cmfPath, 4);
  requireUniformGrid(cmf, cmfPath, kCie1931MinNm, kCie1931MaxNm, tables.cmfStepNm);
  for (const auto& row : cmf.rows) tables.cmf.push_back({row[1], row[2], row[3]});

  const auto d65Path = folder / "cie_d65_5nm.csv";
  const CsvTable d65 = readCsv(d65Path, 2);
  requireUniformGrid(d65, d65Path, kD65MinNm, kD65MaxNm, tables.d65StepNm);
  for (const auto& row : d65.rows) tables.d65.push_back(row[1]);

  const auto mapPath = folder / "magma_256.csv";
  const CsvTable map = readCsv(mapPath, 4);
  requireUniformGrid(map, mapPath, 0, 255, 1);
  for (const auto& row : map.rows) {
    for (int c = 1; c <= 3; ++c) {
      if (row[c] < 0 || row[c] > 1)
        throw std::runtime_error(mapPath.string() + ": entry outside [0, 1]");
    }
    tables.colourMap.push_back({row[1], row[2], row[3]});
  }
  tables.xyzToSrgb = srgbMatrix();
  return tables;
}

const ColourTables& tables() {
  static const ColourTables loaded = loadColourTables();  // thread-safe initialisation (C++11)
  return loaded;
}

/// Linear interpolation in a table sampled at first + i·step; `x` must lie in the table.
template <class T>
T interpolate(const std::vector<T>& values, double first, double step, double x) {
  const double position = (x - first) / step;
  const auto last = values.size() - 1;
  const auto index = std::min(static_cast<std::size_t>(position), last - 1);
  const double f = position - static_cast<double>(index);
  if constexpr (std::is_same_v<T, double>) {
    return values[index] + f * (values[index + 1] - values[index]);
  } else {
    T result{};
    for (std::size_t c = 0; c < result.size(); ++c)
      result[c] = values[index][c] + f * (values[index + 1][c] - values[index][c]);
    return result;
  }
}

}  // namespace

std::array<double, 3> cie1931(double wavelengthNm) {
  if (std::isnan(wavelengthNm)) throw std::invalid_argument("cie1931: wavelength is NaN");
  if (wavelengthNm < kCie1931MinNm || wavelengthNm > kCie1931MaxNm) return {0, 0, 0};
  const auto& t = tables();
  return interpolate(t.cmf, kCie1931MinNm, t.cmfStepNm, wavelengthNm);
}

double d65(double wavelengthNm) {
  if (!(wavelengthNm >= kD65MinNm && wavelengthNm <= kD65MaxNm)) {
    throw std::out_of_range("D65 is tabulated from 300 to 830 nm; asked for " +
                            std::to_string(wavelengthNm) + " nm");
  }
  const auto& t = tables();
  return interpolate(t.d65, kD65MinNm, t.d65StepNm, wavelengthNm);
}

std::array<double, 3> xyzToLinearSrgb(const std::array<double, 3>& xyz) {
  const auto& m = tables().xyzToSrgb;
  std::array<double, 3> rgb{};
  for (int r = 0; r < 3; ++r) rgb[r] = m[r][0] * xyz[0] + m[r][1] * xyz[1] + m[r][2] * xyz[2];
  return rgb;
}

double srgbEncode(double linear) {
  if (std::isnan(linear)) throw std::invalid_argument("srgbEncode: value is NaN");
  const double v = std::clamp(linear, 0.0, 1.0);
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

std::array<double, 3> colourMap(double t) {
  if (std::isnan(t)) throw std::invalid_argument("colourMap: t is NaN");
  const auto& map = tables().colourMap;
  const double scaled = std::clamp(t, 0.0, 1.0) * static_cast<double>(map.size() - 1);
  return interpolate(map, 0.0, 1.0, scaled);
}

}  // namespace hylios
