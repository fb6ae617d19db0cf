// dda vectors (docs/vectors.md): a golden cycle model of the core's documented control
// (docs/design.md, "Behaviour, edge by edge") around the golden datapath, and the files.
#include "vectors.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "dda/hw_command.hpp"
#include "dda/hw_params.hpp"
#include "dda_random.hpp"

namespace dda::vec {

namespace fs = std::filesystem;

namespace {

constexpr int kIdxWidth = 16;  // command index field of the per-cycle inputs
constexpr int kCmdAddrBits = 12;  // the bench's command memory: 2^12 commands
constexpr std::size_t kMaxCommands = std::size_t{1} << kCmdAddrBits;

// One field of a vector word: name, width, meaning, and (expected words) the Verilog
// expression the bench compares it with, relative to the core instance `dut`.
struct Field {
  std::string name;
  int width;
  std::string meaning;
  std::string verilog;
};

std::vector<Field> input_fields() {
  return {{"rst_ni", 1, "reset, active low, applied before the edge", ""},
          {"ce_i", 1, "iteration enable, applied before the edge", ""},
          {"cmd_valid_i", 1, "a command is offered during the cycle", ""},
          {"cmd_idx", kIdxWidth, "line of cmds.hex offered on cmd_i", ""}};
}

std::vector<Field> expect_fields() {
  std::vector<Field> f = {
      {"cmd_ready_o", 1, "ready during the cycle, before the edge (combinational)", "ready"},
      {"step_x_o", 1, "X step pulse after the edge", "step_x"},
      {"step_y_o", 1, "Y step pulse after the edge", "step_y"},
      {"dir_x_o", 1, "X direction after the edge (0 = +X)", "dir_x"},
      {"dir_y_o", 1, "Y direction after the edge (0 = +Y)", "dir_y"},
      {"busy_o", 1, "running a command, after the edge", "busy"},
      {"done_o", 1, "a command finished on the edge", "done"},
      {"err_o", 1, "a command stalled on the edge", "err"},
      {"iter_o", 1, "an iteration happened on the edge", "iter"}};
  for (const auto& r : hw::kRegisters) {
    f.push_back({std::string(r.name), r.width, std::string(r.meaning) + ", after the edge", "dut." + std::string(r.name)});
  }
  return f;
}

std::vector<Field> iteration_fields() {
  return {{"arc_end", 1, "the last iteration of an arc", ""},
          {"seg_end", 1, "the last iteration of a piece (command)", ""},
          {"dir_y", 1, "Y step direction (0 = +Y)", ""},
          {"step_y", 1, "Y step", ""},
          {"dir_x", 1, "X step direction (0 = +X)", ""},
          {"step_x", 1, "X step", ""}};
}

int total_width(const std::vector<Field>& fs) {
  int w = 0;
  for (const auto& f : fs) w += f.width;
  return w;
}

// A wide word built field by field, most significant first, printed in hex.
class Word {
 public:
  explicit Word(int width) : bits_(std::size_t(width), 0) {}
  void put(std::uint64_t v, int width) {
    for (int k = width - 1; k >= 0; --k) bits_[pos_++] = (v >> k) & 1;
  }
  std::string hex() const {
    const int w = int(bits_.size()), digits = (w + 3) / 4;
    std::string s(std::size_t(digits), '0');
    for (int d = 0; d < digits; ++d) {
      int v = 0;
      for (int k = 0; k < 4; ++k) {
        const int bit = w - 1 - (4 * (digits - 1 - d) + (3 - k));  // index from the MSB
        v = v * 2 + (bit >= 0 && bit < w ? bits_[std::size_t(bit)] : 0);
      }
      s[std::size_t(d)] = "0123456789abcdef"[v];
    }
    return s;
  }

 private:
  std::vector<char> bits_;
  std::size_t pos_ = 0;
};

std::uint64_t mask(std::int64_t v, int width) {
  return width >= 64 ? std::uint64_t(v) : std::uint64_t(v) & ((std::uint64_t{1} << width) - 1);
}

// The core's registers, as the golden cycle model holds them.
struct CoreRegs {
  std::int64_t jv_x = 0, jr_x = 0, ix_x = 0, iy_x = 0, jv_y = 0, jr_y = 0, ix_y = 0, iy_y = 0;
  std::int64_t cnt_x = 0, cnt_y = 0, cap = 0;
  bool cdir_x = false, cdir_y = false, dir_x = false, dir_y = false, step_x = false, step_y = false;
  bool run = false, done = false, err = false, iter = false;
  std::vector<std::uint64_t> values() const {
    return {mask(jv_x, hw::kAccWidth), mask(jr_x, hw::kAccWidth), mask(ix_x, hw::kAccWidth), mask(iy_x, hw::kAccWidth),
            mask(jv_y, hw::kAccWidth), mask(jr_y, hw::kAccWidth), mask(ix_y, hw::kAccWidth), mask(iy_y, hw::kAccWidth),
            mask(cnt_x, hw::kCntWidth), mask(cnt_y, hw::kCntWidth), mask(cap, hw::kAccWidth), cdir_x, cdir_y, dir_x,
            dir_y, step_x, step_y, run ? unsigned(hw::State::Run) : unsigned(hw::State::Idle), done, err, iter};
  }
};

struct Cmd {
  Command c;
  std::size_t arc = 0, seg = 0;
  bool arc_last = false;
};

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary);
  f << text;
  f.close();
  if (!f) throw GuardError("vectors: cannot write " + p.string());
}

}  // namespace

