// SPDX-License-Identifier: Apache-2.0
// DDA_ASSERT(cond, msg): an immediate assertion written beside the logic it checks,
// inside `ifndef SYNTHESIS in a clocked block. In simulation a failure ends the run with
// $fatal and msg (Verilator needs --assert; Icarus 11 runs them as they are: a failed
// assertion with the default $error would exit 0 there). Yosys' read_verilog -formal
// defines FORMAL and reads the same condition as a formal assert (no action block).
`ifndef DDA_ASSERT_VH
`define DDA_ASSERT_VH
`ifdef FORMAL
  `define DDA_ASSERT(cond, msg) assert (cond);
`else
  `define DDA_ASSERT(cond, msg) assert (cond) else $fatal(1, msg);
`endif
`endif  // DDA_ASSERT_VH
