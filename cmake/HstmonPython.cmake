# Finds what the Python module (ports/python) needs, before any library is defined: the
# module is a shared object, so every static library linked into it is compiled as
# position-independent code. Sets HSTMON_PYTHON_FOUND.
#
# The interpreter is Debian's /usr/bin/python3 unless Python3_EXECUTABLE is given: the
# Debian packages the module and its tests use (python3-pybind11, -numpy, -pandas,
# -pytest, -dask) are installed for it, not for a python3 that comes first on PATH
# (pyenv, a virtualenv).
set(HSTMON_PYTHON_FOUND OFF)
if(NOT HSTMON_BUILD_PYTHON OR NOT HSTMON_BUILD_HOST OR CMAKE_CROSSCOMPILING OR CMAKE_SYSTEM_NAME STREQUAL "Generic")
  return()
endif()

if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The Python the module is built for (Debian's)")
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module QUIET)
if(Python3_FOUND)
  set(PYBIND11_FINDPYTHON ON)  # pybind11 uses the Python3 found above
  find_package(pybind11 2.6 CONFIG QUIET)
endif()
if(NOT Python3_FOUND OR NOT pybind11_FOUND)
  message(STATUS "Python module hstmon: not built (needs Python 3 headers and pybind11: "
                 "apt-get install python3-dev pybind11-dev python3-pybind11, as scripts/install-deps.sh does; "
                 "or -DHSTMON_BUILD_PYTHON=OFF to silence this)")
  return()
endif()
message(STATUS "Python module hstmon: built for ${Python3_EXECUTABLE} (${Python3_VERSION}), pybind11 ${pybind11_VERSION}")
set(HSTMON_PYTHON_FOUND ON)

# Position-independent code for the libraries the module links. -fno-semantic-interposition
# keeps the code the compiler makes for the programs as it was without -fPIC (calls inside
# a library may still be inlined: nothing interposes a static library's functions).
set(CMAKE_POSITION_INDEPENDENT_CODE ON)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  add_compile_options(-fno-semantic-interposition)
endif()