std::string verilog_fields() {
  const auto ef = expect_fields();
  const int w = total_width(ef);
  std::ostringstream s;
  s << "// Generated by `dda gen-params --kind vector-fields` from model/include/dda/hw_params.hpp\n"
       "// and tb/cli/vectors.cpp: the per-cycle vector layout of `dda vectors` (docs/vectors.md).\n"
       "// Do not edit: the test \"hw_params: tb/vectors/dda_vec_fields.vh is in sync\" checks it.\n";
  s << "`define DDA_VEC_IN_WIDTH " << total_width(input_fields()) << "\n";
  s << "`define DDA_VEC_EXP_WIDTH " << w << "\n";
  s << "`define DDA_VEC_IDX_WIDTH " << kIdxWidth << "\n";
  s << "`define DDA_VEC_CMD_ADDR_BITS " << kCmdAddrBits << "  // the bench holds 2^this commands\n";
  s << "// The word the bench compares after the edge: `ready` is cmd_ready_o sampled before\n"
       "// it, step_x .. iter the wires on the core's outputs, dut.* its registers.\n";
  s << "`define DDA_VEC_GOT(ready) {";
  for (std::size_t i = 0; i < ef.size(); ++i) s << (i ? ", " : "") << ef[i].verilog;
  s << "}\n";
  s << "// Reports the first field (most significant first) where exp and got differ.\n";
  s << "`define DDA_VEC_REPORT(cyc, exp, got) \\\n";
  int msb = w - 1;
  for (std::size_t i = 0; i < ef.size(); ++i) {
    const int lsb = msb - ef[i].width + 1;
    s << "  " << (i ? "else " : "") << "if ((exp[" << msb << ":" << lsb << "]) !== (got[" << msb << ":" << lsb
      << "])) $display(\"MISMATCH cycle %0d field " << ef[i].name << ": expected 'h%0h, got 'h%0h\", cyc, exp["
      << msb << ":" << lsb << "], got[" << msb << ":" << lsb << "]); \\\n";
    msb = lsb - 1;
  }
  s << "  else $display(\"MISMATCH cycle %0d\", cyc);\n";
  return s.str();
}

