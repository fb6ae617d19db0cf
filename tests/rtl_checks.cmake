# SPDX-License-Identifier: Apache-2.0
# RTL checks: Verilator lint, Yosys synthesis for iCE40, and the vector-set bench
# tb/hdl/dda_vec_tb.v on Icarus and Verilator. Included from tests/CMakeLists.txt: include(rtl_checks.cmake).
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

# The build-time parameters outside their ranges (kBuildParams) stop elaboration of the
# three tops on Icarus, and of the block on Verilator and Yosys, naming the parameter.
dda_rtl_test(rtl.build_ranges NEEDS IVERILOG VERILATOR YOSYS COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/check-build-ranges.sh)

# synth_ice40: fails on an error, an inferred latch or multiple drivers; prints stat.
dda_rtl_test(rtl.yosys_synth NEEDS YOSYS
             COMMAND ${_dda_scripts}/synth-check.sh ${CMAKE_CURRENT_BINARY_DIR}/rtl_synth.log)

# Vector sets of `dda vectors` (golden model) through tb/hdl/dda_vec_tb.v on Icarus and
# on Verilator --binary: the paper's example with both preloads, with ce_i low 40% of
# the cycles and in the second quadrant (both directions negative, so cdir_*_q and
# dir_*_q take values other than their reset 0); the lathe paper's oblique ellipse with
# ce_i high 80% of the cycles; three arcs back to back (an axis-aligned quarter, a
# rotated arc, a whole ellipse with half preload); and a corrupted expected value that
# both simulators must report. While cmd_valid_i is low the bench scrambles cmd_i.
set(_dda_vec ${CMAKE_CURRENT_BINARY_DIR}/vec_sets)
file(MAKE_DIRECTORY ${_dda_vec})
set(_dda_lathe --a 25000 --b 15000 --angle 330 --center -30000,5000 --from-theta 60 --to-theta 136 --dir ccw)
function(dda_vec_set name)
  add_test(NAME vectors.gen_${name} COMMAND $<TARGET_FILE:dda> vectors --out-dir ${name} ${ARGN}
           WORKING_DIRECTORY ${_dda_vec})
  set_tests_properties(vectors.gen_${name} PROPERTIES FIXTURES_SETUP vec_${name} LABELS rtl)
endfunction()
dda_vec_set(paper --a 10 --b 6 --bits 4 --preload zero)
dda_vec_set(paper_half --a 10 --b 6 --bits 4 --preload half)
dda_vec_set(paper_ce --a 10 --b 6 --bits 4 --preload zero --ce-percent 60 --seed 11)
dda_vec_set(second_quadrant --a 10 --b 6 --bits 4 --preload zero --from 0,6 --to -10,0)
dda_vec_set(lathe ${_dda_lathe} --preload zero --ce-percent 80 --seed 3)
dda_vec_set(back_to_back --a 10 --b 6 --bits 4 --preload zero --ce-percent 90 --seed 7
            --then "--a 300 --b 200 --angle 30 --preload half --from-theta 10 --to-theta 200"
            --then "--a 50 --b 20 --preload half --dir cw --center 5,-7 --from-theta 45 --to-theta 45")
# A part program: the lathe paper's macro program, its 304 chords and the
# rapids around them as back-to-back commands.
dda_vec_set(paper_macro --program ${PROJECT_SOURCE_DIR}/examples/lathe-paper-macro.ngc --machine lathe --start 60,5
            --ce-percent 90 --seed 13)
foreach(_set paper paper_half paper_ce second_quadrant lathe back_to_back paper_macro)
  dda_rtl_test(vectors.${_set} NEEDS IVERILOG VVP VERILATOR
               COMMAND ${_dda_scripts}/vector-bench.sh ${_dda_vec}/${_set})
  set_tests_properties(vectors.${_set} PROPERTIES FIXTURES_REQUIRED vec_${_set}
                       ENVIRONMENT DDA_BUILD_DIR=${PROJECT_BINARY_DIR} RESOURCE_LOCK vec_bench_build)
