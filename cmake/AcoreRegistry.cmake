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
# Verilates a registry build at build time, as a step of its own that runs beside the others (the
# verilate() of Verilator's CMake package runs Verilator while CMake configures, one build after the
# other: about 100 s on one core for the default build's 56), and compiles the generated C++ as two
# translation units instead of one compiler run per file, each parsing Verilator's headers again
# (as Verilator's own __ALL.cpp does; cmake/AcoreVerilatedUnits.cmake writes them):
#   <prefix>__slow_all.cpp  the run-once code (constructors, initial values, trace set-up) at SLOW,
#                           with the waveform writer's per-clock code (__Trace__N.cpp, a third of the
#                           generated C++), which runs only when a trace file is asked for;
#   <prefix>__fast_all.cpp  the per-sample code at FAST (about 4 CPU-s instead of 16 for a
#                           pipelined top's 11 files).
# The target links acore_vlt_runtime (model/rtlsim/CMakeLists.txt: Verilator's runtime, compiled
# once) and includes the generated headers (<prefix>.h, <prefix>_<module>.h). Verilator runs again
# when a file of rtl/ changes (or VLT, or Verilator itself). FST tracing is compiled in, without the
# parameters (--no-trace-params: two thirds of the traced names are constants the registry line
# gives; without them the run-once code compiles in a fifth less time).
# SYSTEMC: a SystemC model (--sc) without tracing; Verilator's runtime, which differs with SystemC,
# is compiled into the target instead of linking acore_vlt_runtime.
# LINE: the registry line built, recorded in the global property ACORE_VERILATED (CTest rtl_lint does
# not lint those lines again: Verilator ran on them with -Wall here, and a warning stops the build).
#   acore_verilate(TARGET PREFIX P TOP_MODULE M FAST FLAGS... SLOW FLAGS... VLT FILES...
#                  VERILATOR_ARGS ARGS... [LINE NAME] [SYSTEMC])
function(acore_verilate target)
  cmake_parse_arguments(V "SYSTEMC" "PREFIX;TOP_MODULE;LINE" "FAST;SLOW;VLT;VERILATOR_ARGS" ${ARGN})
  set(mdir ${CMAKE_CURRENT_BINARY_DIR}/${target}.verilated)
  set(slow_unit ${mdir}/${V_PREFIX}__slow_all.cpp)
  set(fast_unit ${mdir}/${V_PREFIX}__fast_all.cpp)
  file(GLOB rtl_deps CONFIGURE_DEPENDS ${ACORE_ROOT}/rtl/*.v ${ACORE_ROOT}/rtl/*.vh)
  if(V_SYSTEMC)
    set(mode --sc)
    set(vm VM_SC=1 VM_TRACE=0 VM_TRACE_FST=0)
  else()
    set(mode --cc --trace-fst --no-trace-params)
    set(vm VM_SC=0 VM_TRACE=1 VM_TRACE_FST=1)
  endif()
  add_custom_command(OUTPUT ${slow_unit} ${fast_unit}
    COMMAND ${CMAKE_COMMAND} -E rm -rf ${mdir}
    COMMAND ${VERILATOR_BIN} --compiler gcc ${mode} --make cmake --Mdir ${mdir}
            --prefix ${V_PREFIX} --top ${V_TOP_MODULE} ${V_VERILATOR_ARGS} ${V_VLT} ${ACORE_RTL_FILES}
    COMMAND ${CMAKE_COMMAND} -DMDIR=${mdir} -DPREFIX=${V_PREFIX}
            -P ${ACORE_ROOT}/cmake/AcoreVerilatedUnits.cmake
    DEPENDS ${rtl_deps} ${V_VLT} ${VERILATOR_BIN} ${ACORE_ROOT}/cmake/AcoreVerilatedUnits.cmake
    WORKING_DIRECTORY ${ACORE_ROOT}/rtl
    COMMENT "Verilating ${V_TOP_MODULE} for ${target}" VERBATIM)
  target_sources(${target} PRIVATE ${slow_unit} ${fast_unit})
  set_source_files_properties(${slow_unit} PROPERTIES COMPILE_OPTIONS "${V_SLOW}")
  set_source_files_properties(${fast_unit} PROPERTIES COMPILE_OPTIONS "${V_FAST}")
  # Public: the benches that link a test-local build (tb/CMakeLists.txt) include its headers.
  target_include_directories(${target} PUBLIC ${mdir} ${VERILATOR_ROOT}/include
                                               ${VERILATOR_ROOT}/include/vltstd)
  target_compile_definitions(${target} PRIVATE VM_COVERAGE=0 ${vm} VM_TRACE_VCD=0)
  if(V_SYSTEMC)
    find_package(Threads REQUIRED)
    target_sources(${target} PRIVATE ${VERILATOR_ROOT}/include/verilated.cpp
                                     ${VERILATOR_ROOT}/include/verilated_dpi.cpp
                                     ${VERILATOR_ROOT}/include/verilated_threads.cpp)
    target_link_libraries(${target} PRIVATE Threads::Threads)
  else()
    target_link_libraries(${target} PRIVATE acore_vlt_runtime)
  endif()
  if(V_LINE)
    set_property(GLOBAL APPEND PROPERTY ACORE_VERILATED ${V_LINE})
  endif()
endfunction()