void write_vector_set(const std::vector<Plan>& plans, const Options& opt) {
  if (plans.empty()) throw InputError("vectors need at least one arc");
  // The command stream: every piece of every arc, back to back.
  std::vector<Cmd> cmds;
  for (std::size_t a = 0; a < plans.size(); ++a) {
    for (std::size_t k = 0; k < plans[a].segs.size(); ++k) {
      hw::pack_command(plans[a].segs[k].cmd);  // throws InputError if a field does not fit
      cmds.push_back({plans[a].segs[k].cmd, a, k, k + 1 == plans[a].segs.size()});
    }
  }
  if (cmds.size() > kMaxCommands) {
    throw InputError("vectors: " + std::to_string(cmds.size()) + " commands are too many: tb/vectors/dda_vec_tb.v holds " +
                     std::to_string(kMaxCommands));
  }
  std::uint64_t bound = 16;
  for (const auto& p : plans) bound += p.iteration_bound;
  if (opt.ce_percent < 1 || opt.ce_percent > 100) {
    throw InputError("ce-percent = " + std::to_string(opt.ce_percent) + " is invalid: use 1 to 100");
  }
  bound = bound * 100 / std::uint64_t(opt.ce_percent) * 2 + 64;

  const auto in_f = input_fields(), exp_f = expect_fields(), it_f = iteration_fields();
  std::ostringstream cmds_hex, in_hex, out_hex, cyc_csv, it_hex, it_csv;
  for (const auto& c : cmds) {
    Word w(hw::kCmdWidth);
    const auto v = hw::command_fields(c.c);
    for (std::size_t i = hw::kCmdFields.size(); i-- > 0;) w.put(v[i], hw::kCmdFields[i].width);  // cmd_i[MSB..0]
    cmds_hex << w.hex() << '\n';
  }
  cyc_csv << "cycle";
  for (const auto& f : in_f) cyc_csv << ',' << f.name;
  for (const auto& f : exp_f) cyc_csv << ',' << f.name;
  cyc_csv << '\n';
  it_csv << "iteration,arc,seg,step_x,dir_x,step_y,dir_y,seg_end,arc_end,x,y\n";

  // The golden cycle model.
  std::mt19937_64 rng(opt.seed);
  CoreRegs r;
  std::optional<Datapath> dp;
  std::size_t next = 0, cur = 0;
  std::uint64_t cycle = 0, iterations = 0;
  int idle_tail = 0;
  for (;; ++cycle) {
    if (cycle > bound) throw GuardError("vectors: the command stream did not finish within " + std::to_string(bound) + " cycles");
    const bool rst_n = cycle >= 2;
    const bool ce = opt.ce_percent >= 100 || int(rng() % 100) < opt.ce_percent;
    const bool valid = rst_n && next < cmds.size();
    const std::size_t idx = std::min(next, cmds.size() - 1);
    bool ready = false;
    CoreRegs n = r;
    if (!rst_n) {
      n = CoreRegs{};
      dp.reset();
    } else {
      const bool run_ce = r.run && ce;
      const bool active_x = r.cnt_x != 0, active_y = r.cnt_y != 0;
      const bool finished = run_ce && !active_x && !active_y;
      const bool stalled = run_ce && !finished && dp && dp->stalled();
      const bool iterate = run_ce && !finished && !stalled;
      Iteration it;
      if (iterate) {
        it = dp->iterate();
        n.jv_x = it.after.jv_x, n.jr_x = it.after.jr_x, n.cnt_x = it.after.cnt_x;
        n.jv_y = it.after.jv_y, n.jr_y = it.after.jr_y, n.cnt_y = it.after.cnt_y;
        ++iterations;
        const bool seg_end = dp->done();
        const bool arc_end = seg_end && cmds[cur].arc_last;
        Word w(total_width(it_f));
        for (const int b : {int(arc_end), int(seg_end), int(r.cdir_y), int(it.step_y), int(r.cdir_x), int(it.step_x)}) w.put(unsigned(b), 1);
        it_hex << w.hex() << '\n';
        it_csv << fmt::format("{},{},{},{},{},{},{},{},{},{},{}\n", iterations, cmds[cur].arc, cmds[cur].seg, int(it.step_x),
                              int(r.cdir_x), int(it.step_y), int(r.cdir_y), int(seg_end), int(arc_end), it.pos.x, it.pos.y);
      }
      const bool finishing = finished || (iterate && n.cnt_x == 0 && n.cnt_y == 0);
      ready = !r.run || finishing;
      const bool load = ready && valid;
      n.step_x = iterate && it.step_x;
      n.step_y = iterate && it.step_y;
      n.dir_x = n.step_x ? r.cdir_x : r.dir_x;
      n.dir_y = n.step_y ? r.cdir_y : r.dir_y;
      n.done = finishing;
      n.err = stalled;
      n.iter = iterate;
      n.run = load ? true : (finishing || stalled) ? false : r.run;
      if (load) {
        const Cmd& c = cmds[next];
        const Point start = plans[c.arc].segs[c.seg].from;
        dp.emplace(c.c, start);
        n.jv_x = c.c.jv_x, n.jr_x = c.c.jr_x, n.ix_x = c.c.inc_x_on_x, n.iy_x = c.c.inc_x_on_y;
        n.jv_y = c.c.jv_y, n.jr_y = c.c.jr_y, n.ix_y = c.c.inc_y_on_x, n.iy_y = c.c.inc_y_on_y;
        n.cnt_x = c.c.cnt_x, n.cnt_y = c.c.cnt_y, n.cap = c.c.cap;
        n.cdir_x = c.c.dir_x_neg, n.cdir_y = c.c.dir_y_neg;
        cur = next++;
      }
    }
    r = n;
    Word in(total_width(in_f));
    in.put(rst_n, 1);
    in.put(ce, 1);
    in.put(valid, 1);
    in.put(idx, kIdxWidth);
    in_hex << in.hex() << '\n';
    Word out(total_width(exp_f));
    const std::vector<std::uint64_t> outs = {ready, r.step_x, r.step_y, r.dir_x, r.dir_y, r.run, r.done, r.err, r.iter};
    for (std::size_t i = 0; i < outs.size(); ++i) out.put(outs[i], 1);
    const auto regs = r.values();
    for (std::size_t i = 0; i < regs.size(); ++i) out.put(regs[i], hw::kRegisters[i].width);
    out_hex << out.hex() << '\n';
    cyc_csv << cycle << ',' << rst_n << ',' << ce << ',' << valid << ',' << idx;
    for (const auto v : outs) cyc_csv << ',' << v;
    for (const auto v : regs) cyc_csv << ',' << v;
    cyc_csv << '\n';
    if (rst_n && next == cmds.size() && !r.run && ++idle_tail > 2) break;
  }
  const std::uint64_t ncycles = cycle + 1;

  // Manifest.
  nlohmann::ordered_json m;
  m["generator"] = "dda vectors (golden model; docs/vectors.md)";
  m["command"] = opt.command_line;
  m["seed"] = opt.seed;
  m["ce_percent"] = opt.ce_percent;
  m["widths"] = {{"acc_width", hw::kAccWidth}, {"cnt_width", hw::kCntWidth}, {"cmd_width", hw::kCmdWidth}};
  nlohmann::ordered_json arcs = nlohmann::ordered_json::array();
  for (const auto& p : plans) {
    arcs.push_back({{"options", describe(p)}, {"pieces", p.segs.size()}, {"from", {p.from.x, p.from.y}}, {"to", {p.to.x, p.to.y}}});
  }
  m["arcs"] = arcs;
  m["counts"] = {{"commands", cmds.size()}, {"cycles", ncycles}, {"iterations", iterations}};
  const auto layout = [](const std::vector<Field>& fs) {
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    int msb = total_width(fs) - 1;
    for (const auto& f : fs) {
      a.push_back({{"name", f.name}, {"msb", msb}, {"lsb", msb - f.width + 1}, {"width", f.width}, {"meaning", f.meaning}});
      msb -= f.width;
    }
    return a;
  };
  nlohmann::ordered_json cmd_layout = nlohmann::ordered_json::array();
  {
    int off = 0;
    for (const auto& f : hw::kCmdFields) {
      cmd_layout.push_back({{"name", "cmd_" + std::string(f.name)}, {"msb", off + f.width - 1}, {"lsb", off},
                            {"width", f.width}, {"meaning", std::string(f.meaning)}});
      off += f.width;
    }
  }
  m["files"] = {
      {"counts.hex", "two hex numbers, one per line: commands, cycles"},
      {"cmds.hex", "one command word (cmd_i, " + std::to_string(hw::kCmdWidth) + " bits) per line, line = cmd_idx"},
      {"cycle_in.hex", "per cycle: the inputs (layout cycle_in)"},
      {"cycle_exp.hex", "per cycle: the expected outputs and registers (layout cycle_exp)"},
      {"cycles.csv", "per cycle: inputs and expected values in decimal"},
      {"iter.hex", "per iteration: pulses, directions and end flags (layout iteration)"},
      {"iterations.csv", "per iteration: the same with arc, piece and position"}};
  m["layout"] = {{"cmd", cmd_layout}, {"cycle_in", layout(in_f)}, {"cycle_exp", layout(exp_f)}, {"iteration", layout(it_f)}};

  // Atomic: everything into a temporary directory next to the target, then rename.
  const fs::path dir(opt.out_dir);
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir) || (!fs::is_empty(dir) && !fs::exists(dir / "manifest.json"))) {
      throw InputError("out-dir = '" + opt.out_dir + "' is invalid: it exists and is not a vector set (no manifest.json)");
    }
  }
  const fs::path tmp = dir.parent_path() / (dir.filename().string() + ".tmp." + std::to_string(::getpid()));
  fs::remove_all(tmp, ec);
  if (!fs::create_directories(tmp, ec) || ec) {
    throw GuardError("vectors: cannot create " + tmp.string() + ": " + ec.message());
  }
  try {
    write_text(tmp / "counts.hex", fmt::format("{:x}\n{:x}\n", cmds.size(), ncycles));
    write_text(tmp / "cmds.hex", cmds_hex.str());
    write_text(tmp / "cycle_in.hex", in_hex.str());
    write_text(tmp / "cycle_exp.hex", out_hex.str());
    write_text(tmp / "cycles.csv", cyc_csv.str());
    write_text(tmp / "iter.hex", it_hex.str());
    write_text(tmp / "iterations.csv", it_csv.str());
    write_text(tmp / "manifest.json", m.dump(1) + "\n");
    if (fs::exists(dir)) {
      const fs::path old = dir.parent_path() / (dir.filename().string() + ".old." + std::to_string(::getpid()));
      fs::rename(dir, old);
      fs::rename(tmp, dir);
      fs::remove_all(old);
    } else {
      fs::rename(tmp, dir);
    }
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
}

}  // namespace dda::vec
