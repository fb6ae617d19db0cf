// SPDX-License-Identifier: Apache-2.0
// The golden model as DPI-C functions, for a SystemVerilog bench's scoreboard (the
// bench tb/dpi/dda_dpi_tb.sv shows their use; docs/verification.md "The golden model
// from other testbenches"). One plan and one reference core per process.
//
// In SystemVerilog:
//   import "DPI-C" function int  dda_plan(input string args);
//   import "DPI-C" function void dda_piece_command(input int index, output bit [`DDA_CMD_WIDTH-1:0] cmd);
//   import "DPI-C" function int  dda_ref_edge(input bit rst_n, input bit ce, input bit cmd_valid,
//                                             input bit [`DDA_CMD_WIDTH-1:0] cmd);
//   import "DPI-C" function int  dda_ref_output(input string port, input bit value);
//   import "DPI-C" function int  dda_check_record(input bit step_x, input bit step_y, input bit step_z,
//                                                 input bit dir_x, input bit dir_y, input bit dir_z);
//   import "DPI-C" function int  dda_finish();
#pragma once

#include <svdpi.h>

#ifdef __cplusplus
extern "C" {
#endif

// Plans an arc, a line or a part program from the `dda` command's options, written as
// on its command line ("--a 10 --b 6 --bits 4 --preload zero", "--program part.ngc"),
// resets the reference core; the golden run then goes a piece at a time as the bench
// compares iterations (it holds one piece's records, whatever the plan's length).
// Returns the number of pieces (commands), or -1 with the command's message printed.
int dda_plan(const char* args);
// Piece `index`'s command word (cmd_i of dda_core, `DDA_CMD_WIDTH bits).
void dda_piece_command(int index, svBitVecVal* cmd);
// Before an edge: the value of one output port of the core (by its name in
// rtl/dda_core.v) in this cycle; every output must be given between two edges. 1 with a
// line for a name that is not an output, else 0.
int dda_ref_output(const char* port, svBit value);
// The rising edge, with the inputs the core takes at it: first the outputs given since
// the last edge against the reference model's in this cycle (cmd_ready_o with this ce),
// a line for each that differs naming the port and the cycle (none before the first
// reset edge, when the core's state is not defined); then the reference core's edge.
// Returns the number of mismatches.
int dda_ref_edge(svBit rst_n, svBit ce, svBit cmd_valid, const svBitVecVal* cmd);
// On a cycle with iter_o high: the step and direction outputs against the golden run's
// next iteration record; 0 if equal, 1 with a line naming the iteration if not.
int dda_check_record(svBit step_x, svBit step_y, svBit step_z, svBit dir_x, svBit dir_y, svBit dir_z);
// At the end: prints what was compared; 0 if nothing differed and every record was met.
int dda_finish(void);

// For the program around the bench (not a DPI import): dda_finish()'s result, -1 if it
// was never called.
int dda_dpi_result(void);

#ifdef __cplusplus
}
#endif
