// Library values as Python values for the module's results: numpy arrays, {"mean", "stderr"}
// dicts, lists of layer and absorber names.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <utility>
#include <vector>

#include "skin/core/statistics.h"

namespace hylios::python {

pybind11::array_t<double> array(const std::vector<double>& values);
/// rows × columns, row-major.
pybind11::array_t<double> array2(const std::vector<double>& values, std::size_t rows,
                                 std::size_t columns);
/// The six layers, top to bottom.
pybind11::list layerNames();
/// The absorbers, in the order of coefficient arrays.
pybind11::list absorberNames();
/// {"mean": …, "stderr": …}.
pybind11::dict estimate(const skin::Estimate& e);
/// Means and standard errors of a list of estimates, as two arrays.
std::pair<std::vector<double>, std::vector<double>> split(
    const std::vector<skin::Estimate>& estimates);

}  // namespace hylios::python
