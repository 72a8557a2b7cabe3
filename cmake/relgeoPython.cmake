# cmake/relgeoPython.cmake — finds an interpreter with pybind11 and numpy and
# sets the option RELGEO_BUILD_PYTHON (default ON when all three are found).
#
# FindPython3 runs first so that pybind11 builds for the same interpreter
# (pybind11's config reuses Python3_* when Python3_FOUND). Debian's
# /usr/bin/python3 is preferred over whatever `python3` is first on PATH
# (pyenv, a virtualenv); -DPython3_EXECUTABLE=/path/to/python3 overrides it.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Interpreter the Python bindings are built for")
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module NumPy QUIET)
set(_relgeo_python_missing "")
if(NOT Python3_Interpreter_FOUND OR NOT Python3_Development.Module_FOUND)
  set(_relgeo_python_missing "a Python 3 interpreter with its headers (python3-dev)")
elseif(NOT Python3_NumPy_FOUND)
  set(_relgeo_python_missing "numpy for ${Python3_EXECUTABLE} (python3-numpy)")
else()
  # Debian's python3-pybind11 installs its CMake package under the interpreter's dist-packages.
  execute_process(COMMAND ${Python3_EXECUTABLE} -c "import pybind11; print(pybind11.get_cmake_dir())"
                  OUTPUT_VARIABLE _relgeo_pybind11_dir OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  find_package(pybind11 2.6 CONFIG QUIET HINTS ${_relgeo_pybind11_dir})
  if(NOT pybind11_FOUND)
    set(_relgeo_python_missing "pybind11 for ${Python3_EXECUTABLE} (python3-pybind11)")
  endif()
endif()

if(_relgeo_python_missing STREQUAL "")
  option(RELGEO_BUILD_PYTHON "Build the Python package relgeo (python/)" ON)
  if(RELGEO_BUILD_PYTHON)
    message(STATUS "relgeo: Python bindings for ${Python3_EXECUTABLE} (${Python3_VERSION}, numpy ${Python3_NumPy_VERSION}, pybind11 ${pybind11_VERSION})")
  endif()
else()
  option(RELGEO_BUILD_PYTHON "Build the Python package relgeo (python/)" OFF)
  if(RELGEO_BUILD_PYTHON)
    message(FATAL_ERROR "relgeo: RELGEO_BUILD_PYTHON=ON but ${_relgeo_python_missing} was not found")
  endif()
  message(STATUS "relgeo: ${_relgeo_python_missing} not found; the Python bindings are not built")
endif()
