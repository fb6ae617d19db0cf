// SPDX-License-Identifier: Apache-2.0
// The board top (rtl/board/dda_hx8k_evn.v), as RTL or as a netlist of it (post-synthesis
// or read back from the routed bitstream: scripts/board-sim.sh), run on a vector set of
// the block behind its SPI bridge in the board's build (`dda vectors --bus --bridge spi
// --build pacer=0`, docs/vectors.md) and compared at its pins on every cycle.
//   - The PLL (SB_PLL40_CORE) is the model of tb/hdl/dda_board_pll.v: its output is the
//     oscillator's input, locked at once; the bench's clock is the block's, and a cycle
//     comparison does not depend on its frequency.
//   - Before the set's first cycle, the reset pin is held low until the power-on count is
//     done (2^PorBits + 8 clocks). The reset pin reaches the block's reset SyncEdges
//     edges later (the top's synchronizer): the bench drives it with the reset of the
//     cycle that many ahead, so that the block leaves reset on the set's cycle.
//   - The board ties ce_i high: a set with ce_i low on any cycle is refused.
//   - Compared after every edge: step and direction of each axis, MISO (high impedance
//     while the set's spi_miso_oe_o is low, the set's spi_miso_o while it is high), the
//     busy and irq LEDs (led_o[3], led_o[2]), each axis' enable (low while the block is
//     out of reset); with DDA_BOARD_REGS, also the set's registers (positions, queue
//     level, DONE_COUNT), by their names in the RTL or (DDA_BOARD_NETLIST) in Yosys'
//     flattened netlist. The routed netlist keeps no register names: pins only.
// The first mismatch prints "MISMATCH cycle N field F: expected E, got G" and fails.
`include "dda_spi_vec_fields.vh"

module dda_board_tb;

  localparam integer PorBits   = 8;  // the top's defaults (tests/check-board.py compares them)
  localparam integer SyncEdges = 3;

  reg        clk = 1'b0;
  reg        rst_pin = 1'b0;
  reg        rst_n = 1'b0, ce = 1'b1, csn = 1'b1, sck = 1'b0, mosi = 1'b0;
  reg        estop_n = 1'b1, probe = 1'b0;
  reg  [5:0] limit = 6'd0;
  reg  [2:0] home = 3'd0;
  wire       miso_pin, step_x, dir_x, en_x_n, step_y, dir_y, en_y_n, step_z, dir_z, en_z_n;
  wire [7:0] led;

  dda_hx8k_evn dut (
    .clk_12m_i  (clk),
    .rst_ni     (rst_pin),
    .spi_csn_i  (csn),
    .spi_sck_i  (sck),
    .spi_mosi_i (mosi),
    .spi_miso_io(miso_pin),
    .step_x_o   (step_x),
    .dir_x_o    (dir_x),
    .en_x_no    (en_x_n),
    .step_y_o   (step_y),
    .dir_y_o    (dir_y),
    .en_y_no    (en_y_n),
    .step_z_o   (step_z),
    .dir_z_o    (dir_z),
    .en_z_no    (en_z_n),
    .estop_ni   (estop_n),
    .limit_i    (limit),
    .home_i     (home),
    .probe_i    (probe),
    .led_o      (led)
  );

`ifdef DDA_BOARD_REGS
`ifdef DDA_BOARD_NETLIST
  wire [135:0] regs = {dut.\u_block.u_motion.pos_x_q , dut.\u_block.u_motion.pos_y_q , dut.\u_block.u_motion.pos_z_q ,
                       dut.\u_block.u_motion.level_q , dut.\u_block.u_motion.done_count_q };
`else
  wire [135:0] regs = {dut.u_block.u_motion.pos_x_q, dut.u_block.u_motion.pos_y_q, dut.u_block.u_motion.pos_z_q,
                       dut.u_block.u_motion.level_q, dut.u_block.u_motion.done_count_q};