endforeach()
# The same sets on the fast implementation (its architectural registers are the same).
foreach(_set paper paper_half paper_ce second_quadrant lathe back_to_back)
  dda_rtl_test(vectors.fast.${_set} NEEDS IVERILOG VVP VERILATOR
               COMMAND ${_dda_scripts}/vector-bench.sh --impl fast ${_dda_vec}/${_set})
  set_tests_properties(vectors.fast.${_set} PROPERTIES FIXTURES_REQUIRED vec_${_set}
                       ENVIRONMENT DDA_BUILD_DIR=${PROJECT_BINARY_DIR} RESOURCE_LOCK vec_bench_build_fast)
endforeach()
# The small implementation as scripts/synth synthesizes it: its hand-placed iCE40 cells
# (-DDDA_ICE40, Yosys' SB_LUT4 and SB_CARRY models) on Verilator, and on Icarus for the
# short sets (the lathe's 869,361 cycles take Icarus 4 minutes through the cell models).
foreach(_set paper paper_half paper_ce second_quadrant lathe back_to_back)
  set(_sims both)
  if(_set STREQUAL lathe)
    set(_sims verilator)
  endif()
  dda_rtl_test(vectors.ice40.${_set} NEEDS IVERILOG VVP VERILATOR
               COMMAND ${_dda_scripts}/vector-bench.sh --ice40 --sim ${_sims} ${_dda_vec}/${_set})
  set_tests_properties(vectors.ice40.${_set} PROPERTIES FIXTURES_REQUIRED vec_${_set}
                       ENVIRONMENT DDA_BUILD_DIR=${PROJECT_BINARY_DIR} RESOURCE_LOCK vec_bench_build_ice40)
endforeach()
dda_rtl_test(vectors.fast.detects_corruption NEEDS IVERILOG VVP VERILATOR
             COMMAND ${_dda_scripts}/vector-bench.sh --impl fast --corrupt 12 u_int_y.jr_q ${_dda_vec}/paper)
set_tests_properties(vectors.fast.detects_corruption PROPERTIES FIXTURES_REQUIRED vec_paper
                     ENVIRONMENT DDA_BUILD_DIR=${PROJECT_BINARY_DIR} RESOURCE_LOCK vec_bench_build_fast)
dda_rtl_test(vectors.detects_corruption NEEDS IVERILOG VVP VERILATOR
             COMMAND ${_dda_scripts}/vector-bench.sh --corrupt 12 u_int_y.jr_q ${_dda_vec}/paper)
set_tests_properties(vectors.detects_corruption PROPERTIES FIXTURES_REQUIRED vec_paper
                     ENVIRONMENT DDA_BUILD_DIR=${PROJECT_BINARY_DIR} RESOURCE_LOCK vec_bench_build)
# The bench's field table is generated from hw_params.hpp: the checked-in copy must match.
add_test(NAME vectors.fields_in_sync
         COMMAND ${DDA_BASH_EXE} -c "$<TARGET_FILE:dda> gen-params --kind vector-fields | diff - ${PROJECT_SOURCE_DIR}/tb/hdl/dda_vec_fields.vh")
set_tests_properties(vectors.fields_in_sync PROPERTIES LABELS rtl)
# The paper's and the lathe example's vector sets, written to the same directory names,
# are byte-identical to the checked-in checksums (first taken before the restructuring of
# the models into libraries; the third axis widened the command and expected words, and
# left the inputs and iterations, iter.hex and iterations.csv, unchanged).
add_test(NAME baseline.vector_sets COMMAND sha256sum --quiet -c ${CMAKE_CURRENT_SOURCE_DIR}/data/vector-sets-sha256.txt
         WORKING_DIRECTORY ${_dda_vec})
set_tests_properties(baseline.vector_sets PROPERTIES FIXTURES_REQUIRED "vec_paper;vec_lathe" LABELS baseline)

