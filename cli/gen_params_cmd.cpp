// SPDX-License-Identifier: Apache-2.0
// dda gen-params (gen_params_cmd.hpp).
#include "cli/gen_params_cmd.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <ostream>

#include "cli/options/arc_options.hpp"
#include "cli/options/output.hpp"
#include "cli/vectors.hpp"
#include "model/datapath/hw_command.hpp"
#include "model/motion/motion_map.hpp"
#include "model/motion/motion_model.hpp"

namespace dda::cli {

namespace {

// What gen-params prints (--kind).
enum class GenKind {
  Verilog,
  Markdown,
  Json,
  VectorFields,
  GtkwSystemc,
  GtkwRtl,
  Registers,
  MotionMarkdown,
  MotionC,
  MotionVerilog,
  MotionVectorFields,
  AxilVectorFields,
  SpiVectorFields,
  GtkwMotion,
  StepdirDiagram,
};

// The text of one kind, at the accumulator and counter widths acc and cnt.
void write_gen_params(std::ostream& os, GenKind kind, int acc, int cnt) {
  switch (kind) {
    case GenKind::Verilog:
      os << hw::verilog_header(acc, cnt);
      break;
    case GenKind::Markdown:
      os << hw::markdown_tables();
      break;
    case GenKind::Json: {
      nlohmann::ordered_json j;
      j["acc_width"] = acc;
      j["cnt_width"] = cnt;
      j["cmd_width"] = hw::cmd_width(acc, cnt);
      j["max_semi_axis"] = hw::max_semi_axis(4, acc, cnt);  // default width: smallest valid + 4
      os << j.dump(1) << '\n';
      break;
    }
    case GenKind::VectorFields:
      os << vec::verilog_fields();
      break;
    case GenKind::GtkwSystemc:  // the waveforms' scopes: dda --engine systemc|rtl --vcd
      os << hw::gtkw(hw::signal_table(), "dda_systemc.gtkw", "SystemC");
      break;
    case GenKind::GtkwRtl:
      os << hw::gtkw(hw::signal_table(), "dda_rtl.gtkw", "dut.dda_core");
      break;
    case GenKind::Registers:  // the architectural registers: "name width" (scripts/formal.sh)
      for (const auto& r : hw::kSignals) {
        if (r.kind == hw::SigKind::Reg) os << r.name << ' ' << hw::field_width(r.width, acc, cnt) << '\n';
      }
      break;
    case GenKind::MotionMarkdown:  // the motion block's register map
      os << motion::markdown();
      break;
    case GenKind::MotionC:
      os << motion::c_header();
      break;
    case GenKind::MotionVerilog:
      os << motion::verilog_header();
      break;
    case GenKind::MotionVectorFields:  // the bus bench's field table
      os << vec::bus_verilog_fields();
      break;
    case GenKind::AxilVectorFields:  // ... with the block behind a bridge
      os << vec::bus_verilog_fields(motion::Bus::axil);
      break;
    case GenKind::SpiVectorFields:
      os << vec::bus_verilog_fields(motion::Bus::spi);
      break;
    case GenKind::GtkwMotion:  // the motion block's waveform: dda vectors --bus --vcd
      os << motion::gtkw("dda_motion.gtkw", "dut.dda_motion", motion::kMaxDepthLog2);
      break;
    case GenKind::StepdirDiagram:  // the step/dir stage's edge-by-edge diagram (docs/design.md)
      os << motion::stage_diagram();
      break;
  }
}

}  // namespace

void add_gen_params_options(CLI::App* sub, GenParamsCli& g) {
  sub->add_option("--kind", g.kind,
                  "verilog (rtl/dda_params.vh), markdown (docs/design.md tables), json (the widths and "
                  "the largest semi-axis they hold at the default width), vector-fields "
                  "(tb/hdl/dda_vec_fields.vh), gtkw-systemc or gtkw-rtl (docs/dda_*.gtkw), registers (the "
                  "architectural registers and their widths: scripts/formal.sh), motion-markdown, motion-c or "
                  "motion-verilog (the motion block's register map: docs/design.md, fw/dda_motion_regs.h, "
                  "rtl/dda_motion_regs.vh), motion-vector-fields, axil-vector-fields or spi-vector-fields "
                  "(tb/hdl/dda_bus_vec_fields.vh, "
                  "dda_axil_vec_fields.vh, dda_spi_vec_fields.vh), stepdir-diagram, gtkw-motion "
                  "(docs/dda_motion.gtkw); default verilog");
  sub->add_option("--out", g.out, "write to FILE (atomically; - or none: standard output)");
  sub->add_option("--acc-width", g.acc_width,
                  "--kind verilog, json or registers at another accumulator width (formal proofs, scripts/synth --acc; "
                  "default " +
                      std::to_string(hw::kAccWidth) + ")")
      ->check(CLI::Range(4, hw::kAccWidth));
  sub->add_option(
         "--cnt-width", g.cnt_width,
         "--kind verilog, json or registers at another counter width (default " + std::to_string(hw::kCntWidth) + ")")
      ->check(CLI::Range(2, hw::kCntWidth));
}

void run_gen_params(const GenParamsCli& g) {
  const GenKind kind = parse_enum<GenKind>("kind", g.kind,
                                           {{"verilog", GenKind::Verilog},
                                            {"markdown", GenKind::Markdown},
                                            {"json", GenKind::Json},
                                            {"vector-fields", GenKind::VectorFields},
                                            {"gtkw-systemc", GenKind::GtkwSystemc},
                                            {"gtkw-rtl", GenKind::GtkwRtl},
                                            {"registers", GenKind::Registers},
                                            {"motion-markdown", GenKind::MotionMarkdown},
                                            {"motion-c", GenKind::MotionC},
                                            {"motion-verilog", GenKind::MotionVerilog},
                                            {"motion-vector-fields", GenKind::MotionVectorFields},
                                            {"axil-vector-fields", GenKind::AxilVectorFields},
                                            {"spi-vector-fields", GenKind::SpiVectorFields},
                                            {"gtkw-motion", GenKind::GtkwMotion},
                                            {"stepdir-diagram", GenKind::StepdirDiagram}});
  const bool sized = kind == GenKind::Verilog || kind == GenKind::Json || kind == GenKind::Registers;
  if (!sized && (g.acc_width != hw::kAccWidth || g.cnt_width != hw::kCntWidth)) {
    throw InputError("--acc-width and --cnt-width go with --kind verilog, json or registers only");
  }
  Output out(g.out);
  write_gen_params(out.stream(), kind, g.acc_width, g.cnt_width);
  out.commit();
}

}  // namespace dda::cli