`endif
`endif

  reg [31:0]                    counts [0:0];
  reg [`DDA_BVEC_IN_WIDTH-1:0]  ahead [0:SyncEdges];  // rows n .. n + SyncEdges
  reg [`DDA_BVEC_IN_WIDTH-1:0]  last;
  reg [`DDA_BVEC_EXP_WIDTH-1:0] vexp, got;
  reg                           pin_rst_n, miso_got, oe_got, en_want;
  integer                       fin, fexp, cyc_n, ncycles, r, k, read_rows;
  string                        dir;

  // The next row of the set into ahead[SyncEdges] (past the end: the last row again).
  task automatic next_row;
    begin
      if (read_rows < ncycles) begin
        r = $fscanf(fin, "%h\n", last);
        if (r != 1) $fatal(1, "dda_board_tb: cycle_in.hex ends before row %0d", read_rows);
        read_rows = read_rows + 1;
      end
      ahead[SyncEdges] = last;
    end
  endtask

  // The reset of a row (the first field of the input word).
  function automatic reg row_rst_n(input reg [`DDA_BVEC_IN_WIDTH-1:0] v);
    row_rst_n = v[`DDA_BVEC_IN_WIDTH-1];
  endfunction

  initial begin
    if (!$value$plusargs("vectors=%s", dir)) $fatal(1, "dda_board_tb: usage: +vectors=DIR");
    counts[0] = 0;
    $readmemh({dir, "/counts.hex"}, counts);
    ncycles = counts[0];
    if (ncycles < 1) $fatal(1, "dda_board_tb: %s/counts.hex: no cycles", dir);
    fin = $fopen({dir, "/cycle_in.hex"}, "r");
    fexp = $fopen({dir, "/cycle_exp.hex"}, "r");
    if (fin == 0 || fexp == 0) $fatal(1, "dda_board_tb: cannot open the cycle files in %s", dir);
    read_rows = 0;
    for (k = 0; k <= SyncEdges; k = k + 1) begin
      next_row;
      ahead[k] = ahead[SyncEdges];
    end
    // The power-on count, the reset pin low; on its last SyncEdges clocks, the pin has
    // the resets of the set's first cycles.
    for (k = 0; k < (1 << PorBits) + 8; k = k + 1) begin
      rst_pin = k >= (1 << PorBits) + 8 - SyncEdges ? row_rst_n(ahead[k - ((1 << PorBits) + 8 - SyncEdges)]) : 1'b0;
      #4 clk = 1'b1;
      #5 clk = 1'b0;
      #1;
    end
    for (cyc_n = 0; cyc_n < ncycles; cyc_n = cyc_n + 1) begin
      r = $fscanf(fexp, "%h\n", vexp);
      if (r != 1) $fatal(1, "dda_board_tb: cycle_exp.hex ends before cycle %0d", cyc_n);
      `DDA_BVEC_UNPACK(ahead[0]);
      if (ce !== 1'b1) $fatal(1, "dda_board_tb: the set has ce_i low on cycle %0d: the board ties it high", cyc_n);
      pin_rst_n = row_rst_n(ahead[SyncEdges]);
      rst_pin = pin_rst_n;
      #4;
      clk = 1'b1;
      #1;
      miso_got = vexp[145];  // (while the enable is low, the pin's state is compared: high impedance)
      oe_got   = vexp[144];
      if (vexp[144] && miso_pin !== vexp[145]) miso_got = ~vexp[145];
      if (!vexp[144] && miso_pin !== 1'bz) oe_got = 1'b1;
`ifdef DDA_BOARD_REGS
      got = {miso_got, oe_got, step_x, step_y, dir_x, dir_y, step_z, dir_z, led[3], led[2], regs};
`else
      got = {miso_got, oe_got, step_x, step_y, dir_x, dir_y, step_z, dir_z, led[3], led[2], vexp[135:0]};
`endif
      if (got !== vexp) begin
        `DDA_BVEC_REPORT(cyc_n, vexp, got)
        $fatal(1, "dda_board_tb: FAIL at cycle %0d of %0d (%s)", cyc_n, ncycles, dir);
      end
      // The enables follow the block's reset: after this edge, the next cycle's.
      en_want = ~row_rst_n(ahead[1]);
      if ({en_x_n, en_y_n, en_z_n} !== {3{en_want}}) begin
        $display("MISMATCH cycle %0d field en_n: expected %b, got %b%b%b", cyc_n, en_want, en_x_n, en_y_n, en_z_n);
        $fatal(1, "dda_board_tb: FAIL at cycle %0d of %0d (%s)", cyc_n, ncycles, dir);
      end
      for (k = 0; k < SyncEdges; k = k + 1) ahead[k] = ahead[k+1];
      next_row;
      #4;
      clk = 1'b0;
      #1;
    end
    $display("dda_board_tb: PASS: %0d cycles, every pin%s equal (%s)", ncycles,
`ifdef DDA_BOARD_REGS
             " and register",
`else
             "",
`endif
             dir);
    $finish;
  end

endmodule
