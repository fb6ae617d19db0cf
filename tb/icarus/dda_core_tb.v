// Self-checking Icarus bench of dda_core against the golden model's records.
//
// The expected values come from tb/tools/gen_core_vectors (golden model), never by hand:
//   gen_core_vectors --a 10 --b 6 --bits 4 --out-dir DIR
//   iverilog -g2012 -I rtl -o sim.vvp tb/icarus/dda_core_tb.v rtl/dda_*.v
//   vvp -n sim.vvp +vectors=DIR [+ce_random=SEED] [+max_cycles=N]
// (scripts/icarus-bench.sh does all three.)
//
// Files in DIR, read with $readmemh:
//   cmd.hex     the command word, DDA_CMD_WIDTH bits.
//   count.hex   the number of iterations.
//   expect.hex  one line per iteration: every architectural register after it, as one
//               wide word. Layout (the same as gen_core_vectors.cpp): the 21 registers
//               of the design doc's register table (hw_params.hpp kRegisters) in table
//               order, the first leftmost (most significant), each zero-padded to whole
//               hex digits, '_' between fields. Left to right (hex digits):
//     u_int_x.jv_q(13) u_int_x.jr_q(13) u_int_x.inc_on_x_q(13) u_int_x.inc_on_y_q(13)
//     u_int_y.jv_q(13) u_int_y.jr_q(13) u_int_y.inc_on_x_q(13) u_int_y.inc_on_y_q(13)
//     u_cnt_x.cnt_q(5) u_cnt_y.cnt_q(5) cap_q(13) cdir_x_q(1) cdir_y_q(1) dir_x_q(1)
//     dir_y_q(1) step_x_q(1) step_y_q(1) u_ctrl.state_q(1) u_ctrl.done_q(1)
//     u_ctrl.err_q(1) u_ctrl.iter_q(1)
//               cdir_*_q are the command's directions; dir_*_q are 0 until the first
//               step of their axis, then the command's direction (they change only with
//               a step).
//
// Stimulus: reset, then the command with the valid/ready handshake on the first edge
// after reset (edge 0 of the design doc's timing table) and ce_i high throughout (or, with
// +ce_random=SEED, ce_i from an LFSR). After the transfer cmd_valid_i drops, so no second
// command loads (cmd_ready_o is also high before the last iteration's edge), and cmd_i
// takes the inverted command, which the core must ignore. Inputs change on the falling
// edge; registers are read through hierarchical references on the falling edge, i.e.
// after each rising edge; cmd_ready_o is taken just before each rising edge.
//
// Checks, on every edge after the load:
//   * iter_o high: all 21 registers equal the next expect.hex line; with ce_i always
//     high, iteration k happens on edge load + k (design doc latency).
//   * iter_o low (an edge with ce_i low): no architectural register changed, pulses 0.
//   * outputs equal their registers (step_*_o, dir_*_o, done_o, err_o, iter_o,
//     busy_o = state run); err_o never rises.
//   * on every edge after reset: cmd_ready_o before the edge = state idle before it, or
//     the edge finishes the command (done_q after it; rtl/dda_ctrl.v "finishing").
//   * done_o rises once, with the last expected iteration; no iteration after it.
//   * watchdog: $fatal if done_o has not risen after +max_cycles edges.
// The first failing check prints what it compared and calls $fatal (vvp exits 1); a
// register mismatch prints "MISMATCH iteration K cycle C: <register> expected .. got ..".
// On success one line "PASS: ..." and $finish.
`include "dda_params.vh"

module dda_core_tb;

`ifndef MAX_ITERS
  `define MAX_ITERS 16384
`endif

  localparam integer AccWidth = `DDA_ACC_WIDTH;
  localparam integer CntWidth = `DDA_CNT_WIDTH;
  localparam integer StWidth  = `DDA_STATE_WIDTH;
  localparam integer MaxIters = `MAX_ITERS;

  // expect.hex field widths (padded to whole hex digits) and offsets from the LSB.
  localparam integer PA = 4 * ((AccWidth + 3) / 4);
  localparam integer PC = 4 * ((CntWidth + 3) / 4);
  localparam integer PS = 4 * ((StWidth + 3) / 4);
  localparam integer P1 = 4;
  localparam integer OffIter  = 0;
  localparam integer OffErr   = OffIter + P1;
  localparam integer OffDone  = OffErr + P1;
  localparam integer OffState = OffDone + P1;
  localparam integer OffStepY = OffState + PS;
  localparam integer OffStepX = OffStepY + P1;
  localparam integer OffDirY  = OffStepX + P1;
  localparam integer OffDirX  = OffDirY + P1;
  localparam integer OffCdirY = OffDirX + P1;
  localparam integer OffCdirX = OffCdirY + P1;
  localparam integer OffCap   = OffCdirX + P1;
  localparam integer OffCntY  = OffCap + PA;
  localparam integer OffCntX  = OffCntY + PC;
  localparam integer OffYIncY = OffCntX + PC;
  localparam integer OffYIncX = OffYIncY + PA;
  localparam integer OffYJr   = OffYIncX + PA;
  localparam integer OffYJv   = OffYJr + PA;
  localparam integer OffXIncY = OffYJv + PA;
  localparam integer OffXIncX = OffXIncY + PA;
  localparam integer OffXJr   = OffXIncX + PA;
  localparam integer OffXJv   = OffXJr + PA;
  localparam integer ExpWidth = OffXJv + PA;
  // Fields from OffDirY up (dir, cdir, cap, cnt, corrections, jr, jv) are state that an edge
  // with ce_i low must not change; below them are the pulses and state_q (checked apart).
  localparam integer PulseHi = OffStepX + P1;

  reg                      clk_i;
  reg                      rst_ni;
  reg                      ce_i;
  reg                      cmd_valid_i;
  reg [`DDA_CMD_WIDTH-1:0] cmd_i;
  wire                     cmd_ready_o;
  wire                     step_x_o, step_y_o, dir_x_o, dir_y_o;
  wire                     busy_o, done_o, err_o, iter_o;

  dda_core dut (
    .clk_i       (clk_i),
    .rst_ni      (rst_ni),
    .ce_i        (ce_i),
    .cmd_valid_i (cmd_valid_i),
    .cmd_ready_o (cmd_ready_o),
    .cmd_i       (cmd_i),
    .step_x_o    (step_x_o),
    .step_y_o    (step_y_o),
    .dir_x_o     (dir_x_o),
    .dir_y_o     (dir_y_o),
    .busy_o      (busy_o),
    .done_o      (done_o),
    .err_o       (err_o),
    .iter_o      (iter_o)
  );

  // Vectors.
  reg [`DDA_CMD_WIDTH-1:0] cmd_mem   [0:0];
  reg [31:0]               count_mem [0:0];
  reg [ExpWidth-1:0]       exp_mem   [0:MaxIters-1];
  reg [8*1024-1:0]         vec_dir, path;
  integer                  n_expected;

  // Options.
  integer ce_random;   // 0: ce_i always high; else LFSR seed
  integer max_cycles;
  reg [15:0] lfsr;

  // Monitor state.
  reg [ExpWidth-1:0] got, prev_got;
  integer last_edge;       // rising edges since reset release, the first one is edge 0
  integer load_edge;       // edge that transferred the command (-1: not yet)
  integer n_iter;          // iterations seen
  integer n_done;          // done_o pulses seen
  integer done_edge;
  reg     ce_at_edge, ready_at_edge, valid_at_edge, rst_at_edge;
  reg [StWidth-1:0] state_at_edge;
  integer n_bad;

  initial clk_i = 1'b0;
  always #5 clk_i = ~clk_i;

  // Inputs as they were just before each rising edge (NBA: pre-edge values).
  always @(posedge clk_i) begin
    ce_at_edge    <= ce_i;
    ready_at_edge <= cmd_ready_o;
    valid_at_edge <= cmd_valid_i;
    rst_at_edge   <= rst_ni;
    state_at_edge <= dut.u_ctrl.state_q;
    if (rst_ni) last_edge <= last_edge + 1;
  end

  // The registers in expect.hex layout.
  task sample_regs;
    begin
      got = {ExpWidth{1'b0}};
      got[OffXJv   +: AccWidth] = dut.u_int_x.jv_q;
      got[OffXJr   +: AccWidth] = dut.u_int_x.jr_q;
      got[OffXIncX +: AccWidth] = dut.u_int_x.inc_on_x_q;
      got[OffXIncY +: AccWidth] = dut.u_int_x.inc_on_y_q;
      got[OffYJv   +: AccWidth] = dut.u_int_y.jv_q;
      got[OffYJr   +: AccWidth] = dut.u_int_y.jr_q;
      got[OffYIncX +: AccWidth] = dut.u_int_y.inc_on_x_q;
      got[OffYIncY +: AccWidth] = dut.u_int_y.inc_on_y_q;
      got[OffCntX  +: CntWidth] = dut.u_cnt_x.cnt_q;
      got[OffCntY  +: CntWidth] = dut.u_cnt_y.cnt_q;
      got[OffCap   +: AccWidth] = dut.cap_q;
      got[OffCdirX]             = dut.cdir_x_q;
      got[OffCdirY]             = dut.cdir_y_q;
      got[OffDirX]              = dut.dir_x_q;
      got[OffDirY]              = dut.dir_y_q;
      got[OffStepX]             = dut.step_x_q;
      got[OffStepY]             = dut.step_y_q;
      got[OffState +: StWidth]  = dut.u_ctrl.state_q;
      got[OffDone]              = dut.u_ctrl.done_q;
      got[OffErr]               = dut.u_ctrl.err_q;
      got[OffIter]              = dut.u_ctrl.iter_q;
    end
  endtask

  // Compare one padded field of exp against got; print it if it differs.
  task check_field(input [8*24-1:0] name, input integer off, input integer width,
                   input [ExpWidth-1:0] exp, input integer iter);
    reg [63:0] e, g, mask;
    begin
      mask = (64'd1 << width) - 64'd1;
      e = (exp >> off) & mask;
      g = (got >> off) & mask;
      if (e !== g) begin
        $display("MISMATCH iteration %0d cycle %0d: %0s expected 0x%0h (%0d) got 0x%0h (%0d)",
                 iter, last_edge, name, e, e, g, g);
        n_bad = n_bad + 1;
      end
    end
  endtask

  task check_all(input [ExpWidth-1:0] exp, input integer iter);
    begin
      n_bad = 0;
      check_field("u_int_x.jv_q",       OffXJv,   PA, exp, iter);
      check_field("u_int_x.jr_q",       OffXJr,   PA, exp, iter);
      check_field("u_int_x.inc_on_x_q", OffXIncX, PA, exp, iter);
      check_field("u_int_x.inc_on_y_q", OffXIncY, PA, exp, iter);
      check_field("u_int_y.jv_q",       OffYJv,   PA, exp, iter);
      check_field("u_int_y.jr_q",       OffYJr,   PA, exp, iter);
      check_field("u_int_y.inc_on_x_q", OffYIncX, PA, exp, iter);
      check_field("u_int_y.inc_on_y_q", OffYIncY, PA, exp, iter);
      check_field("u_cnt_x.cnt_q",      OffCntX,  PC, exp, iter);
      check_field("u_cnt_y.cnt_q",      OffCntY,  PC, exp, iter);
      check_field("cap_q",              OffCap,   PA, exp, iter);
      check_field("cdir_x_q",           OffCdirX, P1, exp, iter);
      check_field("cdir_y_q",           OffCdirY, P1, exp, iter);
      check_field("dir_x_q",            OffDirX,  P1, exp, iter);
      check_field("dir_y_q",            OffDirY,  P1, exp, iter);
      check_field("step_x_q",           OffStepX, P1, exp, iter);
      check_field("step_y_q",           OffStepY, P1, exp, iter);
      check_field("u_ctrl.state_q",     OffState, PS, exp, iter);
      check_field("u_ctrl.done_q",      OffDone,  P1, exp, iter);
      check_field("u_ctrl.err_q",       OffErr,   P1, exp, iter);
      check_field("u_ctrl.iter_q",      OffIter,  P1, exp, iter);
    end
  endtask

  // Outputs must be their registers. cmd_ready_o also depends on ce_i, which the
  // stimulus may change on this falling edge: it is checked with its value just before
  // the rising edge (ready_at_edge): high iff the state was idle or the edge finished
  // the command (done_q = finishing of that edge, and done_q is checked on its own).
  task check_ports;
    begin
      if (step_x_o !== dut.step_x_q || step_y_o !== dut.step_y_q ||
          dir_x_o !== dut.dir_x_q || dir_y_o !== dut.dir_y_q ||
          done_o !== dut.u_ctrl.done_q || err_o !== dut.u_ctrl.err_q ||
          iter_o !== dut.u_ctrl.iter_q ||
          busy_o !== (dut.u_ctrl.state_q == `DDA_STATE_RUN)) begin
        $display("PORTS cycle %0d: step %b%b dir %b%b done %b err %b iter %b busy %b state %0d",
                 last_edge, step_x_o, step_y_o, dir_x_o, dir_y_o, done_o, err_o, iter_o,
                 busy_o, dut.u_ctrl.state_q);
        $fatal(1, "dda_core_tb: FAIL: an output differs from its register at cycle %0d", last_edge);
      end
      if (ready_at_edge !== ((state_at_edge == `DDA_STATE_IDLE) || dut.u_ctrl.done_q)) begin
        $display("READY cycle %0d: cmd_ready_o %b before the edge, state %0d before, done_q %b after",
                 last_edge, ready_at_edge, state_at_edge, dut.u_ctrl.done_q);
        $fatal(1, "dda_core_tb: FAIL: cmd_ready_o is not idle | finishing before cycle %0d", last_edge);
      end
    end
  endtask

  // Monitor: after every rising edge once reset is released.
  always @(negedge clk_i) begin
    if (rst_at_edge === 1'b1) begin
      prev_got = got;
      sample_regs;
      check_ports;
      if (err_o) $fatal(1, "dda_core_tb: FAIL: err_o (stall) at cycle %0d", last_edge);
      if (load_edge < 0 && valid_at_edge && ready_at_edge) begin
        load_edge = last_edge;  // the command was transferred on this edge
        if (!busy_o) $fatal(1, "dda_core_tb: FAIL: busy_o low after the command load (cycle %0d)", last_edge);
      end else if (load_edge >= 0) begin
        if (iter_o) begin
          n_iter = n_iter + 1;
          if (n_iter > n_expected) begin
            $fatal(1, "dda_core_tb: FAIL: iteration %0d at cycle %0d, only %0d expected",
                   n_iter, last_edge, n_expected);
          end
          if (ce_random == 0 && last_edge != load_edge + n_iter) begin
            $fatal(1, "dda_core_tb: FAIL: iteration %0d at cycle %0d, expected at cycle %0d (ce_i high)",
                   n_iter, last_edge, load_edge + n_iter);
          end
          check_all(exp_mem[n_iter-1], n_iter);
          if (n_bad != 0) begin
            $display("  expected %h", exp_mem[n_iter-1]);
            $display("  got      %h", got);
            $fatal(1, "dda_core_tb: FAIL: %0d register(s) differ after iteration %0d (cycle %0d)",
                   n_bad, n_iter, last_edge);
          end
        end else if (n_done == 0) begin
          // No iteration on this edge while running: ce_i must have been low, and then
          // nothing but the pulses may change (the pulses must be 0).
          if (ce_at_edge) begin
            $fatal(1, "dda_core_tb: FAIL: no iteration at cycle %0d although ce_i was high (%0d done)",
                   last_edge, n_iter);
          end
          if (got[ExpWidth-1:PulseHi] !== prev_got[ExpWidth-1:PulseHi] ||
              got[OffState +: StWidth] !== prev_got[OffState +: StWidth] ||
              got[OffStepX] || got[OffStepY] || got[OffDone] || got[OffErr]) begin
            $display("  before %h", prev_got);
            $display("  after  %h", got);
            $fatal(1, "dda_core_tb: FAIL: state changed on cycle %0d with ce_i low", last_edge);
          end
        end
        if (done_o) begin
          n_done = n_done + 1;
          done_edge = last_edge;
          if (n_done > 1) $fatal(1, "dda_core_tb: FAIL: second done_o pulse at cycle %0d", last_edge);
          if (!iter_o || n_iter != n_expected) begin
            $fatal(1, "dda_core_tb: FAIL: done_o at cycle %0d after %0d iterations (iter_o %b), expected with iteration %0d",
                   last_edge, n_iter, iter_o, n_expected);
          end
        end
      end
      if (n_done == 0 && last_edge >= max_cycles) begin
        $fatal(1, "dda_core_tb: FAIL: watchdog: no done_o within %0d cycles (%0d of %0d iterations)",
               max_cycles, n_iter, n_expected);
      end
    end
  end

  // Stimulus.
  initial begin
    rst_ni      = 1'b0;
    ce_i        = 1'b0;
    cmd_valid_i = 1'b0;
    cmd_i       = {`DDA_CMD_WIDTH{1'b0}};
    last_edge   = -1;
    load_edge   = -1;
    n_iter      = 0;
    n_done      = 0;
    done_edge   = -1;
    rst_at_edge = 1'b0;
    got         = {ExpWidth{1'b0}};

    if (!$value$plusargs("vectors=%s", vec_dir)) begin
      $fatal(1, "dda_core_tb: FAIL: no +vectors=DIR (directory written by gen_core_vectors)");
    end
    if (!$value$plusargs("ce_random=%d", ce_random)) ce_random = 0;
    lfsr = ce_random[15:0] ^ 16'hace1;
    if (lfsr == 16'd0) lfsr = 16'd1;

    count_mem[0] = 32'hxxxxxxxx;
    $sformat(path, "%0s/count.hex", vec_dir);
    $readmemh(path, count_mem);
    if (^count_mem[0] === 1'bx) $fatal(1, "dda_core_tb: FAIL: cannot read %0s", path);
    n_expected = count_mem[0];
    if (n_expected < 1 || n_expected > MaxIters) begin
      $fatal(1, "dda_core_tb: FAIL: %0d iterations expected, the bench holds 1 to %0d (-DMAX_ITERS=N)",
             n_expected, MaxIters);
    end
    cmd_mem[0] = {`DDA_CMD_WIDTH{1'bx}};
    $sformat(path, "%0s/cmd.hex", vec_dir);
    $readmemh(path, cmd_mem);
    if (^cmd_mem[0] === 1'bx) $fatal(1, "dda_core_tb: FAIL: cannot read %0s", path);
    exp_mem[n_expected-1] = {ExpWidth{1'bx}};
    $sformat(path, "%0s/expect.hex", vec_dir);
    $readmemh(path, exp_mem, 0, n_expected - 1);
    if (^exp_mem[n_expected-1] === 1'bx) $fatal(1, "dda_core_tb: FAIL: cannot read %0d lines of %0s", n_expected, path);
    if (!$value$plusargs("max_cycles=%d", max_cycles)) max_cycles = 8 * n_expected + 100;

    // Reset for three edges, then the command (and ce_i) before edge 0.
    repeat (3) @(posedge clk_i);
    @(negedge clk_i);
    rst_ni      = 1'b1;
    cmd_valid_i = 1'b1;
    cmd_i       = cmd_mem[0];
    ce_i        = 1'b1;

    forever begin
      @(negedge clk_i);
      // The transfer happened on the last edge: drop cmd_valid_i (from the values before
      // that edge, so not racing the monitor, which runs on this falling edge too), and
      // invert cmd_i, so a register that reads cmd_i after the load shows a mismatch.
      if (cmd_valid_i && valid_at_edge && ready_at_edge && rst_at_edge) begin
        cmd_valid_i = 1'b0;
        cmd_i       = ~cmd_mem[0];
      end
      if (ce_random != 0) begin
        lfsr = {lfsr[14:0], lfsr[15] ^ lfsr[13] ^ lfsr[12] ^ lfsr[10]};
        ce_i = lfsr[0];
      end
      if (n_done != 0 && last_edge >= done_edge + 3) begin
        // Three quiet edges after done: idle, ready, no further iteration (monitor).
        if (busy_o || !cmd_ready_o) $fatal(1, "dda_core_tb: FAIL: not idle after done_o");
        $display("PASS: dda_core_tb: %0d iterations (%0d expected), done_o with the last one at cycle %0d, command loaded at cycle %0d, ce_i %0s",
                 n_iter, n_expected, done_edge, load_edge, ce_random != 0 ? "random" : "always high");
        $finish;
      end
    end
  end

endmodule
