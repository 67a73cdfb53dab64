// hylios.render: what `hylios render` (app/render_command.cpp) does, without files: the film comes
// back as an array (height × width × channels) with its wavelengths.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/progress_bar.h"
#include "python/argument_checks.h"
#include "python/interruptible.h"
#include "python/module.h"
#include "python/numpy_conversions.h"
#include "renderer/scene/sampler_kind.h"
#include "renderer/scene/scene.h"
#include "renderer/scene/scene_file.h"
#include "renderer/tracing/render_job.h"

namespace hylios::python {

namespace py = pybind11;

namespace {

py::tuple render(const std::string& scenePath, std::optional<int> spp, std::optional<int> width,
                 std::optional<int> height, std::optional<std::uint64_t> seed, int threads,
                 std::optional<std::string> skinMode, std::optional<double> epsilon,
                 std::optional<double> noiseTarget, std::optional<std::string> estimator,
                 std::optional<std::string> sampler, bool progress, bool verbose) {
  requireThreads(threads);
  RenderSettings settings;
  if (skinMode) settings.skinMode = skinModeNamed(*skinMode);
  if (epsilon) requireEpsilon(*epsilon);
  settings.samplesPerPixel = spp;
  settings.width = width;
  settings.height = height;
  settings.seed = seed;
  settings.threads = threads;
  settings.effectTolerance = epsilon;
  if (noiseTarget && !(std::isfinite(*noiseTarget) && *noiseTarget > 0))
    throw std::invalid_argument("noise_target must be a positive relative noise");
  settings.noiseTarget = noiseTarget;
  if (estimator) settings.estimator = estimatorNamed(*estimator);
  if (sampler) settings.sampler = parseEnum(*sampler, kSamplerNames, "sampler");
  if (progress) settings.progress = progressBarFactory();
  SceneDesc scene;
  RenderResult result;
  runInterruptible(
      [&](const StopFlag& stop) {
        scene = applyRenderSettings(loadSceneFile(scenePath), settings);
        RenderSettings interruptible = settings;
        interruptible.stopRequested = [&stop] { return stop(); };
        result = renderScene(scene, interruptible, verbose ? &std::cout : nullptr);
      },
      false);
  const Film& film = *result.film;
  const std::size_t channels = film.channels().size();
  py::array_t<float> image({static_cast<py::ssize_t>(film.height()),
                            static_cast<py::ssize_t>(film.width()),
                            static_cast<py::ssize_t>(channels)});
  auto out = image.mutable_unchecked<3>();
  std::vector<double> wavelengths;
  for (const FilmChannel& c : film.channels()) wavelengths.push_back(c.wavelengthNm);
  {
    py::gil_scoped_release release;
    for (int y = 0; y < film.height(); ++y)
      for (int x = 0; x < film.width(); ++x)
        for (std::size_t c = 0; c < channels; ++c)
          out(y, x, static_cast<py::ssize_t>(c)) = static_cast<float>(film.value(x, y, c));
  }
  return py::make_tuple(image, array(wavelengths));
}

}  // namespace

void bindRender(py::module_& m) {
  m.def("render", &render, py::arg("scene_path"), py::arg("spp"), py::arg("width"),
        py::arg("height"), py::arg("seed"), py::arg("threads"), py::arg("skin_model"),
        py::arg("epsilon"), py::arg("noise_target"), py::arg("estimator"), py::arg("sampler"),
        py::arg("progress"), py::arg("verbose"), "See hylios.render");
  // The renderer has both since issues 11 and 12; the package still asks (python/hylios).
  m.attr("render_has_estimator") = true;
  m.attr("render_has_noise_target") = true;
}

}  // namespace hylios::python
