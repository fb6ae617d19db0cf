// SPDX-License-Identifier: Apache-2.0
// The motion block on the Lattice iCE40-HX8K breakout board (ICE40HX8K-B-EVN;
// docs/board.md: the pins, the wiring of a drive and of the switches, the bitstream):
// the block behind its SPI slave (rtl/dda_motion_spi.v) in the board's build, without
// the pacer (Pacer 0: it does not fit the HX8K with it, docs/results.md "The block's
// builds"), three axes and the machine inputs. Pins: rtl/board/dda_hx8k_evn.pcf.
// Board build: pacer=0
// (the spec of motion::Build the instance below sets; scripts/board-sim.sh reads it, and
// tests/check-board.py checks the instance's parameters against `dda build` of it).
//   - The clock: the board's 12 MHz oscillator through the PLL (SB_PLL40_CORE) to
//     ClockHz; DIVR, DIVF, DIVQ and FILTER_RANGE are `icepll -i 12 -o` its MHz, which
//     tests/check-board.py checks.
//   - The SPI slave on the lines the FT2232H's channel A drives (the configuration SPI
//     bus, shared with the board's flash): MISO is driven only while the slave's CS_n is
//     low, through an SB_IO with an output enable, so that the flash and iceprog keep
//     the line otherwise.
//   - Reset: a power-on reset (2^PorBits clocks after the PLL locks) and the reset pin
//     (rst_ni, pulled up: low holds the block in reset), synchronized by two flip-flops;
//     the block's reset is a register of both, so it follows the pin SyncEdges = 3
//     edges late, once the power-on count is done.
//   - ce_i tied high: the block paces itself (every entry at its feed increment).
//   - Each axis' drive enable (active low, as most step/dir drives' ENA-): low while
//     the block is out of reset; high (the drive off) through configuration (the pins
//     are pulled up then), the power-on reset and the reset pin.
//   - LEDs: led_o[0] a heartbeat (the PLL's clock divided by 2^HeartBits), [1] the
//     E-stop pin low, [2] irq_o (with IRQ_ENABLE.err alone, STATUS.err), [3] busy_o,
//     [4] the PLL locked; [7:5] off.
`include "dda_motion_regs.vh"

module dda_hx8k_evn #(
  parameter integer ClockHz     = 30_000_000,  // the block's clock, from the PLL
  parameter [3:0]   PllDivr     = 4'd0,        // icepll -i 12 -o 30
  parameter [6:0]   PllDivf     = 7'd79,
  parameter [2:0]   PllDivq     = 3'd5,
  parameter [2:0]   PllFilter   = 3'd1,
  parameter integer PorBits     = 8,
  parameter integer HeartBits   = 25
) (
  input  wire       clk_12m_i,  // the board's oscillator
  input  wire       rst_ni,     // reset pin, active low (pulled up)
  // the SPI slave (mode 0), from the FT2232H
  input  wire       spi_csn_i,
  input  wire       spi_sck_i,
  input  wire       spi_mosi_i,
  inout  wire       spi_miso_io,
  // the drives
  output wire       step_x_o,
  output wire       dir_x_o,
  output wire       en_x_no,
  output wire       step_y_o,
  output wire       dir_y_o,
  output wire       en_y_no,
  output wire       step_z_o,
  output wire       dir_z_o,
  output wire       en_z_no,
  // the machine's inputs (pulled up), as on dda_motion
  input  wire       estop_ni,
  input  wire [5:0] limit_i,
  input  wire [2:0] home_i,
  input  wire       probe_i,
  output wire [7:0] led_o
);

  localparam integer SyncEdges = 3;  // the reset pin to the block's reset (tb/hdl/dda_board_tb.v)

  // ---- the clock ----
  wire clk, locked;
  SB_PLL40_CORE #(
    .FEEDBACK_PATH("SIMPLE"),
    .DIVR        (PllDivr),
    .DIVF        (PllDivf),
    .DIVQ        (PllDivq),
    .FILTER_RANGE(PllFilter)
  ) u_pll (
    .REFERENCECLK   (clk_12m_i),
    .PLLOUTCORE     (),
    .PLLOUTGLOBAL   (clk),
    .EXTFEEDBACK    (1'b0),
    .DYNAMICDELAY   (8'd0),
    .LOCK           (locked),
    .BYPASS         (1'b0),
    .RESETB         (1'b1),
    .LATCHINPUTVALUE(1'b0),
    .SDO            (),
    .SDI            (1'b0),
    .SCLK           (1'b0)
  );

  // ---- reset ----
  // The flip-flops of an iCE40 are 0 after configuration: the count starts at 0.
  reg [PorBits:0] por_q   = '0;
  reg [1:0]       pin_q   = '0;  // the reset pin, synchronized
  reg             rst_n_q = 1'b0;  // the block's reset
  always @(posedge clk) begin
    if (!locked) por_q <= '0;
    else if (!por_q[PorBits]) por_q <= por_q + 1'b1;
    pin_q   <= {pin_q[0], rst_ni};
    rst_n_q <= por_q[PorBits] & pin_q[1];
  end

  // ---- the block ----
  wire miso, miso_oe, busy, irq;
  dda_motion_spi #(
    .Inputs(1),
    .Axes  (3),
    .Pacer (0)
  ) u_block (
    .clk_i        (clk),
    .rst_ni       (rst_n_q),
    .spi_csn_i    (spi_csn_i),
    .spi_sck_i    (spi_sck_i),
    .spi_mosi_i   (spi_mosi_i),
    .spi_miso_o   (miso),
    .spi_miso_oe_o(miso_oe),
    .ce_i         (1'b1),
    .estop_ni     (estop_ni),
    .limit_i      (limit_i),
    .home_i       (home_i),
    .probe_i      (probe_i),
    .step_x_o     (step_x_o),
    .step_y_o     (step_y_o),
    .dir_x_o      (dir_x_o),
    .dir_y_o      (dir_y_o),
    .step_z_o     (step_z_o),
    .dir_z_o      (dir_z_o),
    .busy_o       (busy),
    .irq_o        (irq)
  );

  // MISO: an output with an enable (PIN_TYPE: output enabled by OUTPUT_ENABLE, no
  // input register), high impedance while CS_n is high.
  SB_IO #(
    .PIN_TYPE(6'b1010_01),
    .PULLUP  (1'b0)
  ) u_miso (
    .PACKAGE_PIN      (spi_miso_io),
    .LATCH_INPUT_VALUE(1'b0),
    .CLOCK_ENABLE     (1'b1),
    .INPUT_CLK        (1'b0),
    .OUTPUT_CLK       (1'b0),
    .OUTPUT_ENABLE    (miso_oe),
    .D_OUT_0          (miso),
    .D_OUT_1          (1'b0),
    .D_IN_0           (),
    .D_IN_1           ()
  );

  assign en_x_no = ~rst_n_q;
  assign en_y_no = ~rst_n_q;
  assign en_z_no = ~rst_n_q;

  // ---- LEDs ----
  reg [HeartBits-1:0] heart_q = '0;
  always @(posedge clk) heart_q <= heart_q + 1'b1;
  assign led_o = {3'b000, locked, busy, irq, ~estop_ni, heart_q[HeartBits-1]};

endmodule
