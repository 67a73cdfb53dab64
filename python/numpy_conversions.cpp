#include "python/numpy_conversions.h"

#include <string>

#include "skin/absorber.h"
#include "skin/layer.h"

namespace hylios::python {

namespace py = pybind11;

py::array_t<double> array(const std::vector<double>& values) {
  py::array_t<double> result(static_cast<py::ssize_t>(values.size()));
  auto out = result.mutable_unchecked<1>();
  for (std::size_t i = 0; i < values.size(); ++i) out(static_cast<py::ssize_t>(i)) = values[i];
  return result;
}

/// rows × columns, row-major.
py::array_t<double> array2(const std::vector<double>& values, std::size_t rows,
                           std::size_t columns) {
  py::array_t<double> result({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(columns)});
  auto out = result.mutable_unchecked<2>();
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < columns; ++c)
      out(static_cast<py::ssize_t>(r), static_cast<py::ssize_t>(c)) = values[r * columns + c];
  return result;
}

py::list layerNames() {
  py::list names;
  for (skin::Layer layer : skin::kAllLayers) names.append(std::string(skin::layerName(layer)));
  return names;
}

py::list absorberNames() {
  py::list names;
  for (skin::Absorber a : skin::kAllAbsorbers) names.append(std::string(skin::absorberName(a)));
  return names;
}

py::dict estimate(const skin::Estimate& e) {
  py::dict d;
  d["mean"] = e.mean;
  d["stderr"] = e.standardError;
  return d;
}

std::pair<std::vector<double>, std::vector<double>> split(
    const std::vector<skin::Estimate>& estimates) {
  std::pair<std::vector<double>, std::vector<double>> parts;
  for (const skin::Estimate& e : estimates) {
    parts.first.push_back(e.mean);
    parts.second.push_back(e.standardError);
  }
  return parts;
}

}  // namespace hylios::python
