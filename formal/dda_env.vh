// SPDX-License-Identifier: Apache-2.0
// The environment of the formal proofs (scripts/formal.sh), included by the wrappers
// dda_props.sv and the generated equivalence miter. It states what the driver (the
// planner and the command packer, docs/design.md "Command preconditions") guarantees,
// nothing else:
//   * reset in the first cycle;
//   * a loaded command is well formed: 0 < cap < 2^(AccWidth-1), jr_x, jr_y < cap, and
//     a moving third axis (cnt_z != 0) has 0 < cap_z < 2^(AccWidth-1), jr_z < cap_z,
//     jv_z <= cap_z (the packer checks it; dda_core's assertions "a loaded command is
//     malformed" check it in every simulation);
//   * the state assumption: an active axis' integrand stays in [-cap, cap], and an
//     iteration that leaves the axis active does not wrap it around 2^AccWidth: the
//     integrand after it is exactly the one before plus the corrections of its steps
//     (plan_arc and the packer check every piece's integrands against its capacity
//     before it is issued, docs/design.md "Integrator"; a wrap would also differ from
//     the golden model's exact integrands, which the scoreboards compare). The
//     accumulator's bound jr < cap and the fast implementation's e = jr + jv - cap
//     need it.
// No assumption keeps a command from stalling: the stall cover reaches err_o.
// The including module declares: clk_i, rst_ni, cmd_valid_i, cmd_i, cmd_ready (the
// core's cmd_ready_o), s_step_x, s_step_y, s_iter (its step_*_o and iter_o), and the
// state it constrains: s_jv_x, s_jv_y, s_cap, s_cnt_x, s_cnt_y and the corrections
// s_inc_xx (inc_x_on_x), s_inc_xy, s_inc_yx, s_inc_yy.

  localparam integer EnvW = `DDA_ACC_WIDTH;
  localparam integer EnvC = `DDA_CNT_WIDTH;

  wire            env_load   = cmd_valid_i & cmd_ready;
  wire [EnvW-1:0] env_cap    = cmd_i[`DDA_CMD_CAP_LSB +: EnvW];
  wire [EnvW-1:0] env_jr_x   = cmd_i[`DDA_CMD_JR_X_LSB +: EnvW];
  wire [EnvW-1:0] env_jr_y   = cmd_i[`DDA_CMD_JR_Y_LSB +: EnvW];
  wire [EnvW-1:0] env_jv_z   = cmd_i[`DDA_CMD_JV_Z_LSB +: EnvW];
  wire [EnvW-1:0] env_jr_z   = cmd_i[`DDA_CMD_JR_Z_LSB +: EnvW];
  wire [EnvW-1:0] env_cap_z  = cmd_i[`DDA_CMD_CAP_Z_LSB +: EnvW];
  wire [EnvC-1:0] env_cnt_z  = cmd_i[`DDA_CMD_CNT_Z_LSB +: EnvC];

  function automatic in_range(input [EnvW-1:0] jv, input [EnvW-1:0] cap);
    // -cap <= jv <= cap, jv two's complement, 0 <= cap < 2^(EnvW-1)
    in_range = jv[EnvW-1] ? (-jv <= cap) : (jv <= cap);
  endfunction

  // The exact integrand after an iteration, from the one before and the step pulses of
  // the iteration (two bits wider than the register: no wrap).
  function automatic [EnvW+1:0] sx2(input [EnvW-1:0] v);
    sx2 = {{2{v[EnvW-1]}}, v};
  endfunction
  reg             env_past_ok = 1'b0;  // the last edge was an iteration without a load
  reg [EnvW-1:0]  env_jv_x_q, env_jv_y_q;
  always @(posedge clk_i) begin
    env_past_ok <= rst_ni && !env_load;
    env_jv_x_q  <= s_jv_x;
    env_jv_y_q  <= s_jv_y;
  end
  wire [EnvW+1:0] env_jv_x_exact = sx2(env_jv_x_q) + (s_step_x ? sx2(s_inc_xx) : {(EnvW+2){1'b0}}) +
                                   (s_step_y ? sx2(s_inc_xy) : {(EnvW+2){1'b0}});
  wire [EnvW+1:0] env_jv_y_exact = sx2(env_jv_y_q) + (s_step_x ? sx2(s_inc_yx) : {(EnvW+2){1'b0}}) +
                                   (s_step_y ? sx2(s_inc_yy) : {(EnvW+2){1'b0}});

  always @(*) begin
    if ($initstate) assume (!rst_ni);
    if (!$initstate && env_past_ok && s_iter) begin
      if (s_cnt_x != {EnvC{1'b0}}) assume (env_jv_x_exact == sx2(s_jv_x));
      if (s_cnt_y != {EnvC{1'b0}}) assume (env_jv_y_exact == sx2(s_jv_y));
    end
    if (env_load) begin
      assume (env_cap != {EnvW{1'b0}} && !env_cap[EnvW-1]);
      assume (env_jr_x < env_cap && env_jr_y < env_cap);
      if (env_cnt_z != {EnvC{1'b0}}) begin
        assume (env_cap_z != {EnvW{1'b0}} && !env_cap_z[EnvW-1]);
        assume (env_jr_z < env_cap_z && env_jv_z <= env_cap_z);
      end
    end
    if (s_cnt_x != {EnvC{1'b0}}) assume (in_range(s_jv_x, s_cap));
    if (s_cnt_y != {EnvC{1'b0}}) assume (in_range(s_jv_y, s_cap));
  end
