// SPDX-License-Identifier: Apache-2.0
// Control of the DDA core (docs/design.md, "Control" and "Behaviour, edge by edge"):
// the state machine state_q (idle, run) and the one-cycle pulses done_q, err_q, iter_q.
//
// Run with ce_i high does exactly one of (in this order)
//   finished  every counter 0                          -> idle, done_q = 1
//   stalled   no active axis can carry (can_x/y/z low) -> idle, err_q = 1
//   iterate   iterate_o = 1, iter_q = 1; every counter 0 after it -> idle, done_q = 1
// The command ends (finishing) on a finished edge or on its last iteration's edge.
// cmd_ready_o is high while idle and while finishing: cmd_valid_i then loads the next
// command on that edge (load_o) and the state is run, so commands run back to back.
// Run with ce_i low, and idle without a load: the pulses take 0 and nothing else changes.
`include "dda_params.vh"
`include "dda_assert.vh"

module dda_ctrl (
  input  wire clk_i,
  input  wire rst_ni,       // synchronous, active low
  input  wire ce_i,
  input  wire cmd_valid_i,
  output wire cmd_ready_o,
  input  wire active_x_i,   // counter X non-zero
  input  wire active_y_i,
  input  wire active_z_i,
  input  wire can_x_i,      // X active with a non-zero integrand
  input  wire can_y_i,
  input  wire can_z_i,
  input  wire last_x_i,     // counter X is 0 after this iteration
  input  wire last_y_i,
  input  wire last_z_i,
  output wire load_o,       // load the command on this edge
  output wire iterate_o,    // iterate on this edge
  output wire busy_o,
  output wire done_o,
  output wire err_o,
  output wire iter_o
);

  localparam [`DDA_STATE_WIDTH-1:0] StIdle = `DDA_STATE_IDLE;
  localparam [`DDA_STATE_WIDTH-1:0] StRun  = `DDA_STATE_RUN;

  reg [`DDA_STATE_WIDTH-1:0] state_q /* verilator public_flat_rd */;
  reg                        done_q  /* verilator public_flat_rd */;
  reg                        err_q   /* verilator public_flat_rd */;
  reg                        iter_q  /* verilator public_flat_rd */;

  reg [`DDA_STATE_WIDTH-1:0] state_d;
  reg                        done_d;
  reg                        err_d;
  reg                        iter_d;

  wire idle     = state_q == StIdle;
  wire run_ce   = (state_q == StRun) & ce_i;
  wire finished = run_ce & ~active_x_i & ~active_y_i & ~active_z_i;
  wire stalled  = run_ce & ~finished & ~can_x_i & ~can_y_i & ~can_z_i;
  wire iterate  = run_ce & ~finished & ~stalled;
  // The command ends on this edge: the next one may load on the same edge, so
  // back-to-back commands run with no idle cycle between them.
  wire finishing = finished | (iterate & last_x_i & last_y_i & last_z_i);

  assign cmd_ready_o = idle | finishing;
  assign load_o      = cmd_ready_o & cmd_valid_i;
  assign iterate_o   = iterate;

  always @(*) begin
    state_d = state_q;
    iter_d  = iterate;
    done_d  = finishing;
    err_d   = stalled;
    if (load_o) begin
      state_d = StRun;
    end else if (finishing | stalled) begin
      state_d = StIdle;
    end
  end

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q <= StIdle;
      done_q  <= 1'b0;
      err_q   <= 1'b0;
      iter_q  <= 1'b0;
    end else begin
      state_q <= state_d;
      done_q  <= done_d;
      err_q   <= err_d;
      iter_q  <= iter_d;
    end
  end

  assign busy_o = state_q == StRun;
  assign done_o = done_q;
  assign err_o  = err_q;
  assign iter_o = iter_q;

`ifndef SYNTHESIS
  // Assertions (rtl/dda_assert.vh): in run with ce_i exactly one of finished, stalled
  // and iterate; done and err never together; in run with ce_i low no load and no
  // iteration (so only the pulse registers change); busy_o is the run state.
  always @(posedge clk_i) begin
    if (rst_ni) begin
      `DDA_ASSERT(!run_ce || ({2'b00, finished} + {2'b00, stalled} + {2'b00, iterate}) == 3'd1,
                  "ASSERTION dda_ctrl: in run with ce_i not exactly one of finished, stalled, iterate")
      `DDA_ASSERT(!(done_d && err_d), "ASSERTION dda_ctrl: done and err together")
      `DDA_ASSERT(!(state_q == StRun && !ce_i) || (!load_o && !iterate), "ASSERTION dda_ctrl: run with ce_i low changes state")
      `DDA_ASSERT(busy_o == (state_q == StRun), "ASSERTION dda_ctrl: busy_o differs from running")
    end
  end
`endif

endmodule
