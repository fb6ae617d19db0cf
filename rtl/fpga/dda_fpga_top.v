// SPDX-License-Identifier: Apache-2.0
// Place-and-route wrapper that counts the core's own cells (scripts/synth,
// core_logic_cells): the core runs a command list from block RAM, so the only logic
// beside it is this wrapper's control. The command memory holds CMD_DEPTH words of
// DDA_CMD_WIDTH bits as 16-bit lanes, each word in two rows as the motion block's queue
// holds an entry (42 lanes at the default widths would take more EBRs than the HX8K's
// 32): 21 lanes of one iCE40 EBR each (SB_RAM40_4K, 256 x 16, two rows per word at
// CMD_DEPTH 128); EBRs are not logic cells, row0_q (the first row kept while the second
// is read) is the wrapper's. A host writes it 16 bits at a time on its own clock
// (wclk_i, we_i, waddr_i = {word, lane}, wdata_i; no read-during-write logic then), so
// synthesis cannot see its contents and the core stays general; after reset the words
// 0 .. end_i-1 are offered to the core, each two edges after the one before was taken.
// Not part of the IP: it exists so that place and route sees the core as a design would
// use it, without a 666-bit shift register in front of it.
`include "dda_params.vh"

module dda_fpga_top #(
  parameter integer CMD_DEPTH = 128,
  parameter         Impl      = "small"  // the core's implementation (dda_core.Impl)
) (
  input  wire                                  clk_i,
  input  wire                                  rst_ni,
  input  wire                                  ce_i,
  input  wire                                  wclk_i,   // the host's write clock
  input  wire                                  we_i,
  input  wire [$clog2(CMD_DEPTH)+$clog2((`DDA_CMD_WIDTH+15)/16)-1:0] waddr_i,  // {word, lane}
  input  wire [15:0]                           wdata_i,
  input  wire [$clog2(CMD_DEPTH)-1:0]          end_i,    // commands to run: 0 .. end_i-1
  output wire                                  cmd_ready_o,
  output wire                                  step_x_o,
  output wire                                  step_y_o,
  output wire                                  dir_x_o,
  output wire                                  dir_y_o,
  output wire                                  step_z_o,
  output wire                                  dir_z_o,
  output wire                                  busy_o,
  output wire                                  done_o,
  output wire                                  err_o,
  output wire                                  iter_o
);

  localparam integer AddrWidth = $clog2(CMD_DEPTH);
  localparam integer Lanes     = (`DDA_CMD_WIDTH + 15) / 16;
  localparam integer LaneBits  = $clog2(Lanes);
  localparam integer RowLanes  = (Lanes + 1) / 2;

  // The RAM reads row 0 of word addr_d after addr moves, after reset and while no word
  // is offered (the host may be writing it), then row 1 while row0_q keeps row 0: the
  // word is whole when fetch_q is 2.
  reg  [AddrWidth-1:0]  addr_q;
  reg  [1:0]            fetch_q;  // rows of word addr_q read
  wire                  cmd_valid = (fetch_q == 2'd2) & (addr_q != end_i);
  wire                  accept = cmd_valid & cmd_ready_o;
  wire [AddrWidth-1:0]  addr_d = !rst_ni ? '0 : accept ? addr_q + 1'b1 : addr_q;
  wire [1:0]            fetch_d = (!rst_ni | accept | fetch_q == 2'd0 | addr_q == end_i)
                                  ? 2'd1 : 2'd2;
  wire [16*RowLanes-1:0] rd_row;
  reg  [16*RowLanes-1:0] row0_q;
  wire [32*RowLanes-1:0] cmd_q = {rd_row, row0_q};

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      addr_q  <= '0;
      fetch_q <= 2'd0;
    end else begin
      addr_q  <= addr_d;
      fetch_q <= fetch_d;
    end
    if (fetch_q == 2'd1) row0_q <= rd_row;
  end

  wire [LaneBits-1:0]  wlane = waddr_i[LaneBits-1:0];
  wire                 wrow = wlane >= LaneBits'(RowLanes);
  wire [AddrWidth-1:0] wword = waddr_i[AddrWidth+LaneBits-1:LaneBits];
  for (genvar l = 0; l < RowLanes; l++) begin : g_lane
    reg [15:0] mem [0:2*CMD_DEPTH-1];
    reg [15:0] rd_q;
    always @(posedge wclk_i) if (we_i && (wlane == LaneBits'(l) || wlane == LaneBits'(l + RowLanes))) mem[{wword, wrow}] <= wdata_i;
    always @(posedge clk_i) rd_q <= mem[{addr_d, fetch_d == 2'd2}];
    assign rd_row[16*l+:16] = rd_q;
  end

  wire [`DDA_ACC_WIDTH-1:0] norm_v_x, norm_v_y, norm_v_z, norm_cap, norm_cap_z;
  dda_core #(.Impl(Impl)) u_core (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .ce_i        (ce_i),
    .cmd_valid_i (cmd_valid),
    .cmd_ready_o (cmd_ready_o),
    .cmd_i       (cmd_q[`DDA_CMD_WIDTH-1:0]),
    .step_x_o    (step_x_o),
    .step_y_o    (step_y_o),
    .dir_x_o     (dir_x_o),
    .dir_y_o     (dir_y_o),
    .step_z_o    (step_z_o),
    .dir_z_o     (dir_z_o),
    .busy_o      (busy_o),
    .done_o      (done_o),
    .err_o       (err_o),
    .iter_o      (iter_o),
    .norm_v_x_o  (norm_v_x),  // the pacer's norm operands: no pacer here
    .norm_v_y_o  (norm_v_y),
    .norm_v_z_o  (norm_v_z),
    .norm_cap_o  (norm_cap),
    .norm_cap_z_o(norm_cap_z)
  );
  wire unused_norm = &{1'b0, norm_v_x, norm_v_y, norm_v_z, norm_cap, norm_cap_z};

endmodule
