// SPDX-License-Identifier: Apache-2.0
#include "tb/engines/motion_harness.hpp"

#include <verilated.h>
#include <verilated_syms.h>

#include "Vdda_motion.h"
#if DDA_HARNESS_BRIDGES
#include "Vdda_motion_axil.h"
#include "Vdda_motion_spi.h"
#endif
#include "model/datapath/errors.hpp"
#include "tb/engines/vl_coverage.hpp"
#include "tb/engines/vl_sampler.hpp"
#include "tb/engines/vl_waveform.hpp"

namespace dda::motion {

namespace {

std::uint64_t read_var(const void* p, int bytes) {
  switch (bytes) {
    case 1:
      return *static_cast<const std::uint8_t*>(p);
    case 2:
      return *static_cast<const std::uint16_t*>(p);
    case 4:
      return *static_cast<const std::uint32_t*>(p);
    default:
      return *static_cast<const std::uint64_t*>(p);
  }
}

int bytes_of(const VerilatedVar& v) {
  return v.vltype() == VLVT_UINT8 ? 1 : v.vltype() == VLVT_UINT16 ? 2 : v.vltype() == VLVT_UINT32 ? 4 : 8;
}

// A register of `width` bits by its name below `scope` ("u_sx.step_q", "u_io.u_estop.s1_q":
// a register of a submodule, in its scope). GuardError if the RTL lacks it or holds it
// at another width.
struct Var {
  const void* p;
  int bytes;
  int width;
  std::uint64_t read() const { return read_var(p, bytes) & ((width >= 64 ? 0 : std::uint64_t{1} << width) - 1); }
};
Var find_var(const VerilatedContext& ctx, const std::string& scope, std::string_view name, int width) {
  const std::size_t dot = name.rfind('.');
  const std::string sub = dot == std::string_view::npos ? scope : scope + "." + std::string(name.substr(0, dot));
  const VerilatedScope* rs = ctx.scopeFind(sub.c_str());
  if (!rs) throw GuardError("motion sampler: no scope " + sub);
  const std::string var(dot == std::string_view::npos ? name : name.substr(dot + 1));
  VerilatedVar* v = rs->varFind(var.c_str());
  if (!v) throw GuardError("motion sampler: the RTL has no public register " + std::string(name));
  const int got = v->dims() == 0 ? 1 : v->packed().elements();
  if (got != width) {
    throw GuardError("motion sampler: the RTL's " + std::string(name) + " is " + std::to_string(got) +
                     " bits wide, the model says " + std::to_string(width));
  }
  return Var{v->datap(), bytes_of(*v), width};
}

}  // namespace

struct VlBlockSampler::Vars {
  std::vector<Var> v;
};

VlBlockSampler::VlBlockSampler(const VerilatedContext& ctx, const std::string& scope, int depth_log2)
    : block_(std::make_unique<Vars>()) {
  for (const auto& r : kBlockRegs) block_->v.push_back(find_var(ctx, scope, r.name, width_bits(r.width, depth_log2)));
  // The core's register table, read below the block's instance by the core's sampler.
  core_ = std::make_unique<rtl::VlSampler>(ctx, scope + ".u_core", hw::signal_table());
}

VlBlockSampler::~VlBlockSampler() = default;

struct VlRegSampler::Vars {
  std::vector<Var> v;
};

VlRegSampler::VlRegSampler(const VerilatedContext& ctx, const std::string& scope, const std::vector<BridgeReg>& regs)
    : v_(std::make_unique<Vars>()) {
  for (const auto& r : regs) v_->v.push_back(find_var(ctx, scope, r.name, r.width));
}

VlRegSampler::~VlRegSampler() = default;

std::vector<std::uint64_t> VlRegSampler::read() const {
  std::vector<std::uint64_t> r;
  for (const auto& v : v_->v) r.push_back(v.read());
  return r;
}

std::string compare_bridge(Bus bus, const std::vector<std::uint64_t>& got, const Bridge& model) {
  const std::vector<std::uint64_t> want = model.regs();
  const std::vector<BridgeReg> names = bridge_regs(bus);
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (got.at(i) != want.at(i)) {
      return "u_bridge." + std::string(names[i].name) + " is " + std::to_string(got[i]) +
             ", the reference model says " + std::to_string(want[i]);
    }
  }
  return "";
}

BlockRegs VlBlockSampler::block() const {
  BlockRegs r{};
  for (std::size_t i = 0; i < block_->v.size(); ++i) r[i] = block_->v[i].read();
  return r;
}

