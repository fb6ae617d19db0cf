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
