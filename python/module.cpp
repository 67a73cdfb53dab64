// hylios._hylios: the compiled part of the Python module (python/hylios/__init__.py is the public
// face, with the keyword arguments and docstrings). Every function here does what the matching
// `hylios` command does (app/*_command.cpp) with the same libraries, options and random streams,
// so the numbers are the ones the command writes; results come back as dicts of numpy arrays.
//
// | concern     | how                                                                          |
// |-------------|------------------------------------------------------------------------------|
// | GIL         | released for the whole computation (it runs on a worker thread)              |
// | Ctrl-C      | the calling thread polls PyErr_CheckSignals every 50 ms; a pending signal    |
// |             | stops the work at its next safe point (between wavelengths, bundles, render  |
// |             | passes, or TBB tasks where nothing is cached) and the Python error is raised |
// | errors      | the messages of the command line (SpecimenError, SceneError: file:line:col)   |
// | data        | HYLIOS_DATA_DIR or the compiled-in source tree (renderer/scene/data_paths.h) |
//
// The functions are bound by concept in python/module_*.cpp (python/module.h); the shared parts
// are python/interruptible (GIL and Ctrl-C), python/interruptible_tallies (the --estimator run),
// python/numpy_conversions and python/argument_checks.
#include "python/module.h"

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <exception>
#include <string>

#include "app/render_options.h"
#include "app/wavelength_list.h"
#include "python/numpy_conversions.h"
#include "renderer/scene/data_paths.h"
#include "renderer/scene/scene_file.h"
#include "skin/specimen.h"
#include "skin/specimen_fit.h"

namespace py = pybind11;

PYBIND11_MODULE(_hylios, m) {
  using namespace hylios;
  using namespace hylios::python;
  m.doc() = "Compiled core of the hylios module; use the functions of the hylios package.";

  static py::exception<skin::SpecimenError> specimenError(m, "SpecimenError", PyExc_ValueError);
  static py::exception<SceneError> sceneError(m, "SceneError", PyExc_ValueError);
  static py::exception<skin::FitError> fitError(m, "FitError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const skin::SpecimenError& e) {
      specimenError(e.what());
    } catch (const SceneError& e) {
      sceneError(e.what());
    } catch (const skin::FitError& e) {
      fitError(e.what());
    }
  });

  bindSpecimen(m);
  m.def("layer_names", &layerNames, "The six layers, top to bottom");
  m.def("absorber_names", &absorberNames, "The absorbers, in the order of coefficient arrays");
  m.def(
      "data_root", [] { return dataRoot().string(); }, "The folder holding assets/ and scenes/");
  m.def("parse_resolution", &parseResolution, py::arg("text"), "'WxH' -> (W, H), as --resolution");
  m.def("parse_wavelengths", &parseWavelengthList, py::arg("text"),
        "start:stop:step or a comma list, nm");
  bindSpectrum(m);
  bindAngular(m);
  bindRender(m);
  bindFit(m);
  bindSlab(m);
}