# An assertion written beside the logic fires on a mutated RTL copy, under Verilator
# (--assert) and Icarus, on the paper's vector set (tb/hdl/dda_vec_tb.v).
dda_rtl_test(rtl.assertions_fire NEEDS IVERILOG VVP VERILATOR
             COMMAND ${_dda_scripts}/assert-mutants.sh ${_dda_vec}/paper)
dda_rtl_test(rtl.fast.assertions_fire NEEDS IVERILOG VVP VERILATOR
             COMMAND ${_dda_scripts}/assert-mutants.sh --impl fast ${_dda_vec}/paper)
set_tests_properties(rtl.assertions_fire PROPERTIES FIXTURES_REQUIRED vec_paper
                     ENVIRONMENT DDA_BUILD_DIR=${PROJECT_BINARY_DIR})
set_tests_properties(rtl.fast.assertions_fire PROPERTIES FIXTURES_REQUIRED vec_paper
                     ENVIRONMENT DDA_BUILD_DIR=${PROJECT_BINARY_DIR})

# Bus-level sets of the motion block (`dda vectors --bus`, label motion): the paper's
# example; the lathe example with ce_i high 80% of the cycles; three arcs queued while
# the block runs, on pipelined cycles; an abort in the middle of an arc. Each through
# tb/hdl/dda_bus_tb.v on Icarus and Verilator; a corrupted expected value fails both.
set(_dda_bvec ${CMAKE_CURRENT_BINARY_DIR}/bus_vec_sets)
file(MAKE_DIRECTORY ${_dda_bvec})
function(dda_bus_vec_set name)
  add_test(NAME vectors.bus.gen_${name} COMMAND $<TARGET_FILE:dda> vectors --bus --out-dir ${name} ${ARGN}
           WORKING_DIRECTORY ${_dda_bvec})
  set_tests_properties(vectors.bus.gen_${name} PROPERTIES FIXTURES_SETUP bvec_${name} LABELS "rtl;motion")
  dda_rtl_test(vectors.bus.${name} NEEDS IVERILOG VVP VERILATOR
               COMMAND ${_dda_scripts}/vector-bench.sh --bus ${_dda_bvec}/${name})
  set_tests_properties(vectors.bus.${name} PROPERTIES FIXTURES_REQUIRED bvec_${name} LABELS "rtl;motion"
                       ENVIRONMENT DDA_BUILD_DIR=${PROJECT_BINARY_DIR} RESOURCE_LOCK vec_bench_build_bus)
endfunction()
dda_bus_vec_set(paper --a 10 --b 6 --bits 4 --preload zero)
# Drive timings and a feed: the paper's example at a feed in steps per second
# for a 48 MHz clock with slow-drive timings, the lathe example at a constant increment.
dda_bus_vec_set(paper_timed --a 10 --b 6 --bits 4 --preload zero --timing-x 5,3,4,2 --timing-y 2,9,0,3
                --polarity 5 --feed-rate 400000 --clock 48000000 --seed 5)
dda_bus_vec_set(lathe_timed ${_dda_lathe} --preload zero --timing 2,2,3,1 --feed-increment 3221225472 --pipelined --seed 9)
set_property(TEST vectors.bus.paper_timed vectors.bus.lathe_timed APPEND PROPERTY LABELS stepdir)
dda_bus_vec_set(lathe ${_dda_lathe} --preload zero --ce-percent 80 --seed 3)
dda_bus_vec_set(queue --a 10 --b 6 --bits 4 --preload zero --pipelined --ce-percent 90 --seed 7
                --then "--a 300 --b 200 --angle 30 --preload half --from-theta 10 --to-theta 200"
                --then "--a 50 --b 20 --preload half --dir cw --center 5,-7 --from-theta 45 --to-theta 45")
