# SPDX-License-Identifier: MIT
# The libraries the model builds on (Debian packages, scripts/setup.sh), found once for the
# top-level build and for the Python package's build (python/CMakeLists.txt).
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(fmt REQUIRED)
# The compiler cache when the machine has one (scripts/setup.sh installs it): the set-up's build of
# the Python package compiles acore_ip, acore_lab and the RTL engine with the same flags as the
# top-level build, which then takes those objects from the cache instead of compiling them again.
find_program(ACORE_CCACHE ccache)
if(ACORE_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  set(CMAKE_CXX_COMPILER_LAUNCHER ${ACORE_CCACHE})
endif()
