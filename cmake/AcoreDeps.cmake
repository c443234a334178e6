# SPDX-License-Identifier: MIT
# The libraries the model builds on (Debian packages, scripts/setup.sh), found once for the
# top-level build and for the Python package's build (python/CMakeLists.txt).
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(fmt REQUIRED)
