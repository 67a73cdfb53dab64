# The Python module (python/): built when pybind11's CMake package is found (Debian 12:
# python3-pybind11 / pybind11-dev, installed by scripts/install-deps.sh). The interpreter is the
# first of `python3` on PATH and /usr/bin/python3 that can import numpy (the module returns numpy
# arrays and its tests need numpy), unless PYTHON_EXECUTABLE is given. Not in sanitizer or fuzz
# builds (an ASan-instrumented module cannot be loaded into an uninstrumented python3).
include(CMakeDependentOption)
if(NOT PYTHON_EXECUTABLE)
  find_program(HYLIOS_PATH_PYTHON3 python3)
  foreach(candidate IN ITEMS "${HYLIOS_PATH_PYTHON3}" /usr/bin/python3)
    if(candidate AND EXISTS "${candidate}")
      execute_process(COMMAND "${candidate}" -c "import numpy" RESULT_VARIABLE numpy_missing
                      OUTPUT_QUIET ERROR_QUIET)
      if(numpy_missing EQUAL 0)
        set(PYTHON_EXECUTABLE "${candidate}" CACHE FILEPATH "Python interpreter of the hylios module")
        break()
      endif()
    endif()
  endforeach()
endif()
find_package(pybind11 CONFIG QUIET)
cmake_dependent_option(HYLIOS_BUILD_PYTHON "Build the hylios Python module (build/python/hylios)" ON
  "pybind11_FOUND;NOT HYLIOS_SANITIZE;NOT HYLIOS_FUZZ" OFF)