Signals VlBlockSampler::core() const { return core_->read(); }

std::string compare_block(const BlockRegs& got, const Signals& got_core, const MotionModel& m) {
  for (std::size_t i = 0; i < kBlockRegs.size(); ++i) {
    if (got[i] != m.regs()[i]) {
      return std::string(kBlockRegs[i].name) + " is " + std::to_string(got[i]) + ", the reference model says " +
             std::to_string(m.regs()[i]);
    }
  }
  for (std::size_t i = 0; i < hw::kSignals.size(); ++i) {
    if (got_core[i] != m.core()[i]) {
      return "u_core." + std::string(hw::kSignals[i].name) + " is " + std::to_string(got_core[i]) +
             ", the reference model says " + std::to_string(m.core()[i]);
    }
  }
  return "";
}

// The verilated top of a bus: the block's ports, the bus' and, behind a bridge, the
// bridge's registers.
class MotionHarness::Top {
 public:
  virtual ~Top() = default;
  // One edge: every input set while the clock is low, then the rising edge; the outputs
  // after it (behind a bridge, the block's own bus outputs are left to the caller).
  virtual BlockOutputs edge(const BlockInputs& in, const BusIn& host) = 0;
  // The bridge's registers (kAxilRegs, kSpiRegs), none on Wishbone.
  virtual std::vector<std::uint64_t> bridge() const = 0;
  virtual std::string scope() const = 0;  // the block's instance
};

namespace {

void drive_bus(Vdda_motion& v, const BlockInputs& in, const BusIn&) {
  v.wb_cyc_i = in.bus.cyc;
  v.wb_stb_i = in.bus.stb;
  v.wb_we_i = in.bus.we;
  v.wb_adr_i = in.bus.adr;
  v.wb_dat_i = in.bus.dat;
  v.wb_sel_i = in.bus.sel;
}
void read_bus(const Vdda_motion& v, BlockOutputs& o) {
  o.ack = v.wb_ack_o;
  o.stall = v.wb_stall_o;
  o.dat = v.wb_dat_o;
}
#if DDA_HARNESS_BRIDGES
void drive_bus(Vdda_motion_axil& v, const BlockInputs&, const BusIn& host) {
  const AxilIn& a = host.axil;
  v.s_awvalid_i = a.awvalid;
  v.s_awaddr_i = a.awaddr & ((1u << kAddrWidth) - 1);
  v.s_wvalid_i = a.wvalid;
  v.s_wdata_i = a.wdata;
  v.s_wstrb_i = a.wstrb;
  v.s_bready_i = a.bready;
  v.s_arvalid_i = a.arvalid;
  v.s_araddr_i = a.araddr & ((1u << kAddrWidth) - 1);
  v.s_rready_i = a.rready;
}
void read_bus(const Vdda_motion_axil& v, BlockOutputs& o) {
  o.axil.awready = v.s_awready_o;
  o.axil.wready = v.s_wready_o;
  o.axil.bvalid = v.s_bvalid_o;
  o.axil.bresp = v.s_bresp_o;
  o.axil.arready = v.s_arready_o;
  o.axil.rvalid = v.s_rvalid_o;
  o.axil.rdata = v.s_rdata_o;
  o.axil.rresp = v.s_rresp_o;
}
void drive_bus(Vdda_motion_spi& v, const BlockInputs&, const BusIn& host) {
  v.spi_csn_i = host.spi.csn;
  v.spi_sck_i = host.spi.sck;
  v.spi_mosi_i = host.spi.mosi;
}
void read_bus(const Vdda_motion_spi& v, BlockOutputs& o) {
  o.spi.miso = v.spi_miso_o;
  o.spi.miso_oe = v.spi_miso_oe_o;
}
#endif

}  // namespace

template <typename V>
class MotionHarness::TopOf : public Top {
 public:
  TopOf(VerilatedContext& ctx, const std::string& vcd, Bus bus, const std::string& top)
      : ctx_(ctx), v_(std::make_unique<V>(&ctx, "dut")), top_(top), bus_(bus) {
    v_->clk_i = 0;
    v_->rst_ni = 0;
    v_->ce_i = 0;
    v_->estop_ni = 1;
    drive_bus(*v_, block_inputs(false, false, BusIn{}), BusIn{});
    v_->eval();
    bridge_ = std::make_unique<VlRegSampler>(ctx, top_ + ".u_bridge", bridge_regs(bus));
    vcd_ = open_waveform(*v_, ctx, vcd);
  }
  ~TopOf() override {
    if (vcd_) vcd_->close();
    v_->final();
    write_coverage(ctx_, "motion");
    Verilated::threadContextp(&ctx_);  // (see MotionHarness::MotionHarness)
    v_.reset();
  }
  TopOf(const TopOf&) = delete;
  TopOf& operator=(const TopOf&) = delete;

