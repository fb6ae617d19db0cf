// SPDX-License-Identifier: Apache-2.0
// dda vectors --bus (docs/vectors.md, "Bus-level sets"): per-cycle vectors of the motion
// block, from its reference model (model/motion/motion_model.hpp) driven over the Wishbone bus by
// the firmware driver of host/driver/motion_driver.hpp: Wishbone cycles in; acknowledge, read data,
// steps, directions, interrupt, positions and queue level out.
#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "cli/vectors.hpp"
#include "host/driver/feed.hpp"
#include "host/driver/motion_driver.hpp"
#include "tb/engines/motion_harness.hpp"
#include "tb/scenarios/io_scenarios.hpp"

#include "cli/vector_set.hpp"
#include "cli/vector_words.hpp"

namespace dda::vec {

namespace {

// The last member: the bench's register the field drives (tb/hdl/dda_bus_tb.v).
std::vector<Field> bus_input_fields(motion::Bus bus) {
  std::vector<Field> f{{"rst_ni", 1, "reset, active low", "rst_n"}, {"ce_i", 1, "iteration enable", "ce"}};
  switch (bus) {
    case motion::Bus::axil:
      f.insert(f.end(), {{"s_awvalid_i", 1, "write address valid", "awvalid"},
                         {"s_awaddr_i", motion::kAddrWidth, "write address", "awaddr"},
                         {"s_wvalid_i", 1, "write data valid", "wvalid"},
                         {"s_wdata_i", 32, "write data", "wdata"},
                         {"s_wstrb_i", 4, "write strobes", "wstrb"},
                         {"s_bready_i", 1, "write response ready", "bready"},
                         {"s_arvalid_i", 1, "read address valid", "arvalid"},
                         {"s_araddr_i", motion::kAddrWidth, "read address", "araddr"},
                         {"s_rready_i", 1, "read data ready", "rready"}});
      break;
    case motion::Bus::spi:
      f.insert(f.end(), {{"spi_csn_i", 1, "SPI chip select, active low", "csn"},
                         {"spi_sck_i", 1, "SPI clock", "sck"},
                         {"spi_mosi_i", 1, "SPI data in", "mosi"}});
      break;
    default:
      f.insert(f.end(), {{"wb_cyc_i", 1, "Wishbone cycle", "cyc"},
                         {"wb_stb_i", 1, "Wishbone strobe", "stb"},
                         {"wb_we_i", 1, "Wishbone write enable", "we"},
                         {"wb_adr_i", motion::kAddrWidth, "Wishbone byte address", "adr"},
                         {"wb_dat_i", 32, "Wishbone write data", "dat_i"},
                         {"wb_sel_i", 4, "Wishbone byte lanes", "sel"}});
  }
  f.insert(f.end(), {{"estop_ni", 1, "E-stop pin, active low", "estop_n"},
                     {"limit_i", 6, "limit pins {z+, z-, y+, y-, x+, x-}", "limit"},
                     {"home_i", 3, "home pins {z, y, x}", "home"},
                     {"probe_i", 1, "probe pin", "probe"}});
  return f;
}

std::vector<Field> bus_expect_fields(motion::Bus bus) {
  std::vector<Field> f;
  switch (bus) {
    case motion::Bus::axil:
      f = {{"s_awready_o", 1, "write address ready", "awready"},
           {"s_wready_o", 1, "write data ready", "wready"},
           {"s_bvalid_o", 1, "write response valid", "bvalid"},
           {"s_bresp_o", 2, "write response", "bresp"},
           {"s_arready_o", 1, "read address ready", "arready"},
           {"s_rvalid_o", 1, "read data valid", "rvalid"},
           {"s_rdata_o", 32, "read data", "rdata"},
           {"s_rresp_o", 2, "read response", "rresp"}};
      break;
    case motion::Bus::spi:
      f = {{"spi_miso_o", 1, "SPI data out", "miso"}, {"spi_miso_oe_o", 1, "SPI data out enable", "miso_oe"}};
      break;
    default:
      f = {{"wb_ack_o", 1, "acknowledge, after the edge", "ack"},
           {"wb_stall_o", 1, "stall, after the edge", "stall"},
           {"wb_dat_o", 32, "read data, after the edge", "dat_o"}};
  }
  // The block's registers, below the bench's instance (and the bridged top's u_motion).
  const std::string blk = bus == motion::Bus::wishbone ? "dut." : "dut.u_motion.";
  f.insert(f.end(), {{"step_x_o", 1, "X step pulse", "step_x"},
                     {"step_y_o", 1, "Y step pulse", "step_y"},
                     {"dir_x_o", 1, "X direction", "dir_x"},
                     {"dir_y_o", 1, "Y direction", "dir_y"},
                     {"step_z_o", 1, "Z step pulse", "step_z"},
                     {"dir_z_o", 1, "Z direction", "dir_z"},
                     {"busy_o", 1, "the core runs, or a step is on its way to the pins or a pulse is out", "busy"},
                     {"irq_o", 1, "interrupt", "irq"},
                     {"pos_x_q", 32, "X position register", blk + "pos_x_q"},
                     {"pos_y_q", 32, "Y position register", blk + "pos_y_q"},
                     {"pos_z_q", 32, "Z position register", blk + "pos_z_q"},
                     {"level_q", motion::kLevelWidth, "queue level register", blk + "level_q"},
                     {"done_count_q", 32, "done counter register", blk + "done_count_q"}});
  return f;
}

// One cycle's words in the order of the fields above.
std::vector<std::uint64_t> bus_input_word(motion::Bus bus, const motion::BusIn& host, const motion::BlockInputs& in) {
  std::vector<std::uint64_t> v{in.rst_n, in.ce};
  const motion::AxilIn& a = host.axil;
  const std::uint32_t amask = (1u << motion::kAddrWidth) - 1;
  switch (bus) {
    case motion::Bus::axil:
      v.insert(v.end(), {a.awvalid, a.awaddr & amask, a.wvalid, a.wdata, a.wstrb, a.bready, a.arvalid, a.araddr & amask,
                         a.rready});
      break;
    case motion::Bus::spi:
      v.insert(v.end(), {host.spi.csn, host.spi.sck, host.spi.mosi});
      break;
    default:
      v.insert(v.end(), {in.bus.cyc, in.bus.stb, in.bus.we, in.bus.adr, in.bus.dat, in.bus.sel});
  }
  v.insert(v.end(), {in.pins.estop_n, in.pins.limit, in.pins.home, in.pins.probe});
  return v;
}
std::vector<std::uint64_t> bus_expect_word(motion::Bus bus, const motion::BlockOutputs& o, const motion::BlockRegs& r) {
  std::vector<std::uint64_t> v;
  switch (bus) {
    case motion::Bus::axil:
      v = {o.axil.awready, o.axil.wready, o.axil.bvalid, o.axil.bresp,
           o.axil.arready, o.axil.rvalid, o.axil.rdata,  o.axil.rresp};
      break;
    case motion::Bus::spi:
      v = {o.spi.miso, o.spi.miso_oe};
      break;
    default:
      v = {o.ack, o.stall, o.dat};
  }
  v.insert(v.end(), {o.step_x, o.step_y, o.dir_x, o.dir_y, o.step_z, o.dir_z, o.busy, o.irq, r[motion::breg("pos_x_q")],
                     r[motion::breg("pos_y_q")], r[motion::breg("pos_z_q")], r[motion::breg("level_q")],
                     r[motion::breg("done_count_q")]});
  return v;
}

}  // namespace

std::string bus_verilog_fields(motion::Bus bus) {
  const auto ef = bus_expect_fields(bus);
  const int w = total_width(ef);
  std::ostringstream s;
  const std::string kind = bus == motion::Bus::wishbone ? "motion" : std::string(motion::bus_name(bus));
  const std::string with = bus == motion::Bus::wishbone ? "" : " --bridge " + std::string(motion::bus_name(bus));
  s << "// SPDX-License-Identifier: Apache-2.0\n"
       "// Generated by `dda gen-params --kind "
    << kind << "-vector-fields` from cli/bus_vectors.cpp: the\n// per-cycle layout of `dda vectors --bus" << with
    << "` (docs/vectors.md). Do not edit: ctest\n// vectors.bus.fields_in_sync checks it.\n";
  s << "`define DDA_BVEC_IN_WIDTH " << total_width(bus_input_fields(bus)) << "\n";
  // The bench's registers, in the input word's order (most significant first).
  const auto inf = bus_input_fields(bus);
  s << "`define DDA_BVEC_UNPACK(v) {";
  for (std::size_t i = 0; i < inf.size(); ++i) s << (i ? ", " : "") << inf[i].verilog;
  s << "} = v\n";
  s << "`define DDA_BVEC_EXP_WIDTH " << w << "\n";
  s << "`define DDA_BVEC_GOT {";
  for (std::size_t i = 0; i < ef.size(); ++i) s << (i ? ", " : "") << ef[i].verilog;
  s << "}\n";
  std::vector<std::pair<std::string, int>> named;
  for (const auto& f : ef) named.emplace_back(f.name, f.width);
  s << report_macro("DDA_BVEC_REPORT", named);
  return s.str();
}

void add_bus_options(CLI::App* vectors, BusCli& c) {
  vectors->add_flag("--bus", c.bus, "the motion block's set: Wishbone cycles in, steps and positions out");
  vectors->add_flag("--pipelined", c.pipelined, "with --bus: pipelined Wishbone cycles (default classic)");
  vectors
      ->add_option("--bridge", c.bridge,
                   "with --bus: the block behind its AXI4-Lite (axil: rtl/dda_motion_axil.v) or SPI (spi: "
                   "rtl/dda_motion_spi.v) bridge, driven by that bus (default: its Wishbone slave)")
      ->check(CLI::IsMember({"axil", "spi"}));
  vectors->add_option("--build", c.build,
                      "with --bus: the block's build, key=value choices separated by commas (depth_log2, inputs, "
                      "axes, pacer: `dda build`, docs/design.md \"Builds\"; default: the default build)");
  vectors
      ->add_option("--abort-after", c.abort_after,
                   "with --bus: abort N cycles after the last commit (default: none, the queue drains)")
      ->check(CLI::Range(1, 100000000));
  vectors->add_option("--timing", c.timing,
                      "with --bus: STEPLEN,STEPSPACE,DIRSETUP,DIRHOLD in clock cycles, every axis (default 0,0,0,0)");
  vectors->add_option("--timing-x", c.timing_x, "with --bus: X's timings (as --timing)");
  vectors->add_option("--timing-y", c.timing_y, "with --bus: Y's timings (as --timing)");
  vectors->add_option("--timing-z", c.timing_z, "with --bus: Z's timings (as --timing)");
  vectors
      ->add_option("--polarity", c.polarity,
                   "with --bus: POLARITY bits (step_x 1, dir_x 2, step_y 4, dir_y 8, step_z 16, dir_z 32; "
                   "default 0)")
      ->check(CLI::Range(0, 63));
  vectors
      ->add_option("--feed-increment", c.feed,
                   "with --bus: every piece's feed increment, iterations per clock x 2^32 (default 0: full rate)")
      ->check(CLI::Range(std::uint64_t{0}, (std::uint64_t{1} << motion::kFeedWidth) - 1));
  vectors->add_option("--feed-rate", c.feed_rate,
                      "with --bus: feed in steps per second along the path (needs --clock)");
  vectors->add_option("--clock", c.clock_hz, "with --bus --feed-rate: the block's clock in Hz");
  add_bus_pace_options(vectors, c);
  std::string names;
  for (const auto& s : motion::kIoScenarios) names += (names.empty() ? "" : ", ") + std::string(s.name);
  vectors->add_option(
      "--io-scenario", c.io_scenario,
      "with --bus, instead of an arc: a scenario of the machine's inputs on a simulated machine (" + names + ")");
}

namespace {
motion::StageTimings parse_timing(const std::string& opt, const std::string& s) {
  std::vector<std::uint32_t> v;
  std::stringstream in(s);
  std::string item;
  const std::uint32_t max = (1u << motion::kTimingWidth) - 1;
  while (std::getline(in, item, ',')) {
    std::size_t used = 0;
    unsigned long n = 0;
    try {
      n = std::stoul(item, &used, 10);
    } catch (const std::exception&) {
      used = 0;
    }
    if (item.empty() || used != item.size() || item[0] == '-' || n > max) {
      throw InputError(fmt::format("{} '{}': each timing is a number of clock cycles from 0 to {}", opt, s, max));
    }
    v.push_back(std::uint32_t(n));
  }
  if (v.size() != 4) throw InputError(opt + " '" + s + "': give STEPLEN,STEPSPACE,DIRSETUP,DIRHOLD");
  return motion::StageTimings{v[0], v[1], v[2], v[3]};
}
}  // namespace

BusOptions bus_options(const BusCli& c) {
  // (An io scenario takes the bridge and the build, none of the others.)
  const bool settings = c.pipelined || c.abort_after || !c.timing.empty() || !c.timing_x.empty() ||
                        !c.timing_y.empty() || !c.timing_z.empty() || c.polarity || c.feed || c.feed_rate != 0 ||
                        c.clock_hz != 0 || c.scenario();
  const bool any = settings || !c.bridge.empty() || !c.build.empty();
  if (!c.bus) {
    if (any) {
      throw InputError(
          "--pipelined, --bridge, --build, --abort-after, --timing*, --polarity, --feed*, --clock, --accel, --vmin, "
          "--override*, "
          "--hold-at, --resume-at, --soft-stop-at and --watchdog go with --bus only");
    }
    return BusOptions{};
  }
  BusOptions b;
  b.build = motion::parse_build(c.build);
  if (!c.io_scenario.empty()) {
    if (!motion::find_io_scenario(c.io_scenario))
      throw InputError("--io-scenario '" + c.io_scenario + "': no such scenario (--help lists them)");
    if (settings || c.planned)
      throw InputError(
          "--io-scenario runs its own moves and settings: give it with --bus, --bridge, --build, --out-dir, --vcd "
          "alone");
    if (!b.build.inputs) throw InputError("--io-scenario needs the machine inputs: the build has none (inputs=0)");
    b.io_scenario = c.io_scenario;
    b.bridge = c.bridge == "axil" ? motion::Bus::axil : c.bridge == "spi" ? motion::Bus::spi : motion::Bus::wishbone;
    const unsigned needs = motion::find_io_scenario(c.io_scenario)->needs;
    const std::string which = "--io-scenario " + c.io_scenario;
    if ((needs & motion::kNeedsPacer) && !b.build.pacer)
      throw InputError(which + " needs the pacer (its ramped stops, its registers): the build has none (pacer=0)");
    if ((needs & motion::kNeedsZ) && b.build.axes == 2)
      throw InputError(which + " moves or reads the third axis: the build has two axes (axes=2)");
    if ((needs & motion::kNeedsFastBus) && b.bridge == motion::Bus::spi)
      throw InputError(which +
                       " times its accesses closer than an SPI frame (some 300 clocks): run it on Wishbone "
                       "or --bridge axil");
    return b;
  }
  b.bridge = c.bridge == "axil" ? motion::Bus::axil : c.bridge == "spi" ? motion::Bus::spi : motion::Bus::wishbone;
  if (c.pipelined && b.bridge != motion::Bus::wishbone) {
    throw InputError("--pipelined chooses Wishbone cycles: it does not go with --bridge");
  }
  b.pipelined = c.pipelined;
  b.abort_after = c.abort_after;
  if (!c.timing.empty()) b.timing_x = b.timing_y = b.timing_z = parse_timing("--timing", c.timing);
  if (!c.timing_x.empty()) b.timing_x = parse_timing("--timing-x", c.timing_x);
  if (!c.timing_y.empty()) b.timing_y = parse_timing("--timing-y", c.timing_y);
  if (!c.timing_z.empty()) b.timing_z = parse_timing("--timing-z", c.timing_z);
  b.polarity = c.polarity;
  if (c.feed && c.feed_rate != 0) throw InputError("--feed-increment and --feed-rate are alternatives: give one");
  if (c.planned) {
    if (c.feed || c.feed_rate != 0 || (c.vmin_opt && c.vmin_opt->count()))
      throw InputError("--feed-increment, --feed-rate and --vmin are an arc's: a program's speeds are planned");
    if (!(c.clock_hz >= 1 && c.clock_hz <= 1e10))
      throw InputError("--speeds with --bus needs --clock HZ (the block's clock, 1 to 1e10)");
  } else if ((c.feed_rate != 0) != (c.clock_hz != 0)) {
    throw InputError("--feed-rate and --clock go together");
  }
  // (nan and inf fail these comparisons too.)
  if (c.feed_rate != 0 && !(c.feed_rate > 0 && c.feed_rate <= 1e9)) {
    throw InputError(
        fmt::format("feed-rate = {} is out of range: steps per second, above 0 and at most 1e9", c.feed_rate));
  }
  if (c.clock_hz != 0 && !(c.clock_hz >= 1 && c.clock_hz <= 1e10)) {
    throw InputError(fmt::format("clock = {} is out of range: Hz, from 1 to 1e10", c.clock_hz));
  }
  b.feed = c.feed;
  b.feed_rate = c.feed_rate;
  b.clock_hz = c.clock_hz;
  b.planned = c.planned;
  bus_pace_options(c, b);
  // A build without the pacer runs every entry at its feed increment and takes no write of
  // ACCEL, VMIN or OVERRIDE: a set that would rely on them is refused, not made wrong.
  if (!b.build.pacer && (b.paced || b.planned || b.override_ != motion::kOverrideOne))
    throw InputError(
        "--accel, --speeds and --override pace entries by the pacer: the build has none (pacer=0; --feed-rate "
        "paces by the feed increment)");
  return b;
}

// The firmware's work: reset, preset the positions to the first arc's start, queue every
// piece, then drain the queue (or abort), read the positions.
void drive(motion::BusTarget& t, const std::vector<Plan>& plans, const Options& opt, const BusOptions& bus) {
  const std::unique_ptr<motion::BusMaster> master =
      motion::make_master(bus.bridge, t, opt.seed, bus.pipelined, bus.idle_percent);
  motion::BusMaster& m = *master;
  std::mt19937_64 ce_rng(opt.seed + 1);
  std::uint64_t cycle = 0;  // the set's cycles so far
  m.each_cycle = [&] {
    ++cycle;
    t.set_ce(int(ce_rng() % 100) < opt.ce_percent);
  };
  motion::MotionDriver d(m, opt.seed + 2);
  t.set_reset(false);
  m.idle(2);
  t.set_reset(true);
  d.set_timings('x', bus.timing_x);
  d.set_timings('y', bus.timing_y);
  d.set_timings('z', bus.timing_z);
  d.set_polarity(bus.polarity);
  if (bus.paced) {
    const PaceOptions& o = bus.pace;
    d.set_pacing(std::uint32_t(accel_field(o.accel, o.clock_hz)), speed_field(o.vmin, o.clock_hz));
  }
  if (bus.planned) d.set_pacing(std::uint32_t(bus.planned_accel), bus.planned_vmin);
  if (bus.override_ != motion::kOverrideOne && bus.override_at == 0) d.set_override(bus.override_);
  d.preset(plans.front().from);
  const std::vector<motion::PaceEntry> pace = bus_pace_entries(plans, bus);
  std::size_t k = 0;
  for (const auto& p : plans) {
    for (const auto& piece : p.pieces) {
      const std::uint32_t f = bus.paced || bus.planned || bus.feed_rate == 0
                                  ? bus.feed
                                  : feed::feed_increment(feed::piece_motion(piece.cmd), bus.feed_rate, bus.clock_hz);
      d.queue(piece.cmd, f, piece.rot, bus.paced || bus.planned ? pace[k++] : motion::PaceEntry{});
    }
  }
  run_bus_scenario(m, d, bus, cycle);
  m.read(motion::reg_offset("STATUS"));
  d.position();
  m.idle(4);
}

namespace {
// The set's work: the plans, or the machine-input scenario with every check it makes (a
// scenario that fails one writes no set).
void drive_set(motion::BusTarget& t, const std::vector<Plan>& plans, const Options& opt, const BusOptions& bus) {
  if (bus.io_scenario.empty()) return drive(t, plans, opt, bus);
  const motion::IoScenario& s = *motion::find_io_scenario(bus.io_scenario);
  s.run(t, motion::Expect([&](bool ok, const std::string& what) {
          if (!ok) throw GuardError("the " + std::string(s.name) + " scenario failed a check: " + what);
        }));
}

// The manifest's record of how the set was made (docs/vectors.md).
nlohmann::ordered_json bus_manifest(const Options& opt, const BusOptions& bus, std::uint64_t ncycles) {
  nlohmann::ordered_json j;
  j["generator"] = "dda vectors --bus (the motion block's reference model, model/motion/motion_model.hpp)";
  j["command_line"] = opt.command_line;
  j["cycles"] = ncycles;
  j["queue_depth_log2"] = bus.build.depth_log2;
  j["build"] = motion::build_spec(bus.build);
  j["bus"] = std::string(motion::bus_name(bus.bridge));
  if (bus.bridge == motion::Bus::wishbone) j["bus_cycles"] = bus.pipelined ? "pipelined" : "classic";
  j["abort_after"] = bus.abort_after;
  const auto timing = [](const motion::StageTimings& t) {
    return nlohmann::ordered_json{
        {"steplen", t.steplen}, {"stepspace", t.stepspace}, {"dirsetup", t.dirsetup}, {"dirhold", t.dirhold}};
  };
  j["timing_x"] = timing(bus.timing_x);
  j["timing_y"] = timing(bus.timing_y);
  j["timing_z"] = timing(bus.timing_z);
  j["polarity"] = bus.polarity;
  if (bus.feed_rate > 0 || bus.planned) {
    if (bus.feed_rate > 0) j["feed_rate_steps_per_s"] = bus.feed_rate;
    j["clock_hz"] = bus.clock_hz;
  } else {
    j["feed_increment"] = bus.feed;
  }
  if (bus.paced) {
    j["paced"] = {{"accel_steps_per_s2", bus.pace.accel}, {"vmin_steps_per_s", bus.pace.vmin}};
  }
  if (bus.planned) {
    j["planned_speeds"] = {
        {"accel", bus.planned_accel}, {"vmin", bus.planned_vmin}, {"entries", bus.planned_entries.size()}};
  }
  if (!bus.io_scenario.empty()) {
    j["io_scenario"] = bus.io_scenario;
    return j;
  }
  j["scenario"] = {{"override", bus.override_},  {"override_at", bus.override_at},   {"hold_at", bus.hold_at},
                   {"resume_at", bus.resume_at}, {"soft_stop_at", bus.soft_stop_at}, {"watchdog", bus.watchdog}};
  return j;
}
}  // namespace

void write_bus_vector_set(const std::vector<Plan>& plans, const Options& opt, const BusOptions& bus) {
  if (plans.empty() && bus.io_scenario.empty()) throw InputError("vectors need at least one arc");
  // A block of two axes reads no linear axis and no axes field: a set that needs them is
  // refused. The RTL the tool runs for --vcd is the default build's.
  if (bus.build.axes == 2)
    for (const auto& p : plans)
      for (const auto& piece : p.pieces)
        if (piece.cmd.cnt_z != 0 || piece.rot != 0)
          throw InputError("the build has two axes (axes=2): a move of the third axis or on another plane is refused");
  if (!bus.vcd.empty() && motion::build_spec(bus.build) != motion::build_spec(motion::Build{}))
    throw InputError("--vcd runs the default build's RTL: it does not go with another --build");
  // The per-cycle files stream into the set's temporary directory; every line of them
  // has the same length, so the count of cycles is the size: past --max-size the run
  // stops, and the temporary directory goes with the error (the target is untouched).
  SetWriter set(opt.out_dir);
  std::ostream& in_hex = set.open("cycle_in.hex");
  std::ostream& exp_hex = set.open("cycle_exp.hex");
  motion::ModelTarget t(bus.build, bus.bridge);
  std::uint64_t ncycles = 0;
  const auto inf = bus_input_fields(bus.bridge);
  const auto exf = bus_expect_fields(bus.bridge);
  // (A line's length: a word of zeros, as hex_word() writes every word, and its newline.)
  const auto line_of = [](const std::vector<Field>& f) {
    return std::uint64_t(hex_word(f, std::vector<std::uint64_t>(f.size(), 0)).size() + 1);
  };
  const std::uint64_t line = line_of(inf) + line_of(exf);
  t.on_edge = [&](const motion::BusIn& host, const motion::BlockInputs& in, const motion::BlockOutputs& o,
                  const motion::MotionModel& m) {
    if ((ncycles + 1) * line > opt.max_size) {
      throw InputError(
          fmt::format("the vector set would take more than --max-size {} ({} bytes) after {} cycles: "
                      "nothing is written (a larger --max-size writes it)",
                      size_text(opt.max_size), opt.max_size, ncycles));
    }
    in_hex << hex_word(inf, bus_input_word(bus.bridge, host, in)) << '\n';
    exp_hex << hex_word(exf, bus_expect_word(bus.bridge, o, m.regs())) << '\n';
    ++ncycles;
  };
  drive_set(t, plans, opt, bus);
  if (!bus.vcd.empty()) {
    // The RTL through the same cycles (the master decides from the outputs, equal to the
    // model's edge by edge: the harness checks every edge), writing its waveform.
    motion::MotionHarness h(bus.vcd, bus.bridge);
    drive_set(h, plans, opt, bus);
  }

  nlohmann::ordered_json j = bus_manifest(opt, bus, ncycles);
  j["files"] = {{"counts.hex", "the number of cycles"},
                {"cycle_in.hex", "per cycle: the inputs applied before the edge (layout cycle_in)"},
                {"cycle_exp.hex", "per cycle: the outputs and registers after the edge (layout cycle_exp)"}};
  j["layout"] = {{"cycle_in", field_layout(inf)}, {"cycle_exp", field_layout(exf)}};
  const std::string counts = fmt::format("{:x}\n", ncycles), manifest = j.dump(1) + "\n";
  const std::uint64_t size = ncycles * line + counts.size() + manifest.size();
  if (size > opt.max_size) {
    throw InputError(
        fmt::format("the vector set would take {} ({} bytes), more than --max-size {}: nothing is "
                    "written (a larger --max-size writes it)",
                    size_text(size), size, size_text(opt.max_size)));
  }
  set.write("counts.hex", counts);
  set.write("manifest.json", manifest);
  set.commit();
}

}  // namespace dda::vec