dda_bus_vec_set(abort --a 300 --b 200 --preload half --abort-after 400 --seed 5)
# The block's post-synthesis netlist (synth_ice40, Yosys' cell models) on two of those
# sets, every output every cycle, and the LUTs that drive step_x_o and read data bit 0
# inverted, which must fail (scripts/netlist-sim.sh): about a minute of Yosys and Icarus,
# so in the long lane (`ctest -L netlist`).
dda_rtl_test(netlist.post_synthesis NEEDS YOSYS IVERILOG VVP
             COMMAND ${_dda_scripts}/netlist-sim.sh --mutants 0 ${_dda_bvec}/paper ${_dda_bvec}/abort)
set_tests_properties(netlist.post_synthesis PROPERTIES FIXTURES_REQUIRED "bvec_paper;bvec_abort"
                     LABELS "rtl;motion;netlist;long" TIMEOUT 900 ENVIRONMENT DDA_BUILD_DIR=${PROJECT_BINARY_DIR})
# The board top (rtl/board/, docs/board.md): its pins and settings against docs/board.md
# (tests/check-board.py); its RTL on the board's five vector sets (scripts/board-sets.sh:
# the block behind SPI in the board's build), every pin and register on every cycle, on
# Icarus (about 40 s with the sets' writing). Its bitstream and both netlists on the same sets with the LUT
# mutants, 10 random ones of each kind: the long lane (scripts/bitstream.sh, scripts/board-sim.sh;
# over an hour on 2 cores).
add_test(NAME board.pins COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/check-board.py ${PROJECT_BINARY_DIR})
set_tests_properties(board.pins PROPERTIES LABELS "docs;board")
# The motion tops' port tables in docs/design.md ("Ports") against their port lists.
add_test(NAME docs.ports COMMAND python3 ${CMAKE_CURRENT_SOURCE_DIR}/check-ports.py)
set_tests_properties(docs.ports PROPERTIES LABELS "docs")
set(_dda_board_sets ${CMAKE_CURRENT_BINARY_DIR}/board_sets)
add_test(NAME board.gen_sets COMMAND ${_dda_scripts}/board-sets.sh ${_dda_board_sets})
set_tests_properties(board.gen_sets PROPERTIES FIXTURES_SETUP board_sets LABELS "rtl;motion;board"
                     ENVIRONMENT DDA_BUILD_DIR=${PROJECT_BINARY_DIR})
set(_dda_board_set_dirs ${_dda_board_sets}/program ${_dda_board_sets}/hold ${_dda_board_sets}/softstop
    ${_dda_board_sets}/estop ${_dda_board_sets}/homing)
dda_rtl_test(board.rtl NEEDS IVERILOG VVP COMMAND ${_dda_scripts}/board-sim.sh --netlist rtl ${_dda_board_set_dirs})
set_tests_properties(board.rtl PROPERTIES FIXTURES_REQUIRED board_sets LABELS "rtl;motion;board"
                     ENVIRONMENT DDA_BUILD_DIR=${PROJECT_BINARY_DIR})
dda_rtl_test(board.netlists NEEDS YOSYS NEXTPNR ICEPACK ICETIME IVERILOG VVP
             COMMAND ${_dda_scripts}/board-sim.sh --netlist all --mutants 10 ${_dda_board_set_dirs})
set_tests_properties(board.netlists PROPERTIES FIXTURES_REQUIRED board_sets LABELS "rtl;motion;board;netlist;long"
                     TIMEOUT 7200 ENVIRONMENT DDA_BUILD_DIR=${PROJECT_BINARY_DIR})
# The pacer's comparisons at their thresholds on the bus: on a clock of 2^20 Hz the entry
# speeds and the acceleration are whole fields, the cruise speed exactly one ramp step
# above the minimum speed, and two ramp steps less one unit (tests/test_pace.cpp checks
# the fields); a circle of radius 2, its pieces' exits equal to the cruise speed.
dda_bus_vec_set(pace_step --a 2 --b 2 --from 2,0 --to 2,0 --feed-rate 1000.0625 --accel 65536 --vmin 1000
                --clock 1048576)
