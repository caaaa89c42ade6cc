# Release packages (CPack; scripts/release.sh builds and checks them, docs/packaging.md):
#   hstmon-<version>-Linux.deb      the host programs, the core headers, the C API, the
#                                   Python module (lib/python3.X/dist-packages/hstmon) and
#                                   the examples (share/hstmon/examples), installed under /usr
#   hstmon-<version>-Source.tar.gz  the source tree without build trees and VCS data
# The version is project(VERSION), as for every other manifest.
set(CPACK_PACKAGE_NAME hstmon)
set(CPACK_PACKAGE_VENDOR "hstmon")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "Hydrostatic transmission monitor: replay, identification and gap tools, and the allocation-free firmware core")
set(CPACK_PACKAGE_CONTACT "hstmon maintainers <hstmon@localhost>")
set(CPACK_RESOURCE_FILE_README ${PROJECT_SOURCE_DIR}/README.md)

set(CPACK_GENERATOR DEB)  # installs under /usr (the DEB generator's default prefix)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# Runtime libraries (libfmt, libstdc++) from the programs themselves (dpkg-shlibdeps), so
# the package states what a clean Debian needs; Eigen for the installed headers' users.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libeigen3-dev, gnuplot")
# The Python module (ports/python), where built: for the Python this build ran, with the
# Debian packages its import and its plots need; the programs need none of them.
if(TARGET hstmon_python)
  set(CPACK_DEBIAN_PACKAGE_RECOMMENDS
    "python3 (>= ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}), python3 (<< ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}.99), python3-numpy, python3-pandas")
  set(CPACK_DEBIAN_PACKAGE_SUGGESTS "${CPACK_DEBIAN_PACKAGE_SUGGESTS}, python3-matplotlib, python3-dask, python3-distributed")
endif()

set(CPACK_SOURCE_GENERATOR TGZ)
set(CPACK_SOURCE_PACKAGE_FILE_NAME hstmon-${PROJECT_VERSION}-Source)
set(CPACK_SOURCE_IGNORE_FILES "/\\\\.git/" "/\\\\.git$" "/build/" "/\\\\.cache/" "__pycache__" "~$")

# The examples, so the installed tools have a log to run on.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${CMAKE_INSTALL_DATADIR}/hstmon/examples
  COMPONENT programs)

include(CPack)
