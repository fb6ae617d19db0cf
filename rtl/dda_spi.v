// SPDX-License-Identifier: Apache-2.0
// SPI slave (mode 0) in front of the motion block's Wishbone slave (docs/design.md, "Bus
// bridges"): one register access per complete frame, none for any other.
// A frame is CS_n low for exactly 64 rising SCK edges, most significant bit first:
//   MOSI: command (8: bit 7 write, bits 3:0 the byte lanes of a write, bits 6:4 reserved),
//         address (16: a byte address, the bits above the map's ignored), write data
//         (32), 8 bits ignored;
//   MISO: 24 zeros, the previous frame's read data (32), a status byte (8).
// The access is made once CS_n rises after the 64th edge; a frame with fewer or more
// edges makes none and sets the status' bad bit. So a read's data comes back in the next
// frame (a stream of reads returns each one frame later). Status byte, as the frame
// starts: bit 0 done (the previous frame's access has completed: its read data is the
// one in this frame), bit 1 bad (the previous frame had the wrong length), bit 2 the
// block's irq_o, bit 3 its busy_o, bits 7:4 the count of accesses made (modulo 16).
// Every input goes through a two flip-flop synchronizer (SCK, CS_n and MOSI alike), so
// SCK may be at most a quarter of the block's clock: MOSI is sampled on SCK's rising
// edge; MISO changes on the second clock edge after the first one that samples SCK
// high (two to three clocks after SCK rose: at the falling edge or after it at that
// speed, before the next rising one). CS_n falls at least two clocks before the
// first rising SCK edge and stays high at least four clocks between frames.
`include "dda_motion_regs.vh"

module dda_spi (
  input  wire                              clk_i,
  input  wire                              rst_ni,  // synchronous, active low
  // SPI slave, mode 0
  input  wire                              spi_csn_i,
  input  wire                              spi_sck_i,
  input  wire                              spi_mosi_i,
  output wire                              spi_miso_o,
  // the block's state for the status byte
  input  wire                              irq_i,
  input  wire                              busy_i,
  // Wishbone B4 pipelined master (to dda_motion)
  output wire                              wb_cyc_o,
  output wire                              wb_stb_o,
  output wire                              wb_we_o,
  output wire [`DDA_MOTION_ADDR_WIDTH-1:0] wb_adr_o,
  output wire [31:0]                       wb_dat_o,
  output wire [3:0]                        wb_sel_o,
  input  wire [31:0]                       wb_dat_i,
  input  wire                              wb_ack_i,
  input  wire                              wb_stall_i
);

  localparam integer AW = `DDA_MOTION_ADDR_WIDTH;
  // in_q keeps the frame's MOSI bits up to the data's last, the frame's bit k in
  // in_q[In-1-k]; a part's lowest bit is then at In - its first bit - its width.
  localparam integer In = `DDA_MOTION_SPI_DATA_AT + `DDA_MOTION_SPI_DATA_WIDTH;
  localparam integer CmdLo = In - `DDA_MOTION_SPI_COMMAND_AT - `DDA_MOTION_SPI_COMMAND_WIDTH;
  localparam integer AdrLo = In - `DDA_MOTION_SPI_ADDRESS_AT - `DDA_MOTION_SPI_ADDRESS_WIDTH;
  localparam integer DatLo = In - `DDA_MOTION_SPI_DATA_AT - `DDA_MOTION_SPI_DATA_WIDTH;
  localparam integer OW = `DDA_MOTION_SPI_DATA_WIDTH + `DDA_MOTION_SPI_STATUS_WIDTH;  // MISO bits to go
  localparam [6:0] DataAt = `DDA_MOTION_SPI_DATA_AT;
  localparam [6:0] Whole  = `DDA_MOTION_SPI_FRAME_BITS;  // edges of a whole frame
  localparam [6:0] Kept   = `DDA_MOTION_SPI_DATA_AT + `DDA_MOTION_SPI_DATA_WIDTH;

  // synchronizers: [0] first stage, [1] second, [2] the second's value one clock before
  reg [2:0]    csn_q /* verilator public_flat_rd */;
  reg [2:0]    sck_q /* verilator public_flat_rd */;
  reg [1:0]    mosi_q /* verilator public_flat_rd */;
  reg [6:0]    cnt_q /* verilator public_flat_rd */;  // rising edges in this frame (65: more than 64)
  reg [In-1:0] in_q /* verilator public_flat_rd */;  // command, address, data as they came in
  reg [OW-1:0] out_q /* verilator public_flat_rd */;  // read data and status still to go out
  reg          miso_q /* verilator public_flat_rd */;
  reg          cyc_q /* verilator public_flat_rd */;
  reg          stb_q /* verilator public_flat_rd */;
  reg          we_q /* verilator public_flat_rd */;
  reg [AW-1:0] adr_q /* verilator public_flat_rd */;
  reg [31:0]   dat_q /* verilator public_flat_rd */;
  reg [3:0]    sel_q /* verilator public_flat_rd */;
  reg [31:0]   rdata_q /* verilator public_flat_rd */;
  reg          done_q /* verilator public_flat_rd */;
  reg          bad_q /* verilator public_flat_rd */;
  reg [`DDA_MOTION_SPI_ST_COUNT_WIDTH-1:0] count_q /* verilator public_flat_rd */;

  wire start = csn_q[2] & ~csn_q[1];  // CS_n fell
  wire stop  = ~csn_q[2] & csn_q[1];  // CS_n rose
  wire rise  = ~csn_q[1] & sck_q[1] & ~sck_q[2];
  wire [6:0] next_cnt = cnt_q + 7'd1;
  wire whole = cnt_q == Whole;
  wire [`DDA_MOTION_SPI_STATUS_WIDTH-1:0] status;
  assign status[`DDA_MOTION_SPI_ST_DONE_LSB] = done_q & ~cyc_q;
  assign status[`DDA_MOTION_SPI_ST_BAD_LSB]  = bad_q;
  assign status[`DDA_MOTION_SPI_ST_IRQ_LSB]  = irq_i;
  assign status[`DDA_MOTION_SPI_ST_BUSY_LSB] = busy_i;
  assign status[`DDA_MOTION_SPI_ST_COUNT_LSB+:`DDA_MOTION_SPI_ST_COUNT_WIDTH] = count_q;

  assign spi_miso_o = miso_q;
  assign wb_cyc_o   = cyc_q;
  assign wb_stb_o   = stb_q;
  assign wb_we_o    = we_q;
  assign wb_adr_o   = adr_q;
  assign wb_dat_o   = dat_q;
  assign wb_sel_o   = sel_q;
  wire unused = &{1'b0, in_q[CmdLo+6:CmdLo+4], in_q[AdrLo+15:AdrLo+AW]};

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      csn_q   <= 3'b111;
      sck_q   <= 3'b000;
      mosi_q  <= 2'b00;
      cnt_q   <= 7'd0;
      in_q    <= '0;
      out_q   <= '0;
      miso_q  <= 1'b0;
      cyc_q   <= 1'b0;
      stb_q   <= 1'b0;
      we_q    <= 1'b0;
      adr_q   <= '0;
      dat_q   <= 32'd0;
      sel_q   <= 4'd0;
      rdata_q <= 32'd0;
      done_q  <= 1'b0;
      bad_q   <= 1'b0;
      count_q <= '0;
    end else begin
      csn_q  <= {csn_q[1], csn_q[0], spi_csn_i};
      sck_q  <= {sck_q[1], sck_q[0], spi_sck_i};
      mosi_q <= {mosi_q[0], spi_mosi_i};
      if (start) begin
        cnt_q  <= 7'd0;
        out_q  <= {rdata_q, status};
        miso_q <= 1'b0;
      end else if (rise) begin
        if (cnt_q <= Whole) cnt_q <= next_cnt;
        if (cnt_q < Kept) in_q <= {in_q[In-2:0], mosi_q[1]};
        if (next_cnt >= DataAt && next_cnt < Whole) begin
          miso_q <= out_q[OW-1];
          out_q  <= {out_q[OW-2:0], 1'b0};
        end else begin
          miso_q <= 1'b0;
        end
      end
      if (cyc_q) begin
        if (!wb_stall_i) stb_q <= 1'b0;
        if (wb_ack_i && !stb_q) begin
          cyc_q <= 1'b0;
          if (!we_q) rdata_q <= wb_dat_i;
        end
      end
      // (A whole frame cannot end while an access runs: it takes 128 clocks or more, the
      // block answers in two. Were it to, it is refused as a bad one.)
      if (stop) begin
        done_q <= whole & ~cyc_q;
        bad_q  <= ~whole | cyc_q;
        if (whole && !cyc_q) begin
          cyc_q   <= 1'b1;
          stb_q   <= 1'b1;
          we_q    <= in_q[CmdLo+`DDA_MOTION_SPI_WRITE_BIT];
          sel_q   <= in_q[CmdLo+:4];
          adr_q   <= in_q[AdrLo+:AW];
          dat_q   <= in_q[DatLo+:32];
          count_q <= count_q + 1'b1;
        end
      end
    end
  end

endmodule
