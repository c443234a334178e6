# SPDX-License-Identifier: MIT
# The build registry rtl/configs.txt and the RTL file list rtl/files.f, read once for the whole
# build (included by the top-level CMakeLists.txt): the RTL engine (model/rtlsim) generates its
# table of builds from it and, with Verilator, one run-time module per build; tb/ adds the benches.
#
# ACORE_REG_NAMES lists every line's name; ACORE_REG_MODULE_<name>, ACORE_REG_FLOWS_<name> (a list),
# ACORE_REG_PARAMS_<name> (a list of PARAM=value) and ACORE_REG_TAGS_<name> (a list) its fields;
# ACORE_REG_TAGGED_<tag> the names carrying a tag (the registry's header lists the tags).
# ACORE_RTL_FILES: the absolute paths of rtl/files.f. Paths from this file's folder: the Python
# package's build (python/CMakeLists.txt) has python/ as its source folder.
get_filename_component(ACORE_ROOT ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)
file(STRINGS ${ACORE_ROOT}/rtl/files.f ACORE_RTL_FILES_REL REGEX "^[^#].*\\.v$")
set(ACORE_RTL_FILES "")
foreach(f ${ACORE_RTL_FILES_REL})
  list(APPEND ACORE_RTL_FILES ${ACORE_ROOT}/rtl/${f})
endforeach()
set(ACORE_RTL_VLT ${ACORE_ROOT}/rtl/verilator.vlt)
# Random initial values (with randReset(2)) so the tests prove the outputs are valid-gated. The
# modules include rtl/acore_derived.vh (the derived quantities).
set(ACORE_VERILATOR_ARGS -Wall --x-assign unique --x-initial unique -I${ACORE_ROOT}/rtl)

# The registry is read by scripts/registry.py alone: at configure time it writes the variables
# below into the build tree and CMake includes them. A malformed line (or a malformed devices table,
# whose families and devices are the synthesis flows) stops the configuration with registry.py's
# message (file, line and field); editing either file, or the reader, configures again.
find_program(ACORE_PYTHON3 NAMES python3 REQUIRED)
set(ACORE_REGISTRY_CMAKE ${CMAKE_BINARY_DIR}/acore_registry.cmake)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
  ${ACORE_ROOT}/rtl/configs.txt ${ACORE_ROOT}/rtl/files.f ${ACORE_ROOT}/synth/devices.toml
  ${ACORE_ROOT}/scripts/registry.py ${ACORE_ROOT}/scripts/devices.py)
execute_process(
  COMMAND ${ACORE_PYTHON3} ${ACORE_ROOT}/scripts/registry.py --root ${ACORE_ROOT} cmake
          ${ACORE_REGISTRY_CMAKE}
  RESULT_VARIABLE _acore_registry_rc ERROR_VARIABLE _acore_registry_err)
if(NOT _acore_registry_rc EQUAL 0)
  string(STRIP "${_acore_registry_err}" _acore_registry_err)
  message(FATAL_ERROR "${_acore_registry_err}")
endif()
include(${ACORE_REGISTRY_CMAKE})

# -G arguments of a registry line.
function(acore_gargs out name)
  set(g "")
  foreach(p ${ACORE_REG_PARAMS_${name}})
    list(APPEND g -G${p})
  endforeach()
  set(${out} ${g} PARENT_SCOPE)
endfunction()
# Removes the Verilator runtime that verilate() adds to a target (it links acore_vlt_runtime, built
# once by model/rtlsim/CMakeLists.txt).
function(acore_strip_runtime target)
  get_target_property(srcs ${target} SOURCES)
  list(FILTER srcs EXCLUDE REGEX "^${VERILATOR_ROOT}/include/")
  set_property(TARGET ${target} PROPERTY SOURCES ${srcs})
  target_link_libraries(${target} PRIVATE acore_vlt_runtime)
endfunction()
# Verilator's run-once code of a target (constructors, initial values, trace set-up: the sources
# verilate() gives no OPT_FAST flags) compiled as one translation unit at LEVEL, as Verilator's own
# __ALL.cpp does, instead of one compiler run per file that parses the same headers again; the
# per-sample code keeps its OPT_FAST level, file by file (sources with flags of their own stay out of
# a unity build), and HARNESS, the target's own source, Release's -O3. The waveform writer's per-clock
# code (__Trace__N.cpp, a third of the generated C++) runs only when a trace file is asked for: it
# joins the run-once code at LEVEL (about 3 s of compile a build saved; a traced run is slower).
function(acore_unity_slow target level harness)
  target_compile_options(${target} PRIVATE ${level})
  get_target_property(srcs ${target} SOURCES)
  list(FILTER srcs INCLUDE REGEX "__Trace__[0-9]+\\.cpp$")
  if(srcs)
    set_property(SOURCE ${srcs} PROPERTY COMPILE_FLAGS)
  endif()
  set_source_files_properties(${harness} TARGET_DIRECTORY ${target} PROPERTIES COMPILE_OPTIONS -O3)
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 0)
endfunction()
