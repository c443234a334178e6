# SPDX-License-Identifier: MIT
# The build registry rtl/configs.txt and the RTL file list rtl/files.f, read once for the whole
# build (included by the top-level CMakeLists.txt): the RTL engine (model/rtlsim) generates its
# table of builds from it and, with Verilator, one run-time module per build; tb/ adds the benches.
#
# ACORE_REG_NAMES lists every line's name; ACORE_REG_MODULE_<name>, ACORE_REG_FLOWS_<name> (a list)
# and ACORE_REG_PARAMS_<name> (a list of PARAM=value) its fields. ACORE_RTL_FILES: the absolute
# paths of rtl/files.f.
file(STRINGS ${CMAKE_SOURCE_DIR}/rtl/files.f ACORE_RTL_FILES_REL REGEX "^[^#].*\\.v$")
set(ACORE_RTL_FILES "")
foreach(f ${ACORE_RTL_FILES_REL})
  list(APPEND ACORE_RTL_FILES ${CMAKE_SOURCE_DIR}/rtl/${f})
endforeach()
set(ACORE_RTL_VLT ${CMAKE_SOURCE_DIR}/rtl/verilator.vlt)
# Random initial values (with randReset(2)) so the tests prove the outputs are valid-gated. The
# modules include rtl/acore_derived.vh (the derived quantities).
set(ACORE_VERILATOR_ARGS -Wall --x-assign unique --x-initial unique -I${CMAKE_SOURCE_DIR}/rtl)

set(ACORE_REGISTRY ${CMAKE_SOURCE_DIR}/rtl/configs.txt)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${ACORE_REGISTRY}
                                                               ${CMAKE_SOURCE_DIR}/rtl/files.f)
file(STRINGS ${ACORE_REGISTRY} ACORE_REG_LINES REGEX "^[a-z]")
set(ACORE_REG_NAMES "")
foreach(line ${ACORE_REG_LINES})
  string(REGEX REPLACE "[ \t]+" ";" fields "${line}")
  list(LENGTH fields n)
  if(n LESS 3)
    message(FATAL_ERROR "rtl/configs.txt: '${line}': expected name module flows [PARAM=value ...]")
  endif()
  list(GET fields 0 name)
  list(GET fields 1 module)
  list(GET fields 2 flows)
  list(REMOVE_AT fields 0 1 2)
  if(name IN_LIST ACORE_REG_NAMES)
    message(FATAL_ERROR "rtl/configs.txt: '${name}' is listed twice")
  endif()
  foreach(p ${fields})
    if(NOT p MATCHES "^[A-Z_][A-Z0-9_]*=[0-9]+$")
      message(FATAL_ERROR "rtl/configs.txt: ${name}: '${p}' is not PARAM=value")
    endif()
  endforeach()
  list(APPEND ACORE_REG_NAMES ${name})
  set(ACORE_REG_MODULE_${name} ${module})
  string(REPLACE "," ";" ACORE_REG_FLOWS_${name} "${flows}")
  set(ACORE_REG_PARAMS_${name} ${fields})
endforeach()
list(GET ACORE_REG_NAMES 0 first)
if(NOT first STREQUAL "default" OR NOT ACORE_REG_MODULE_default STREQUAL "acore_top")
  message(FATAL_ERROR "rtl/configs.txt: the first line must be 'default acore_top ...'")
endif()

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
