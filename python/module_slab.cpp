// hylios.slab: what `hylios slab` (app/slab_command.cpp) computes for a layered slab (MCML's
// problem), as a dict of floats and numpy arrays.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "python/argument_checks.h"
#include "python/interruptible.h"
#include "python/module.h"
#include "python/numpy_conversions.h"
#include "skin/core/enum_names.h"
#include "skin/core/thread_limit.h"
#include "skin/layered_slab.h"

namespace hylios::python {

namespace py = pybind11;

namespace {

/// A layer as (n, mua per cm, mus per cm, g, d in cm), top first (`hylios slab --layer`).
using LayerTuple = std::array<double, 5>;

py::dict slab(const std::vector<LayerTuple>& layers, double nAbove, double nBelow, double angleDeg,
              bool diffuse, std::uint64_t rays, std::uint64_t seed, const std::string& schemeName,
              bool scalar, int threads) {
  requireAngle(angleDeg);
  requireRays(rays);
  requireThreads(threads);
  skin::SlabProblem problem;
  problem.refractiveIndexAbove = nAbove;
  problem.refractiveIndexBelow = nBelow;
  problem.incidenceAngleDeg = angleDeg;
  problem.diffuseIncidence = diffuse;
  for (const LayerTuple& l : layers) problem.layers.push_back({l[0], l[1], l[2], l[3], l[4]});
  skin::validateSlabProblem(problem);  // "layer 2: mus must be finite and >= 0, got -1"
  skin::SlabRunOptions run;
  run.photons = rays;
  run.seed = seed;
  run.scheme = parseEnum(schemeName, skin::kAbsorptionSchemeNames, "scheme");
  run.laneWalk = !scalar;
  skin::SlabResult result;
  runInterruptible(
      [&](const StopFlag&) {
        const ThreadLimit threadLimit(threads);
        result = skin::simulateLayeredSlab(problem, run);
      },
      true);
  py::dict d;
  d["specular_reflectance"] = result.specularReflectance;
  const auto put = [&](const char* name, const skin::Estimate& e) {
    d[name] = e.mean;
    d[(std::string(name) + "_stderr").c_str()] = e.standardError;
  };
  put("diffuse_reflectance", result.diffuseReflectance);
  put("transmittance", result.transmittance);
  put("unscattered_transmittance", result.unscatteredTransmittance);
  put("diffuse_transmittance", result.diffuseTransmittance);
  put("absorptance", result.absorptance);
  put("event_limited", result.eventLimited);
  std::vector<double> perLayer, perLayerErr;
  for (const skin::Estimate& e : result.layerAbsorptance) {
    perLayer.push_back(e.mean);
    perLayerErr.push_back(e.standardError);
  }
  d["layer_absorptance"] = array(perLayer);
  d["layer_absorptance_stderr"] = array(perLayerErr);
  d["photons"] = result.photons;
  return d;
}

}  // namespace

void bindSlab(py::module_& m) {
  m.def("slab", &slab, py::arg("layers"), py::arg("above"), py::arg("below"), py::arg("angle_deg"),
        py::arg("diffuse"), py::arg("rays"), py::arg("seed"), py::arg("scheme"), py::arg("scalar"),
        py::arg("threads"), "hylios slab: Rd, Tt and absorptance per layer of a layered slab");
}

}  // namespace hylios::python
