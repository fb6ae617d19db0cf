# SPDX-License-Identifier: Apache-2.0
# The RTL as CMake sees it: sources read from the file list rtl/dda_core.f (the one list
# every flow reads), and the Verilated harness libraries built on them.

set(DDA_RTL_DIR ${PROJECT_SOURCE_DIR}/rtl)

# dda_rtl_sources(LIST OUT [RTL_DIR]): the Verilog sources of file list LIST, with
# $(DDA_RTL) replaced by RTL_DIR (default rtl/), nested lists (-f) expanded.
function(dda_rtl_sources list out)
  set(dir ${DDA_RTL_DIR})
  if(ARGC GREATER 2)
    set(dir ${ARGV2})
  endif()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${list})
  file(STRINGS ${list} lines)
  set(files "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "//.*$" "" line "${line}")
    string(STRIP "${line}" line)
    string(REPLACE "$(DDA_RTL)" "${DDA_RTL_DIR}" line "${line}")
    if(line STREQUAL "" OR line MATCHES "^\\+incdir\\+")
      continue()
    elseif(line MATCHES "^-[fFc] +(.*)$")
      dda_rtl_sources(${CMAKE_MATCH_1} nested ${dir})
      list(APPEND files ${nested})
    else()
      string(REPLACE "${DDA_RTL_DIR}" "${dir}" line "${line}")
      list(APPEND files ${line})
    endif()
  endforeach()
  set(${out} ${files} PARENT_SCOPE)
endfunction()

dda_rtl_sources(${DDA_RTL_DIR}/dda_core.f DDA_RTL_SOURCES)

find_package(verilator REQUIRED)

# verilate() with the build's coverage choice: with -DDDA_COVERAGE=ON every verilated
# model counts Verilator's line, toggle and user coverage points, and the harnesses
# write them (tb/engines/vl_coverage.hpp) for scripts/coverage.sh.
option(DDA_COVERAGE "verilate every model with --coverage (scripts/coverage.sh)" OFF)
macro(dda_verilate)
  if(DDA_COVERAGE)
    verilate(${ARGN} COVERAGE)
  else()
    verilate(${ARGN})
  endif()
endmacro()

# A harness library around a verilated copy of the RTL in `rtl_dir` (tests verilate a
# mutated copy too): `cc` is the C++ model and RtlHarness (tb/engines/, run by the dda
# command), `sc` the SystemC model and the co-simulation harness (tb/cosim/). Immediate
# assertions in the RTL are on (--assert). Extra arguments go to verilator.
function(dda_verilated_harness target mode rtl_dir)
  set(eng ${PROJECT_SOURCE_DIR}/tb/engines)
  if(mode STREQUAL "cc")
    set(src ${eng}/rtl_harness.cpp ${eng}/vl_sampler.cpp)
    set(prefix Vdda_core)
    set(kind TRACE)
    set(extra --timescale 1ns/1ns)  # the harness counts time in ns, like the SystemC clock
    set(base dda_engine)
  else()
    set(src ${PROJECT_SOURCE_DIR}/tb/cosim/cosim_harness.cpp ${eng}/vl_sampler.cpp)
    set(prefix Vdda_core_sc)
    set(kind SYSTEMC)
    set(extra "")
    set(base dda_sc_harness)
  endif()
  add_library(${target} STATIC ${src})
  set_source_files_properties(${src} TARGET_DIRECTORY ${target} PROPERTIES COMPILE_OPTIONS "${DDA_WARNINGS}")
  # Verilator's runtime headers are not ours: include them as system headers.
  target_include_directories(${target} SYSTEM PRIVATE ${VERILATOR_ROOT}/include ${VERILATOR_ROOT}/include/vltstd)
  target_link_libraries(${target} PUBLIC ${base})
  dda_rtl_sources(${DDA_RTL_DIR}/dda_core.f sources ${rtl_dir})
  # At other widths the generated header comes first (Verilator searches -I in order).
  set(params_dir "")
  if(NOT DDA_WIDTHS_DEFAULT)
    set(params_dir ${DDA_RTL_PARAMS_DIR})
  endif()
  dda_verilate(${target} ${kind}
    SOURCES ${sources} ${DDA_RTL_DIR}/lint.vlt
    TOP_MODULE dda_core PREFIX ${prefix}
    INCLUDE_DIRS ${params_dir} ${rtl_dir} ${DDA_RTL_DIR}
    VERILATOR_ARGS -Wall -O3 --assert --x-assign fast --x-initial fast ${extra} ${ARGN})
endfunction()

# The motion block's sources, and the generated register header at other widths.
dda_rtl_sources(${DDA_RTL_DIR}/dda_motion.f DDA_MOTION_SOURCES)
set(DDA_MOTION_PARAMS "")
if(NOT DDA_WIDTHS_DEFAULT)
  set(DDA_MOTION_PARAMS ${DDA_RTL_PARAMS_DIR})
endif()

# dda_motion_harness_lib(TARGET DEPTH_LOG2 [BRIDGES] [NO_INPUTS] [AXES2] [NO_PACER]): the motion block's harness (tb/engines/)
# around the RTL verilated with that queue depth (MotionHarness compiled with the same
# depth); "default": the RTL's default (DepthLog2 = motion::kMaxDepthLog2, from the
# generated header). Its build's -G parameters are the target's property
# DDA_BUILD_GPARAMS. BRIDGES: the block behind its AXI4-Lite and SPI bridges too
# (dda_motion_axil, dda_motion_spi), each verilated on its own.
function(dda_motion_harness_lib target depth_log2)
  set(eng ${PROJECT_SOURCE_DIR}/tb/engines)
  set(src ${eng}/motion_harness.cpp ${eng}/vl_sampler.cpp)
  add_library(${target} STATIC ${src})
  set_source_files_properties(${src} TARGET_DIRECTORY ${target} PROPERTIES COMPILE_OPTIONS "${DDA_WARNINGS}")
  target_include_directories(${target} SYSTEM PRIVATE ${VERILATOR_ROOT}/include ${VERILATOR_ROOT}/include/vltstd)
  target_link_libraries(${target} PUBLIC dda_motion_map dda_monitors dda_golden)
  if(depth_log2 STREQUAL "default")
    target_compile_definitions(${target} PUBLIC DDA_MOTION_TEST_DEPTH_LOG2=dda::motion::kMaxDepthLog2)
    set(gparam "")
  else()
    target_compile_definitions(${target} PUBLIC DDA_MOTION_TEST_DEPTH_LOG2=${depth_log2})
    set(gparam -GDepthLog2=${depth_log2})
  endif()
  set(tops dda_motion)
  set(bparam "")  # the build's parameters (without the depth): the target's DDA_BUILD_GPARAMS
  # NO_INPUTS: the build without the machine inputs (motion::Build::inputs; the
  # parameter's name is kBuildParams' and the test "build: ..." checks it).
  if("NO_INPUTS" IN_LIST ARGN)
    target_compile_definitions(${target} PUBLIC DDA_MOTION_TEST_INPUTS=0)
    list(APPEND bparam -GInputs=0)
  else()
    target_compile_definitions(${target} PUBLIC DDA_MOTION_TEST_INPUTS=1)
  endif()
  # AXES2: the build of two axes (motion::Build::axes).
  if("AXES2" IN_LIST ARGN)
    target_compile_definitions(${target} PUBLIC DDA_MOTION_TEST_AXES=2)
    list(APPEND bparam -GAxes=2)
  else()
    target_compile_definitions(${target} PUBLIC DDA_MOTION_TEST_AXES=3)
  endif()
  # NO_PACER: the build without the pacer (motion::Build::pacer).
  if("NO_PACER" IN_LIST ARGN)
    target_compile_definitions(${target} PUBLIC DDA_MOTION_TEST_PACER=0)
    list(APPEND bparam -GPacer=0)
  else()
    target_compile_definitions(${target} PUBLIC DDA_MOTION_TEST_PACER=1)
  endif()
  list(APPEND gparam ${bparam})
  # (for the same build verilated elsewhere: the SystemC-side RTL of its co-simulation)
  set_target_properties(${target} PROPERTIES DDA_BUILD_GPARAMS "${bparam}")
  if("BRIDGES" IN_LIST ARGN)
    list(APPEND tops dda_motion_axil dda_motion_spi)
    target_compile_definitions(${target} PRIVATE DDA_HARNESS_BRIDGES=1)
  endif()
  foreach(top IN LISTS tops)
    dda_rtl_sources(${DDA_RTL_DIR}/${top}.f sources)
    dda_verilate(${target} TRACE
      SOURCES ${sources} ${DDA_RTL_DIR}/lint.vlt
      TOP_MODULE ${top} PREFIX V${top}
      INCLUDE_DIRS ${DDA_MOTION_PARAMS} ${DDA_RTL_DIR}
      VERILATOR_ARGS -Wall -O3 --assert --x-assign fast --x-initial fast --timescale 1ns/1ns ${gparam})
  endforeach()
endfunction()