dda_bus_vec_set(pace_step_less --a 2 --b 2 --from 2,0 --to 2,0 --feed-rate 1000.124755859375 --accel 65536
                --vmin 1000 --clock 1048576)
set_property(TEST vectors.bus.gen_pace_step vectors.bus.pace_step vectors.bus.gen_pace_step_less
             vectors.bus.pace_step_less APPEND PROPERTY LABELS pacer)
# Direction reversals on the step/dir stages' look-ahead: lines back to back along X and
# then Y that turn round at full speed, the reversed step waiting on dirhold (2 clocks on
# X, 6 on Y, dirsetup 0) while the next one comes: the core must be held exactly until
# the waiting step can leave.
dda_bus_vec_set(reversals --line --from 0,0 --to 60,0 --then "--line --from 60,0 --to 0,0"
                --then "--line --from 0,0 --to 60,0" --then "--line --from 60,0 --to 60,60"
                --then "--line --from 60,60 --to 60,0" --then "--line --from 60,0 --to 60,60"
                --timing-x 1,1,0,2 --timing-y 1,1,0,6)
set_property(TEST vectors.bus.gen_reversals vectors.bus.reversals APPEND PROPERTY LABELS stepdir)
# The override below 100% on paced pieces back to back: the cruise speed times the
# override is then below the exit speeds, which the pacer must not head for when it
# decides to slow down near a piece's end (a large acceleration makes the braking
# distances differ by less than the margin there).
dda_bus_vec_set(paced_slower --line --from 0,0 --to 20,0 --then "--line --from 20,0 --to 40,10"
                --then "--line --from 40,10 --to 60,10" --feed-rate 8000 --accel 6e7 --vmin 500 --clock 2e6
                --override 95 --override-at 100)
set_property(TEST vectors.bus.gen_paced_slower vectors.bus.paced_slower APPEND PROPERTY LABELS pacer)
# The machine-input scenarios (tb/scenarios/io_scenarios.hpp, label io): the block on a
# simulated machine, its input pins in the set.
foreach(_scn estop limit-hard limit-decel homing probing snapshot glitches overflow limits ranges)
  string(REPLACE "-" "_" _name "io_${_scn}")
  dda_bus_vec_set(${_name} --io-scenario ${_scn})
  set_property(TEST vectors.bus.gen_${_name} vectors.bus.${_name} APPEND PROPERTY LABELS io)
endforeach()
dda_bus_vec_set(paper_macro --program ${PROJECT_SOURCE_DIR}/examples/lathe-paper-macro.ngc --machine lathe
                --start 60,5 --feed-increment 2621440000 --seed 17)
set_property(TEST vectors.gen_paper_macro vectors.paper_macro vectors.bus.gen_paper_macro vectors.bus.paper_macro
             APPEND PROPERTY LABELS program)
# A program at its planned speeds (docs/programs.md, "Feeds and speeds"): the pacer's
# entries from the speed plan (corner, arc, ellipse cut for its curvature, dwell,
# reversal), with drive timings, at 600 kHz (about 580,000 cycles).
dda_bus_vec_set(feeds --program ${PROJECT_SOURCE_DIR}/examples/feeds.ngc --step 0.02 --speeds --accel 2000
                --clock 6e5 --timing 2,2,1,1 --seed 31)
set_property(TEST vectors.bus.gen_feeds vectors.bus.feeds APPEND PROPERTY LABELS "program;speed")
# The three-axis examples (the third axis through its own step/dir stage): a helix with
# Z timings and inverted Z outputs, a pocket on pipelined cycles with the X and Y
# direction outputs inverted (both ways on both axes), the drilling cycles at
# a feed, 3-D lines with ce_i low a tenth of the time, arcs in the three planes (the
# entry's axes routing the core's to the stages).
dda_bus_vec_set(helix --program ${PROJECT_SOURCE_DIR}/examples/helix.ngc --step 0.005 --timing-z 3,2,2,1
                --polarity 48 --seed 21)
