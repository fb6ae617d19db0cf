// SPDX-License-Identifier: Apache-2.0
// `import dda`: the golden model, the planner and the program reader for Python
// testbenches (cocotb, pyuvm, plain pytest). The arc and program options are the `dda`
// command's, by name (dda.plan(a=10, b=6, bits=4, preload="zero")), parsed by the same
// code with the same messages; a bad one raises dda.InputError (a ValueError).
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>
#include <string>
#include <vector>

#include "cli/options/arc_options.hpp"
#include "cli/options/program_cmd.hpp"
#include "host/pipeline/pipeline.hpp"
#include "host/program/program.hpp"
#include "host/report/report.hpp"
#include "host/run/entries.hpp"
#include "host/run/live_run.hpp"
#include "model/datapath/core_model.hpp"
#include "model/datapath/hw_command.hpp"

namespace py = pybind11;

namespace dda::python {

namespace {

// Keyword arguments as the command's options: from_=(0, 0) -> {"--from", "0,0"}; a
// True flag -> {"--line"}; False and None are left out.
std::vector<std::string> to_args(const py::kwargs& kw) {
  std::vector<std::string> args;
  for (const auto& [key, value] : kw) {
    std::string name = py::str(key);
    while (!name.empty() && name.back() == '_') name.pop_back();
    for (char& c : name) c = c == '_' ? '-' : c;
    if (value.is_none()) continue;
    if (py::isinstance<py::bool_>(value)) {
      if (value.cast<bool>()) args.push_back("--" + name);
      continue;
    }
    std::string text;
    if (py::isinstance<py::tuple>(value) || py::isinstance<py::list>(value)) {
      for (const auto& e : value) text += (text.empty() ? "" : ",") + std::string(py::str(e));
    } else {
      text = py::str(value);
    }
    args.push_back("--" + name);
    args.push_back(text);
  }
  return args;
}

py::tuple point(const Point& p) { return py::make_tuple(p.x, p.y, p.z); }

std::vector<Iteration> records(const Plan& plan) { return run_records(plan); }

// Runs the plan through the golden engine into `sink`; the report it wrote.
std::string report(const Plan& plan, RunSink& sink, std::ostringstream& os) {
  GoldenEngine engine(sink);
  run_plan(plan, engine, sink);
  return os.str();
}

py::dict stats_dict(const Stats& s) {
  py::dict d;
  d["iterations"] = s.iterations;
  d["moves"] = s.moves;
  d["pulses_x"] = s.pulses_x;
  d["pulses_y"] = s.pulses_y;
  d["pulses_z"] = s.pulses_z;
  d["points"] = s.points;
  d["max_dev"] = s.max_dev;
  d["max_dev_at"] = point(s.max_dev_at);
  d["mean_dev"] = s.mean_dev;
  return d;
}

py::dict signals_dict(const Signals& s) {
  py::dict d;
  for (std::size_t i = 0; i < hw::kNumSignals; ++i) d[py::str(std::string(hw::kSignals[i].name))] = s[i];
  return d;
}

std::vector<program::Move> read_moves(const py::kwargs& kw) {
  const cli::ProgramCli prog = cli::program_from_args(to_args(kw));
  const ProgramRun run = cli::program_run(prog, Preload::Half, false);
  const auto in = program::open_program(prog.file);
  std::vector<program::Move> moves;
  program::read_stream(*in, run.file, run.read, [&](const program::Move& mv) { moves.push_back(mv); });
  return moves;
}

py::dict piece_entry(const live::PieceEntry& p) {
  py::dict d;
  d["piece"] = p.piece;
  d["line"] = p.line;
  d["from"] = point(p.from);
  d["to"] = point(p.to);
  d["words"] = p.words;
  return d;
}

// A part program's entries: the program options by name, with machine_config (a file)
// and clock (Hz) taken out first.
py::dict program_entry_words(py::kwargs kw) {
  std::string config;
  double clock = 0;
  if (kw.contains("machine_config")) {
    config = py::str(kw["machine_config"]);
    PyDict_DelItemString(kw.ptr(), "machine_config");
  }
  if (kw.contains("clock")) {
    clock = kw["clock"].cast<double>();
    PyDict_DelItemString(kw.ptr(), "clock");
  }
  const cli::ProgramCli prog = cli::program_from_args(to_args(kw));
  ProgramRun run = cli::program_run(prog, Preload::Half, true);
  speed::MachineLimits lim = speed::default_limits(run.read.machine);
  if (!config.empty()) lim = speed::read_machine_config(config, lim, run.read.machine);
  speed::check(lim, run.read.machine);
  run.lattice.step = live::live_step(lim, run.read.machine, run.lattice.step);
  if (clock == 0) clock = lim.live.clock_hz;
  if (!(clock > 0 && clock <= 1e9)) throw InputError("clock is out of range: Hz, above 0 and at most 1e9");
  const speed::PaceSetup setup = live::program_setup(run, lim, clock);
  const auto in = program::open_program(prog.file);
  py::list pieces;
  live::program_entries(*in, run, lim, setup, [&](const live::PieceEntry& p) { pieces.append(piece_entry(p)); });
  py::dict out;
  out["accel"] = setup.accel;
  out["vmin"] = setup.vmin;
  out["clock_hz"] = setup.clock_hz;
  out["step_mm"] = setup.step_mm;
  out["pieces"] = pieces;
  return out;
}

void bind_types(py::module_& m) {
  py::class_<Command>(m, "Command",
                      "one hardware command: the fields of the command word, as the golden model holds them")
      .def_readonly("jv_x", &Command::jv_x)
      .def_readonly("jv_y", &Command::jv_y)
      .def_readonly("jr_x", &Command::jr_x)
      .def_readonly("jr_y", &Command::jr_y)
      .def_readonly("cap", &Command::cap)
      .def_readonly("cnt_x", &Command::cnt_x)
      .def_readonly("cnt_y", &Command::cnt_y)
      .def_readonly("dir_x_neg", &Command::dir_x_neg)
      .def_readonly("dir_y_neg", &Command::dir_y_neg)
      .def_readonly("inc_x_on_x", &Command::inc_x_on_x)
      .def_readonly("inc_x_on_y", &Command::inc_x_on_y)
      .def_readonly("inc_y_on_x", &Command::inc_y_on_x)
      .def_readonly("inc_y_on_y", &Command::inc_y_on_y)
      .def_readonly("jv_z", &Command::jv_z)
      .def_readonly("jr_z", &Command::jr_z)
      .def_readonly("cap_z", &Command::cap_z)
      .def_readonly("cnt_z", &Command::cnt_z)
      .def_readonly("dir_z_neg", &Command::dir_z_neg);
  py::class_<Piece>(m, "Piece", "one monotone piece of a path: one hardware command")
      .def_property_readonly("from_", [](const Piece& p) { return point(p.from); })
      .def_property_readonly("to", [](const Piece& p) { return point(p.to); })
      .def_readonly("quadrant", &Piece::quadrant)
      .def_property_readonly("kind", [](const Piece& p) { return p.kind == PieceKind::Line ? "line" : "arc"; })
      .def_readonly("command", &Piece::cmd)
      .def_readonly("iteration_bound", &Piece::iteration_bound)
      .def_readonly("rot", &Piece::rot);
  py::class_<Plan>(m, "Plan", "a validated path: its pieces, back to back")
      .def_property_readonly("from_", [](const Plan& p) { return point(p.from); })
      .def_property_readonly("to", [](const Plan& p) { return point(p.to); })
      .def_readonly("pieces", &Plan::pieces)
      .def_readonly("iteration_bound", &Plan::iteration_bound)
      .def_property_readonly("kind", [](const Plan& p) {
        return p.is_arc() ? "arc" : p.is_line() ? "line" : "program";
      });
  py::class_<RegState>(m, "Registers", "the datapath registers between iterations")
      .def_readonly("jv_x", &RegState::jv_x)
      .def_readonly("jv_y", &RegState::jv_y)
      .def_readonly("jr_x", &RegState::jr_x)
      .def_readonly("jr_y", &RegState::jr_y)
      .def_readonly("cnt_x", &RegState::cnt_x)
      .def_readonly("cnt_y", &RegState::cnt_y)
      .def_readonly("jr_z", &RegState::jr_z)
      .def_readonly("cnt_z", &RegState::cnt_z);
}

void bind_iteration(py::module_& m) {
  py::class_<Iteration>(m, "Iteration", "one iteration of the golden model (a row of `dda trace`)")
      .def_readonly("iter", &Iteration::iter)
      .def_readonly("piece", &Iteration::piece)
      .def_readonly("piece_end", &Iteration::piece_end)
      .def_readonly("dir_x_neg", &Iteration::dir_x_neg)
      .def_readonly("dir_y_neg", &Iteration::dir_y_neg)
      .def_readonly("dir_z_neg", &Iteration::dir_z_neg)
      .def_readonly("active_x", &Iteration::active_x)
      .def_readonly("active_y", &Iteration::active_y)
      .def_readonly("active_z", &Iteration::active_z)
      .def_readonly("jv_x", &Iteration::jv_x)
      .def_readonly("jv_y", &Iteration::jv_y)
      .def_readonly("jv_z", &Iteration::jv_z)
      .def_readonly("sum_x", &Iteration::sum_x)
      .def_readonly("sum_y", &Iteration::sum_y)
      .def_readonly("sum_z", &Iteration::sum_z)
      .def_readonly("step_x", &Iteration::step_x)
      .def_readonly("step_y", &Iteration::step_y)
      .def_readonly("step_z", &Iteration::step_z)
      .def_readonly("after", &Iteration::after)
      .def_property_readonly("pos", [](const Iteration& it) { return point(it.pos); });
}

void bind_move(py::module_& m) {
  using program::Move;
  py::class_<Move>(m, "Move", "a motion block as the reader gives it: lengths in nanometres, (u, v) the plane's axes")
      .def_property_readonly("line", [](const Move& mv) { return mv.pos.line; })
      .def_property_readonly("column", [](const Move& mv) { return mv.pos.column; })
      .def_readonly("n", &Move::block_number)
      .def_property_readonly("kind", [](const Move& mv) { return std::string(program::kind_name(mv.kind)); })
      .def_property_readonly("plane", [](const Move& mv) { return mv.plane / 10; })
      .def_property_readonly("from_", [](const Move& mv) { return py::make_tuple(mv.from.u, mv.from.v, mv.w); })
      .def_property_readonly("to", [](const Move& mv) { return py::make_tuple(mv.to.u, mv.to.v, mv.w_to); })
      .def_property_readonly("center", [](const Move& mv) { return py::make_tuple(mv.center.u, mv.center.v, mv.w); })
      .def_readonly("radius", &Move::radius)
      .def_readonly("full", &Move::full)
      .def_readonly("turns", &Move::turns)
      .def_readonly("a", &Move::a)
      .def_readonly("b", &Move::b)
      .def_readonly("feed", &Move::feed);
}

py::dict edge_dict(const CoreEdge& e) {
  py::dict d;
  d["ready"] = e.ready;
  d["load"] = e.load;
  d["iterate"] = e.iterate;
  d["finishing"] = e.finishing;
  d["stalled"] = e.stalled;
  return d;
}

void bind_core(py::module_& m) {
  py::class_<CoreModel>(m, "CoreModel",
                        "the core's cycle-level reference model: every register of the register table, edge by edge")
      .def(py::init<>())
      .def_property_readonly(
          "state", [](const CoreModel& c) { return signals_dict(c.state()); },
          "every signal of the register table by name (dda.signals), masked to its width")
      .def("cmd_ready", &CoreModel::cmd_ready, py::arg("ce") = true, "cmd_ready_o in the current cycle")
      .def(
          "edge",
          [](CoreModel& c, const Command* cmd, bool ce, bool rst_n) {
            CoreInputs in;
            in.rst_n = rst_n;
            in.ce = ce;
            in.cmd_valid = cmd != nullptr;
            if (cmd) in.cmd = hw::command_fields(*cmd);
            return edge_dict(c.edge(in));
          },
          py::arg("cmd") = nullptr, py::arg("ce") = true, py::arg("rst_n") = true,
          "one rising edge (cmd: the command offered with cmd_valid_i high, None for none); what it did")
      .def(
          "outputs",
          [](const CoreModel& c, bool ce) {
            const PortValues v = CoreModel::outputs(c.state(), c.cmd_ready(ce));
            py::dict d;
            std::size_t i = 0;
            for (const auto& p : hw::kPorts) {
              if (p.dir == hw::PortDir::Out) d[py::str(std::string(p.name))] = v[i++];
            }
            return d;
          },
          py::arg("ce") = true, "the output ports the current state drives");
}

void bind_functions(py::module_& m) {
  m.def(
      "plan", [](const py::kwargs& kw) { return cli::plan_from_args(to_args(kw)); },
      "plan an arc, a line or a part program from the dda command's options by name: "
      "plan(a=10, b=6, bits=4, preload='zero'), plan(line=True, from_=(0, 0), to=(7, 3)), "
      "plan(program='part.ngc', machine='lathe')");
  m.def(
      "run",
      [](const Plan& plan, const std::function<void(const Iteration&)>& on_record) -> py::object {
        if (!on_record) return py::cast(records(plan));
        run(plan, on_record);
        return py::none();
      },
      py::arg("plan"), py::arg("on_record") = nullptr,
      "the plan's iterations on the golden model: a list, or each passed to on_record as it comes");
  m.def(
      "trace",
      [](const Plan& plan, const std::string& format) {
        const TraceFormat f = cli::parse_enum<TraceFormat>(
            "format", format, {{"csv", TraceFormat::Csv}, {"table", TraceFormat::Table}, {"json", TraceFormat::Json}});
        std::ostringstream os;
        TraceSink sink(os, plan, f);
        return report(plan, sink, os);
      },
      py::arg("plan"), py::arg("format") = "csv", "what `dda trace` prints for the plan (an arc or a line)");
  m.def(
      "path",
      [](const Plan& plan) {
        py::list l;
        for (const Point& p : path_points(plan, records(plan))) l.append(point(p));
        return l;
      },
      "the lattice points of the path: the start, then the position after every move");
  m.def(
      "stats",
      [](const Plan& plan) {
        std::ostringstream os;
        StatsSink sink(plan);
        report(plan, sink, os);
        return stats_dict(sink.stats());
      },
      "what `dda stats` counts and measures (an arc or a line)");
  m.def("read_program", &read_moves,
        "the motion blocks of a part program (program='FILE' and the dda command's program options)");
  m.def(
      "entry_words",
      [](const Plan& plan) {
        py::list l;
        for (const live::PieceEntry& p : live::plan_entries(plan)) l.append(piece_entry(p));
        return l;
      },
      py::arg("plan"),
      "each piece's block-entry words (dicts of piece, line, from, to and its 27 words, word 0 first: ENTRY + 4k, "
      "then CTRL.commit), at the core's full rate, as `dda entries` prints them");
  m.def("program_entry_words", &program_entry_words,
        "a part program's pieces' block-entry words at their planned speeds (program='FILE', the program options, "
        "machine_config='FILE', clock=HZ), as `dda entries --program` prints them and `dda run` writes them: a dict "
        "of accel and vmin (ACCEL and VMIN, written before the entries), clock_hz, step_mm and pieces");
  m.def(
      "command_fields",
      [](const Command& c) {
        const CmdFields v = hw::command_fields(c);
        py::dict d;
        for (std::size_t i = 0; i < v.size(); ++i) d[py::str(std::string(hw::kCmdFields[i].name))] = v[i];
        return d;
      },
      "the command word's fields as the hardware takes them (masked; InputError if one does not fit)");
}

}  // namespace
}  // namespace dda::python

PYBIND11_MODULE(dda, m) {
  using namespace dda;
  using namespace dda::python;
  m.doc() = "The ellipse DDA's golden model, planner and program reader (docs/verification.md)";
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<GuardError>(m, "GuardError", PyExc_RuntimeError);
  bind_types(m);
  bind_iteration(m);
  bind_move(m);
  bind_core(m);
  bind_functions(m);
  py::list names;
  for (const auto& s : hw::kSignals) names.append(std::string(s.name));
  m.attr("signals") = names;
  m.attr("acc_width") = hw::kAccWidth;
  m.attr("cnt_width") = hw::kCntWidth;
}
