#include "app/skin_population.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace hylios {

double SkinPopulation::lightness(std::size_t index) const {
  const MeasuredSpectrum& s = subjects.at(index);
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < s.wavelengthNm.size(); ++i)
    if (s.wavelengthNm[i] >= 500 && s.wavelengthNm[i] <= 700) {
      sum += s.value[i];
      ++count;
    }
  if (count == 0)
    throw std::out_of_range("measured curve '" + s.label + "' has no wavelength in 500-700 nm");
  return sum / static_cast<double>(count);
}

std::vector<std::size_t> SkinPopulation::byLightness() const {
  std::vector<double> key(subjects.size());
  for (std::size_t i = 0; i < subjects.size(); ++i) key[i] = lightness(i);
  std::vector<std::size_t> order(subjects.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&key](std::size_t a, std::size_t b) { return key[a] > key[b]; });
  return order;
}

std::vector<std::size_t> SkinPopulation::quantileGroup(double fraction, bool lightest) const {
  if (!(fraction > 0 && fraction <= 1))
    throw std::invalid_argument("population group fraction must be in (0, 1]");
  std::vector<std::size_t> order = byLightness();
  if (!lightest) std::reverse(order.begin(), order.end());
  const auto count = std::max<std::size_t>(
      1, static_cast<std::size_t>(std::lround(fraction * static_cast<double>(order.size()))));
  order.resize(std::min(count, order.size()));
  return order;
}

PopulationEnvelope SkinPopulation::envelope(const std::vector<std::size_t>& members,
                                            const std::vector<double>& wavelengths) const {
  if (members.empty()) throw std::invalid_argument("population envelope of an empty group");
  PopulationEnvelope e;
  e.wavelengthNm = wavelengths;
  e.members = members.size();
  std::vector<double> values(members.size());
  for (double w : wavelengths) {
    for (std::size_t k = 0; k < members.size(); ++k) values[k] = subjects.at(members[k]).at(w);
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    e.lowest.push_back(values.front());
    e.highest.push_back(values.back());
    e.median.push_back(n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]));
  }
  return e;
}

SkinPopulation loadSkinPopulation(const std::filesystem::path& file) {
  SkinPopulation p{loadMeasuredSpectra(file)};
  for (const MeasuredSpectrum& s : p.subjects)
    for (std::size_t i = 0; i < s.value.size(); ++i)
      if (s.value[i] < 0 || s.value[i] > 1.5)
        throw std::runtime_error(file.string() + ": " + s.label + " at " +
                                 fmt::format("{:g}", s.wavelengthNm[i]) + " nm is " +
                                 fmt::format("{:g}", s.value[i]) + ", not a reflectance factor");
  return p;
}

}  // namespace hylios
