// SPDX-License-Identifier: Apache-2.0
// The pacer (docs/design.md, "Pacer"; reference: motion::Pacer in
// model/motion/pacer.hpp, the one definition of its behaviour, which this module
// mirrors register for register): decides on every clock whether the core iterates, so
// that the path speed follows a commanded speed v ramping at the acceleration a, with
// the norm unit (rtl/dda_norm.v) giving the DDA's path length per iteration d.
//
// Every clock a piece runs and the block lets the core go on (advance_i), the phase
// adds v; the core iterates when the phase reaches the pacer's d (d_q; in the phase's
// units D = d << (RF - NF)), taking D off. The phase is signed and saturates below 2^PW.
// Between two steps the norm operands hold, so a run of iterations has one d. A step
// comes in on the edge after its iteration (stepped_i with pend_q): the norm unit starts
// on the new run's registers, and the pacer goes on with the d it has, provisionally,
// counting those iterations (m_q, fresh_q low). When the unit has the run's own d, the
// pacer takes it (load) and corrects the phase and the distance to go by m_q times the
// difference, as if the run had been paced with it from the start: a bit of m_q per
// clock after the load (cm_q, cd_q), each clock taking its part (corr) off beside the D
// of an iteration on it, up to MCW clocks. A step that comes while the unit is at work
// is due (due_q): its start waits for the unit. The core waits on the clock a step
// comes in, while the unit reads its operands (OperandEdges edges after its start), on
// the load's clock, while a step is due, and after a take until the first run's d is in
// (first_q). v ramps by at most a per clock towards its
// target: the entry's cruise speed times the override, clamped to its limit; the exit
// speed (0 with no next piece) once the braking distance s, less the exit speed's,
// reaches the distance still
// to go less 2^-MarginShift step; never below vmin; 0 on a hold. The product of the
// cruise speed and the override is formed a bit per clock, OW clocks after a take or an
// override change (a take clamps the product in force to the new limit at once). s adds
// v on a ramp step up from above vmin and takes the new v off on one down to above vmin.
`include "dda_params.vh"

// Instantiated by the motion block (rtl/dda_motion.v, u_pace).
module dda_pace #(
  parameter integer AW = `DDA_ACC_WIDTH,  // the integrands' and capacities' width
  parameter integer NF = 20,    // kNormFrac: fraction bits of d
  parameter integer SF = 32,    // kSpeedFrac: entry speeds
  parameter integer RF = 48,    // kRampFrac: v, the phase, a
  parameter integer DF = 32,    // kDistFrac: s and the distance to go
  parameter integer LF = 8,     // kLenFrac: entry lengths
  parameter integer PW = 56,    // kPhaseBits
  parameter integer OW = 10,    // the override: 0 .. 2 x (1 << OF)
  parameter integer OF = 8,     // kOverrideOne = 1 << OF
  parameter integer MarginShift = 3
) (
  input  wire          clk_i,
  input  wire          rst_ni,         // synchronous, active low
  input  wire          advance_i,      // the block lets the core go on this clock
  input  wire          running_i,      // the core runs a piece
  input  wire          take_i,         // the core loads an entry on this edge ...
  input  wire [31:0]   cruise_i,       // ... with these pacing fields
  input  wire [31:0]   limit_i,
  input  wire [31:0]   exit_i,
  input  wire [31:0]   length_i,
  input  wire [31:0]   brake_exit_i,
  input  wire          next_queued_i,  // another entry waits in the queue
  input  wire [31:0]   accel_i,        // x 2^RF steps/clock^2; 0: the speed jumps
  input  wire [31:0]   vmin_i,         // x 2^SF steps/clock
  input  wire [OW-1:0] override_i,
  input  wire          hold_i,
  input  wire          stepped_i,      // the core's last iteration made a step
  input  wire [AW-1:0] v_x_i,          // the norm unit's operands (0: inactive axis)
  input  wire [AW-1:0] v_y_i,
  input  wire [AW-1:0] v_z_i,
  input  wire [AW-1:0] cap_i,
  input  wire [AW-1:0] cap_z_i,
  output wire          iterate_o,      // the core iterates on this edge
  output wire [RF-1:0] speed_o         // v
);

  localparam integer Latency = 5 * ((NF + 2) / 2) + 1;  // kNormLatency: the norm unit's (rtl/dda_norm.v)
  localparam integer OperandEdges = 2 * ((NF + 2) / 2) + 1;  // kNormOperandEdges: it reads z's then
  localparam integer BW = $clog2(Latency + 1);  // busy_q counts Latency .. 0
  localparam integer MCW = $clog2(Latency - OperandEdges + 2);  // m_q: up to Latency - OperandEdges + 1
  localparam integer CW = NF + MCW + 2;  // cd_q: a difference of two d's times up to 2^(MCW-1), signed
  localparam integer SW = DF + 26;  // s, the distance to go and their sums (below 2^(DF + 25))
  localparam integer MW = 32 + OW;  // the cruise speed times the override (below 2^MW)

  reg  [RF-1:0] v_q      /* verilator public_flat_rd */;
  reg  [PW:0]   ph_q     /* verilator public_flat_rd */;  // signed: below 0 after a correction
  reg  [SW-1:0] s_q      /* verilator public_flat_rd */;
  reg  [SW-1:0] rem_q    /* verilator public_flat_rd */;
  reg  [31:0]   cruise_q /* verilator public_flat_rd */;
  reg  [31:0]   limit_q  /* verilator public_flat_rd */;
  reg  [31:0]   exit_q   /* verilator public_flat_rd */;
  reg  [31:0]   brake_q  /* verilator public_flat_rd */;  // the entry's brake_exit
  reg  [BW-1:0] busy_q   /* verilator public_flat_rd */;  // clocks until the norm unit's d is new
  reg           pend_q   /* verilator public_flat_rd */;  // an iteration on the last edge
  reg           first_q  /* verilator public_flat_rd */;  // a take: the first run's d is not in yet
  reg           due_q    /* verilator public_flat_rd */;  // a step came while the unit was at work
  reg           fresh_q  /* verilator public_flat_rd */;  // d_q is the run's own
  reg  [MCW-1:0] m_q     /* verilator public_flat_rd */;  // the run's provisional iterations
  reg  [NF+1:0] d_q      /* verilator public_flat_rd */;  // the d the pacer paces with
  reg  [MCW-1:0] cm_q    /* verilator public_flat_rd */;  // the correction's multiplier bits still to apply
  reg  [CW-1:0] cd_q     /* verilator public_flat_rd */;  // the difference of the d's times 2^(bits applied), signed
  wire [NF+1:0] d;          // the norm unit's last
  wire          norm_busy;  // (the pacer counts the norm unit's clocks itself: busy_q)

  // A step on the last edge, or one due, starts the unit on the new run once it is free;
  // a take starts it on the new piece's first run. The unit free with the run's own d:
  // the pacer takes it (load) with the correction.
  wire seen  = pend_q & stepped_i;
  wire free  = busy_q == '0;
  wire load  = free & ~fresh_q;
  wire start = take_i | (free & (seen | due_q));
  wire signed [NF+2:0]  delta = $signed({1'b0, d}) - $signed({1'b0, d_q});
  // The correction, m_q x delta (x 2^-NF steps), a bit of m_q per clock after the load
  // (cm_q, shifting down; cd_q the difference, shifting up): corr is this clock's part.
  wire          correcting = cm_q != '0;
  wire signed [CW-1:0] corr = cm_q[0] ? $signed(cd_q) : '0;

  dda_norm #(.AW(AW), .NF(NF)) u_norm (
    .clk_i(clk_i), .rst_ni(rst_ni), .start_i(start),
    .v_x_i(v_x_i), .v_y_i(v_y_i), .v_z_i(v_z_i), .cap_i(cap_i), .cap_z_i(cap_z_i),
    .busy_o(norm_busy), .d_o(d)
  );

  // x > (y << (RF - SF)) for a speed x at RF fraction bits and an entry speed y at SF.
  function automatic above(input [RF-1:0] x, input [31:0] y);
    above = {x[RF-1:RF-SF], |x[RF-SF-1:0]} > {y, 1'b0};
  endfunction

  // Distances at DF fraction bits.
  wire [PW-1:0] dd     = PW'(d_q) << (RF - NF);                     // D, at the phase's scale
  wire [SW-1:0] v_dist = SW'(v_q[RF-1:RF-DF]);
  wire [SW-1:0] margin = SW'(1) << (DF - MarginShift);
  wire [SW-1:0] eb     = next_queued_i ? SW'(brake_q) << (DF - LF) : '0;
  // The phase as a distance (floor, also below 0) against the distance to go: slow down
  // once s + the phase + the margin is not below the distance to go + the exit's braking
  // (one sum: not below 0).
  wire signed [SW+1:0] ph_dist = (SW+2)'($signed(ph_q[PW:RF-DF]));
  wire signed [SW+2:0] decel_x = $signed({3'b0, s_q}) + ph_dist + $signed({3'b0, margin})
                                 - $signed({3'b0, rem_q}) - $signed({3'b0, eb});
  wire                 decel   = ~decel_x[SW+2];

  // The cruise speed times the override, clamped to the limit (eff_q), by shift and add,
  // the override's top bit first: each clock doubles the product so far (macc_q, the
  // entry's cruise speed times the override's bits so far) and adds the cruise speed for
  // the next bit (mplier_q, shifting up), for OW clocks after a take or an override
  // change (ovr_q: the override of the product), which start it again. At the ramp's
  // scale the product is macc_q << (RF - SF - OF); it is below the limit's
  // (limit << (RF - SF)) when macc_q is below limit << OF.
  reg  [OW-1:0]  ovr_q    /* verilator public_flat_rd */;
  reg  [OW-1:0]  mplier_q /* verilator public_flat_rd */;
  reg  [MW-1:0]  macc_q   /* verilator public_flat_rd */;
  reg  [3:0]     mcnt_q   /* verilator public_flat_rd */;  // clocks until the product is ready
  reg  [RF-1:0]  eff_q    /* verilator public_flat_rd */;
  wire           mstart = take_i | (override_i != ovr_q);
  wire [MW-1:0]  msum   = {macc_q[MW-2:0], 1'b0} + (mplier_q[OW-1] ? MW'(cruise_q) : '0);
  wire [RF-1:0]  lim    = RF'(limit_q) << (RF - SF);
  wire [RF-1:0]  eff_d  = msum[MW-1:OF] < (MW-OF)'(limit_q) ? RF'(msum) << (RF - SF - OF) : lim;
  // A take clamps the product in force to the new entry's limit at once (the new
  // product is OW clocks away).
  wire [RF-1:0]  eff_m  = mcnt_q == 4'd1 ? eff_d : eff_q;
  wire [RF-1:0]  lim_in = RF'(limit_i) << (RF - SF);
  wire [RF-1:0]  eff_n  = take_i && above(eff_m, limit_i) ? lim_in : eff_m;

  // The target: the cruise speed; the exit speed on the way down; 0 on a hold.
  wire [RF-1:0] t_ex  = next_queued_i ? RF'(exit_q) << (RF - SF) : '0;
  wire [RF-1:0] t_dn  = decel && accel_i != 32'd0 && (!next_queued_i || above(eff_q, exit_q)) ? t_ex : eff_q;  // (no ramp: no slowing down)
  wire [RF-1:0] t_min = RF'(vmin_i) << (RF - SF);
  wire [RF-1:0] target = hold_i ? '0 : above(t_dn, vmin_i) ? t_dn : t_min;
  wire unused_t = &{1'b0, macc_q[MW-1], norm_busy};

  wire blocked = first_q | due_q | seen | load | (busy_q > BW'(Latency - OperandEdges + 1));
  // The phase plus v while the core may go on; less D: the core iterates when that is not below 0.
  wire signed [PW+1:0] ph_add  = $signed({ph_q[PW], ph_q}) + (advance_i ? $signed((PW+2)'(v_q)) : '0);
  wire signed [PW+1:0] ph_left = ph_add - $signed((PW+2)'(dd));
  assign iterate_o = advance_i & running_i & ~blocked & ~ph_left[PW+1];
  assign speed_o   = v_q;

  // The ramp.
  wire [RF-1:0] a     = RF'(accel_i);
  // From the target less v (gap): up while it is above 0, down while below; a step of a
  // (va) while the gap is wider than a, else the target.
  wire signed [RF+1:0] gap  = $signed({2'b0, target}) - $signed({2'b0, v_q});
  wire                 up   = ~gap[RF+1] & (gap != '0);
  wire                 down = gap[RF+1];
  wire signed [RF+1:0] gpa  = gap + $signed({2'b0, a});
  wire                 far  = up ? gap > $signed({2'b0, a}) : gpa[RF+1];
  wire [RF-1:0]        va   = up ? v_q + a : v_q - a;
  wire [RF-1:0]        v_n  = far ? va : target;  // v after the edge, on a ramp step
  wire [SW-1:0]        vn_dist = SW'(v_n[RF-1:RF-DF]);
  // s plus v's distance on a step up, less the new v's on a step down (at least 0: below
  // it the sum is negative)
  wire signed [SW:0] s_sum = $signed({1'b0, s_q}) + (up ? $signed({1'b0, v_dist}) : -$signed({1'b0, vn_dist}));
  // What the edge takes off the phase and the distance to go (x 2^-NF steps): d on an
  // iteration, and the correction's part.
  wire signed [CW:0]   amt     = $signed({1'b0, iterate_o ? CW'(d_q) : '0}) + corr;
  // The phase: v while the core may go on, less that.
  wire signed [PW+1:0] ph_next = ph_add - ($signed((PW+2)'(amt)) <<< (RF - NF));
  wire                 ph_sat  = ~ph_next[PW+1] & ph_next[PW];  // 2^PW or above
  // The distance to go less that; at least 0.
  wire signed [SW+1:0] rem_sub = $signed((SW+2)'(amt)) <<< (DF - NF);
  wire signed [SW+1:0] rem_c   = $signed({2'b0, rem_q}) - rem_sub;

  always @(posedge clk_i) begin
    if (!rst_ni) begin
      v_q      <= '0;
      ph_q     <= '0;
      s_q      <= '0;
      rem_q    <= '0;
      cruise_q <= '0;
      limit_q  <= '0;
      exit_q   <= '0;
      brake_q  <= '0;
      busy_q   <= '0;
      pend_q   <= 1'b0;
      first_q  <= 1'b0;
      due_q    <= 1'b0;
      fresh_q  <= 1'b0;
      m_q      <= '0;
      d_q      <= '0;
      cm_q     <= '0;
      cd_q     <= '0;
      ovr_q    <= '0;
      mplier_q <= '0;
      macc_q   <= '0;
      mcnt_q   <= 4'd0;
      eff_q    <= '0;
    end else begin
      if (mcnt_q != 4'd0) begin
        macc_q   <= msum;
        mplier_q <= mplier_q << 1;
        mcnt_q   <= mcnt_q - 4'd1;
      end
      eff_q <= eff_n;
      if (mstart) begin
        ovr_q    <= override_i;
        mplier_q <= override_i;
        macc_q   <= '0;
        mcnt_q   <= 4'(OW);
      end
      // The norm unit: its d is new Latency clocks after its start.
      if (start) busy_q <= BW'(Latency);
      else if (!free) busy_q <= busy_q - 1'b1;
      if (iterate_o && !fresh_q) m_q <= m_q + 1'b1;
      if (correcting) begin
        cm_q <= cm_q >> 1;
        cd_q <= cd_q << 1;
      end
      if (load) begin
        cm_q    <= m_q;
        cd_q    <= CW'(delta);
        d_q     <= d;
        fresh_q <= 1'b1;
        first_q <= 1'b0;
      end
      if (start) begin
        fresh_q <= 1'b0;
        due_q   <= 1'b0;
        m_q     <= '0;
      end else if (seen) begin
        due_q   <= 1'b1;
      end
      pend_q <= iterate_o;
      if (iterate_o || correcting) rem_q <= rem_c[SW+1] ? '0 : rem_c[SW-1:0];
      if (!running_i) ph_q <= '0;
      else if (advance_i || correcting) ph_q <= ph_sat ? {1'b0, {PW{1'b1}}} : ph_next[PW:0];
      if (advance_i && running_i) begin
        if (accel_i == 32'd0) begin
          v_q <= target;
          s_q <= '0;
        end else if (up) begin
          v_q <= v_n;
          if (above(v_q, vmin_i)) s_q <= s_sum[SW-1:0];
        end else if (down) begin
          v_q <= v_n;
          if (above(v_n, vmin_i)) s_q <= s_sum[SW] ? '0 : s_sum[SW-1:0];
          if (v_n == '0) s_q <= '0;
        end else if (v_q == '0) begin
          s_q <= '0;
        end
      end
      if (!running_i && !take_i) begin
        v_q <= '0;
        s_q <= '0;
      end
      if (take_i) begin
        cruise_q <= cruise_i;
        limit_q  <= limit_i;
        exit_q   <= exit_i;
        brake_q  <= brake_exit_i;
        rem_q    <= SW'(length_i) << (DF - LF);
        pend_q   <= 1'b0;
        first_q  <= 1'b1;
        due_q    <= 1'b0;
        fresh_q  <= 1'b0;
        m_q      <= '0;
        cm_q     <= '0;  // (a correction left of the piece before is dropped with it)
      end
    end
  end

endmodule