dda_bus_vec_set(pocket --program ${PROJECT_SOURCE_DIR}/examples/pocket.ngc --step 0.005 --pipelined --polarity 10
                --seed 23)
dda_bus_vec_set(drilling --program ${PROJECT_SOURCE_DIR}/examples/drilling.ngc --step 0.005 --feed-increment 2621440000
                --timing 1,1,1,1 --seed 25)
dda_bus_vec_set(lines_3d --program ${PROJECT_SOURCE_DIR}/examples/lines-3d.ngc --ce-percent 90 --seed 27)
dda_bus_vec_set(planes --program ${PROJECT_SOURCE_DIR}/examples/planes.ngc --step 0.005 --timing 2,1,1,1 --seed 29)
set_property(TEST vectors.bus.gen_helix vectors.bus.helix vectors.bus.gen_pocket vectors.bus.pocket
             vectors.bus.gen_drilling vectors.bus.drilling vectors.bus.gen_lines_3d vectors.bus.lines_3d
             vectors.bus.gen_planes vectors.bus.planes
             APPEND PROPERTY LABELS "program;stepdir")
# Paced by the pacer (2 MHz, 1.5e6 steps/s^2, short sets): a quarter of 300 x 200 at
# 8,000 steps/s (a ramp of 21 steps; the block follows at most 8,680 here) with an
# override change to 150% and a feed hold and its end; the same with a soft stop; a
# line at 15,000 steps/s (a ramp of 75 steps) with the watchdog running out.
set(_dda_paced --a 300 --b 200 --preload half --from-theta 0 --to-theta 90 --feed-rate 8000 --accel 1.5e6
    --vmin 1000 --clock 2e6)
dda_bus_vec_set(paced ${_dda_paced} --override 150 --override-at 30000 --hold-at 45000 --resume-at 60000 --seed 31)
dda_bus_vec_set(soft_stop ${_dda_paced} --soft-stop-at 30000 --timing 2,2,1,1 --pipelined --seed 33)
dda_bus_vec_set(watchdog --line --from 0,0 --to 400,150 --feed-rate 15000 --accel 1.5e6 --clock 2e6 --watchdog 25000 --seed 35)
set_property(TEST vectors.bus.gen_paced vectors.bus.paced vectors.bus.gen_soft_stop vectors.bus.soft_stop
             vectors.bus.gen_watchdog vectors.bus.watchdog APPEND PROPERTY LABELS pacer)
dda_rtl_test(vectors.bus.detects_corruption_paced NEEDS IVERILOG VVP VERILATOR
             COMMAND ${_dda_scripts}/vector-bench.sh --bus --corrupt 50000 pos_y_q ${_dda_bvec}/paced)
set_tests_properties(vectors.bus.detects_corruption_paced PROPERTIES FIXTURES_REQUIRED bvec_paced
                     LABELS "rtl;motion;pacer" ENVIRONMENT DDA_BUILD_DIR=${PROJECT_BINARY_DIR}
                     RESOURCE_LOCK vec_bench_build_bus)
dda_rtl_test(vectors.bus.detects_corruption NEEDS IVERILOG VVP VERILATOR
             COMMAND ${_dda_scripts}/vector-bench.sh --bus --corrupt 60 pos_x_q ${_dda_bvec}/paper)
set_tests_properties(vectors.bus.detects_corruption PROPERTIES FIXTURES_REQUIRED bvec_paper LABELS "rtl;motion"
                     ENVIRONMENT DDA_BUILD_DIR=${PROJECT_BINARY_DIR} RESOURCE_LOCK vec_bench_build_bus)
