# SPDX-License-Identifier: Apache-2.0
# Formal proofs (label formal): scripts/formal.sh drives Yosys and yosys-smtbmc with z3.
# Included from tests/CMakeLists.txt. Widths: the small implementation at AccWidth/
# CntWidth 8/4, 12/6 and the default 51/17; the fast one's k-induction at 6/3, and its
# assertions at 8/4 (label long; its equivalence at 8/4 takes over 15 minutes with z3
# 4.8: docs/results.md). The lemmas at the default widths; covers at 8/4; every
# assertion fails on its mutant (scripts/formal-mutants.sh).
find_program(DDA_SMTBMC_EXE yosys-smtbmc REQUIRED)
find_program(DDA_Z3_EXE z3 REQUIRED)

function(dda_formal_test name)
  add_test(NAME ${name} COMMAND ${CMAKE_COMMAND} -E env DDA_BUILD_DIR=${PROJECT_BINARY_DIR} YOSYS=${DDA_YOSYS_EXE}
                                YOSYS_SMTBMC=${DDA_SMTBMC_EXE} ${DDA_BASH_EXE} ${ARGN})
  set_tests_properties(${name} PROPERTIES LABELS formal TIMEOUT 300)
endfunction()

set(_dda_formal ${PROJECT_SOURCE_DIR}/scripts/formal.sh)
dda_formal_test(formal.lemmas ${_dda_formal} lemmas)
foreach(_w 8:4 12:6 51:17)
  string(REPLACE ":" ";" _wl ${_w})
  list(GET _wl 0 _acc)
  list(GET _wl 1 _cnt)
  dda_formal_test(formal.small.props.${_acc}_${_cnt} ${_dda_formal} --impl small --acc ${_acc} --cnt ${_cnt} props)
  dda_formal_test(formal.small.equiv.${_acc}_${_cnt} ${_dda_formal} --impl small --acc ${_acc} --cnt ${_cnt} equiv)
endforeach()
dda_formal_test(formal.fast.props.6_3 ${_dda_formal} --impl fast --acc 6 --cnt 3 props)
# The fast implementation's assertions at 8/4, its widest that proves within 10 minutes
# (about 2.5 minutes; its equivalence at 8/4 did not finish in 15: docs/results.md).
dda_formal_test(formal.fast.props.8_4 ${_dda_formal} --impl fast --acc 8 --cnt 4 props)
set_tests_properties(formal.fast.props.8_4 PROPERTIES TIMEOUT 900)
dda_formal_test(formal.fast.equiv.6_3 ${_dda_formal} --impl fast --acc 6 --cnt 3 equiv)
foreach(_impl small fast)
  dda_formal_test(formal.${_impl}.cover ${_dda_formal} --impl ${_impl} --acc 8 --cnt 4 cover)
  dda_formal_test(formal.${_impl}.mutants ${PROJECT_SOURCE_DIR}/scripts/formal-mutants.sh --impl ${_impl})
endforeach()
# The buses (scripts/formal-bus.sh): the block's Wishbone slave, the AXI4-Lite and SPI
# bridges by k-induction, and a mutant of each failing its proof; the step/dir stage
# with the same script, its mutants among the buses'.
set(_dda_formal_bus ${PROJECT_SOURCE_DIR}/scripts/formal-bus.sh)
dda_formal_test(formal.bus.wb ${_dda_formal_bus} wb)
foreach(_job axil spi)
  dda_formal_test(formal.bus.${_job} ${_dda_formal_bus} ${_job})
  set_tests_properties(formal.bus.${_job} PROPERTIES LABELS "formal;bridges")
endforeach()
# The step/dir stage's four timings, its buffer and its hold, at the block's timing width.
dda_formal_test(formal.stepdir ${_dda_formal_bus} stepdir)
set_tests_properties(formal.stepdir PROPERTIES LABELS "formal;stepdir")
dda_formal_test(formal.bus.mutants ${PROJECT_SOURCE_DIR}/scripts/formal-bus-mutants.sh)
set_tests_properties(formal.bus.mutants PROPERTIES LABELS "formal;bridges")