  BlockOutputs edge(const BlockInputs& in, const BusIn& host) override {
    v_->rst_ni = in.rst_n;
    v_->ce_i = in.ce;
    v_->estop_ni = in.pins.estop_n;
    v_->limit_i = in.pins.limit;
    v_->home_i = in.pins.home;
    v_->probe_i = in.pins.probe;
    drive_bus(*v_, in, host);
    half_period(*v_, ctx_, vcd_.get(), false);
    half_period(*v_, ctx_, vcd_.get(), true);
    BlockOutputs o;
    read_bus(*v_, o);
    o.step_x = v_->step_x_o;
    o.step_y = v_->step_y_o;
    o.dir_x = v_->dir_x_o;
    o.dir_y = v_->dir_y_o;
    o.step_z = v_->step_z_o;
    o.dir_z = v_->dir_z_o;
    o.busy = v_->busy_o;
    o.irq = v_->irq_o;
    return o;
  }
  std::vector<std::uint64_t> bridge() const override { return bridge_->read(); }
  std::string scope() const override { return bus_ == Bus::wishbone ? top_ : top_ + ".u_motion"; }

 private:
  VerilatedContext& ctx_;
  std::unique_ptr<V> v_;
  std::unique_ptr<VerilatedVcdC> vcd_;
  std::string top_;
  Bus bus_;
  std::unique_ptr<VlRegSampler> bridge_;
};

MotionHarness::MotionHarness(const std::string& vcd, Bus bus)
    : ctx_(std::make_unique<VerilatedContext>()), model_(harness_build()), bridge_(make_bridge(bus)), bus_(bus) {
  ctx_->traceEverOn(!vcd.empty());
  // Verilator (5.006) files a model's scopes under the thread's current context when
  // the model is built and looks them up there again when it is destroyed: make it this
  // harness' context both times, so that two harnesses can live side by side.
  Verilated::threadContextp(ctx_.get());
  switch (bus) {
    case Bus::wishbone:
      top_ = std::make_unique<TopOf<Vdda_motion>>(*ctx_, vcd, bus, "dut.dda_motion");
      break;
#if DDA_HARNESS_BRIDGES
    case Bus::axil:
      top_ = std::make_unique<TopOf<Vdda_motion_axil>>(*ctx_, vcd, bus, "dut.dda_motion_axil");
      break;
    case Bus::spi:
      top_ = std::make_unique<TopOf<Vdda_motion_spi>>(*ctx_, vcd, bus, "dut.dda_motion_spi");
      break;
#endif
    default:
      throw GuardError("motion harness: built without the " + std::string(bus_name(bus)) + " bridge");
  }
  sampler_ = std::make_unique<VlBlockSampler>(*ctx_, top_->scope(), kHarnessDepthLog2);
}

MotionHarness::~MotionHarness() = default;

void MotionHarness::tick(const BusIn& bus) {
  const BlockInputs in = block_inputs(rst_n_, ce_, bridge_ ? bridge_->wishbone() : bus, pins_);
  const BlockOutputs before = model_.outputs();
  out_ = top_->edge(in, bus);
  model_.edge(in);
  seen_ = in.bus;
  ++cycle_;
  BlockOutputs want = model_.outputs();
  const BlockRegs regs = sampler_->block();
  // (The message's prefix is made only for a difference: this runs on every edge.)
  const auto at = [&] { return "motion block, cycle " + std::to_string(cycle_) + ": "; };
  if (bridge_) {
    bridge_->edge(rst_n_, bus, before);
    bridge_->outputs(want);
    // The block's own bus is inside the top: its outputs are its registers.
    out_.ack = out_.stall = regs[breg("ack_q")] != 0;
    out_.dat = std::uint32_t(regs[breg("dat_q")]);
    const std::string d = compare_bridge(bus_, top_->bridge(), *bridge_);
    if (!d.empty()) throw GuardError(at() + d);
  }
  if (!(out_ == want)) throw GuardError(at() + "output ports " + out_.diff(want) + " (rtl/reference model)");
  const std::string diff = compare_block(regs, sampler_->core(), model_);
  if (!diff.empty()) throw GuardError(at() + diff);
  timing_.edge(in.bus, rst_n_, out_, model_.regs());
}

}  // namespace dda::motion
