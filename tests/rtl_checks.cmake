# RTL checks: Verilator lint, Yosys synthesis for iCE40, and the golden-driven Icarus
# bench of dda_core. Included from tests/CMakeLists.txt: include(rtl_checks.cmake).
# Each test runs a script of scripts/ that also works by hand (see its header).
# The tools are required: scripts/setup.sh installs them, and a check that silently
# did not run would hide a regression.

find_program(DDA_VERILATOR_EXE verilator REQUIRED)
find_program(DDA_IVERILOG_EXE iverilog REQUIRED)
find_program(DDA_VVP_EXE vvp REQUIRED)
find_program(DDA_YOSYS_EXE yosys REQUIRED)
find_program(DDA_BASH_EXE bash REQUIRED)

set(DDA_RTL_TOOL_ENV
    VERILATOR=${DDA_VERILATOR_EXE} IVERILOG=${DDA_IVERILOG_EXE} VVP=${DDA_VVP_EXE}
    YOSYS=${DDA_YOSYS_EXE})

# dda_rtl_test(NAME NEEDS tool... COMMAND script args...)  (NEEDS documents the tools)
function(dda_rtl_test name)
  cmake_parse_arguments(T "" "" "NEEDS;COMMAND" ${ARGN})
  add_test(NAME ${name}
           COMMAND ${CMAKE_COMMAND} -E env ${DDA_RTL_TOOL_ENV} ${DDA_BASH_EXE} ${T_COMMAND})
  set_tests_properties(${name} PROPERTIES LABELS rtl TIMEOUT 300)
endfunction()

set(_dda_scripts ${PROJECT_SOURCE_DIR}/scripts)

# Verilator lint with -Wall: fails on any %Warning or %Error (waivers in rtl/lint.vlt).
dda_rtl_test(rtl.lint NEEDS VERILATOR COMMAND ${_dda_scripts}/rtl-lint.sh)

# synth_ice40: fails on an error, an inferred latch or multiple drivers; prints stat.
dda_rtl_test(rtl.yosys_synth NEEDS YOSYS
             COMMAND ${_dda_scripts}/synth-check.sh ${CMAKE_CURRENT_BINARY_DIR}/rtl_synth.log)

# The paper's example (a = 10, b = 6, n = 4) against gen_core_vectors' golden records.
set(_dda_bench ${_dda_scripts}/icarus-bench.sh --gen $<TARGET_FILE:gen_core_vectors>)
set(_dda_bench_dir ${CMAKE_CURRENT_BINARY_DIR}/rtl_bench)
dda_rtl_test(rtl.icarus_paper_example NEEDS IVERILOG VVP
             COMMAND ${_dda_bench} --a 10 --b 6 --bits 4 --preload zero
                     --out ${_dda_bench_dir}/paper_zero ${PROJECT_BINARY_DIR})
dda_rtl_test(rtl.icarus_paper_example_half NEEDS IVERILOG VVP
             COMMAND ${_dda_bench} --a 10 --b 6 --bits 4 --preload half
                     --out ${_dda_bench_dir}/paper_half ${PROJECT_BINARY_DIR})
# ce_i from an LFSR: edges with ce_i low must change nothing but clear the pulses.
dda_rtl_test(rtl.icarus_paper_example_ce_random NEEDS IVERILOG VVP
             COMMAND ${_dda_bench} --a 10 --b 6 --bits 4 --preload zero --ce-random 1
                     --out ${_dda_bench_dir}/paper_ce_random ${PROJECT_BINARY_DIR})
# The same ellipse in the second quadrant: both directions 1 (-X, -Y), so cdir_y_q and
# dir_y_q (0 until the first Y step) are checked with a value other than their reset 0.
dda_rtl_test(rtl.icarus_second_quadrant NEEDS IVERILOG VVP
             COMMAND ${_dda_bench} --a 10 --b 6 --bits 4 --preload zero --from 0,6 --to -10,0
                     --out ${_dda_bench_dir}/q2_zero ${PROJECT_BINARY_DIR})
# One expected value corrupted (lowest bit of u_int_x.jr_q after iteration 5): passes only
# if vvp exits non-zero with exactly that MISMATCH (not on a failure for another reason).
dda_rtl_test(rtl.icarus_detects_corruption NEEDS IVERILOG VVP
             COMMAND ${_dda_bench} --a 10 --b 6 --bits 4 --preload zero
                     --corrupt-iter 5 --corrupt-field u_int_x.jr_q
                     --out ${_dda_bench_dir}/paper_corrupt ${PROJECT_BINARY_DIR})

# Vector sets of `dda vectors` (golden model) through tb/vectors/dda_vec_tb.v on Icarus
# and on Verilator --binary: the paper's example, the lathe paper's oblique ellipse with
# ce_i high 80% of the cycles, three arcs back to back (an axis-aligned quarter, a rotated
# arc, a whole ellipse with half preload), and a corrupted expected value that both
# simulators must report.
set(_dda_vec ${CMAKE_CURRENT_BINARY_DIR}/vec_sets)
set(_dda_lathe --a 25000 --b 15000 --angle 330 --center -30000,5000 --from-theta 60 --to-theta 136 --dir ccw)
function(dda_vec_set name)
  add_test(NAME vectors.gen_${name} COMMAND $<TARGET_FILE:dda> vectors --out-dir ${_dda_vec}/${name} ${ARGN})
  set_tests_properties(vectors.gen_${name} PROPERTIES FIXTURES_SETUP vec_${name} LABELS rtl)
endfunction()
dda_vec_set(paper --a 10 --b 6 --bits 4)
dda_vec_set(lathe ${_dda_lathe} --ce-percent 80 --seed 3)
dda_vec_set(back_to_back --a 10 --b 6 --bits 4 --ce-percent 90 --seed 7
            --then "--a 300 --b 200 --angle 30 --preload half --from-theta 10 --to-theta 200"
            --then "--a 50 --b 20 --preload half --dir cw --center 5,-7 --from-theta 45 --to-theta 45")
foreach(_set paper lathe back_to_back)
  dda_rtl_test(vectors.${_set} NEEDS IVERILOG VVP VERILATOR
               COMMAND ${_dda_scripts}/vector-bench.sh ${_dda_vec}/${_set})
  set_tests_properties(vectors.${_set} PROPERTIES FIXTURES_REQUIRED vec_${_set}
                       ENVIRONMENT DDA_BUILD_DIR=${PROJECT_BINARY_DIR} RESOURCE_LOCK vec_bench_build)
endforeach()
dda_rtl_test(vectors.detects_corruption NEEDS IVERILOG VVP VERILATOR
             COMMAND ${_dda_scripts}/vector-bench.sh --corrupt 12 u_int_y.jr_q ${_dda_vec}/paper)
set_tests_properties(vectors.detects_corruption PROPERTIES FIXTURES_REQUIRED vec_paper
                     ENVIRONMENT DDA_BUILD_DIR=${PROJECT_BINARY_DIR} RESOURCE_LOCK vec_bench_build)
# The bench's field table is generated from hw_params.hpp: the checked-in copy must match.
add_test(NAME vectors.fields_in_sync
         COMMAND ${DDA_BASH_EXE} -c "$<TARGET_FILE:dda> gen-params --kind vector-fields | diff - ${PROJECT_SOURCE_DIR}/tb/vectors/dda_vec_fields.vh")