add_test(NAME vectors.bus.fields_in_sync
         COMMAND ${DDA_BASH_EXE} -c "$<TARGET_FILE:dda> gen-params --kind motion-vector-fields | diff - ${PROJECT_SOURCE_DIR}/tb/hdl/dda_bus_vec_fields.vh && $<TARGET_FILE:dda> gen-params --kind axil-vector-fields | diff - ${PROJECT_SOURCE_DIR}/tb/hdl/dda_axil_vec_fields.vh && $<TARGET_FILE:dda> gen-params --kind spi-vector-fields | diff - ${PROJECT_SOURCE_DIR}/tb/hdl/dda_spi_vec_fields.vh")
set_tests_properties(vectors.bus.fields_in_sync PROPERTIES LABELS "motion;bridges")
# The block behind its bridges (label bridges): the paper's example and three arcs
# queued while the block runs, over AXI4-Lite and over SPI; the paper's example with
# drive timings and a feed over AXI4-Lite; a corrupted expected value fails both
# simulators.
dda_bus_vec_set(axil_paper --bridge axil --a 10 --b 6 --bits 4 --preload zero)
dda_bus_vec_set(axil_queue --bridge axil --a 10 --b 6 --bits 4 --preload zero --ce-percent 90 --seed 7
                --then "--a 300 --b 200 --angle 30 --preload half --from-theta 10 --to-theta 200")
dda_bus_vec_set(axil_paper_timed --bridge axil --a 10 --b 6 --bits 4 --preload zero --timing-x 5,3,4,2
                --timing-y 2,9,0,3 --polarity 5 --feed-rate 400000 --clock 48000000 --seed 5)
dda_bus_vec_set(spi_paper --bridge spi --a 10 --b 6 --bits 4 --preload zero)
dda_bus_vec_set(spi_queue --bridge spi --a 10 --b 6 --bits 4 --preload zero --ce-percent 90 --seed 7
                --then "--a 300 --b 200 --angle 30 --preload half --from-theta 10 --to-theta 200")
foreach(_name axil_paper axil_queue axil_paper_timed spi_paper spi_queue)
  set_property(TEST vectors.bus.gen_${_name} vectors.bus.${_name} APPEND PROPERTY LABELS bridges)
endforeach()
foreach(_bridge axil spi)
  dda_rtl_test(vectors.bus.${_bridge}_detects_corruption NEEDS IVERILOG VVP VERILATOR
               COMMAND ${_dda_scripts}/vector-bench.sh --bus --corrupt 200 pos_x_q ${_dda_bvec}/${_bridge}_paper)
  set_tests_properties(vectors.bus.${_bridge}_detects_corruption PROPERTIES FIXTURES_REQUIRED bvec_${_bridge}_paper
                       LABELS "rtl;motion;bridges" ENVIRONMENT DDA_BUILD_DIR=${PROJECT_BINARY_DIR}
                       RESOURCE_LOCK vec_bench_build_bus)
endforeach()
# The motion block's waveform: `dda vectors --bus --vcd` runs the RTL through the set's
# cycles; the GTKWave save file names only signals it declares, and is what
# `dda gen-params --kind gtkw-motion` writes.
add_test(NAME gtkw.motion
         COMMAND ${DDA_BASH_EXE} -c "$<TARGET_FILE:dda> vectors --bus --out-dir '${_dda_bvec}/gtkw' --vcd '${_dda_bvec}/motion.vcd' --a 10 --b 6 --bits 4 --preload zero && '${PROJECT_SOURCE_DIR}/scripts/check-gtkw.sh' '${_dda_bvec}/motion.vcd' '${PROJECT_SOURCE_DIR}/docs/dda_motion.gtkw'")
set_tests_properties(gtkw.motion PROPERTIES LABELS motion)
add_test(NAME gtkw.motion_in_sync
         COMMAND ${DDA_BASH_EXE} -c "$<TARGET_FILE:dda> gen-params --kind gtkw-motion | diff - ${PROJECT_SOURCE_DIR}/docs/dda_motion.gtkw")
set_tests_properties(gtkw.motion_in_sync PROPERTIES LABELS motion)
