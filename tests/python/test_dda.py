# SPDX-License-Identifier: Apache-2.0
"""The Python module (`import dda`) against the `dda` command's output.

The module and the command share the golden model; what these tests check is that the
binding hands Python the same plans, records, paths, blocks and refusals as the
command prints, read back from the command's own formats (JSON and CSV), and that the
cycle-level reference model driven from Python makes the golden model's iterations.
Run by ctest (label python) with PYTHONPATH=build/python and DDA_BIN=build/bin/dda.
"""
import csv
import io
import json
import os
import subprocess
from pathlib import Path

import pytest

import dda

DDA_BIN = os.environ.get("DDA_BIN", "build/bin/dda")
SOURCE = Path(__file__).resolve().parents[2]

PAPER = {"a": 10, "b": 6, "bits": 4, "preload": "zero"}
LATHE = {"a": 25000, "b": 15000, "angle": 330, "center": (-30000, 5000), "from_theta": 60, "to_theta": 136}
# Option sets as a user gives them to both: the keyword's name is the option's.
ARCS = [
    PAPER,
    {"a": 10, "b": 6},
    {"a": 7, "b": 300, "dir": "cw", "from_": (0, -300), "to": (7, 0)},
    {"a": 40, "b": 25, "angle": "12.5", "from_theta": 0, "to_theta": 360},
    {"line": True, "from_": (0, 0), "to": (17, -5)},
]


def args_of(opts):
    """The command's arguments for a keyword set (the rule dda.plan follows)."""
    out = []
    for key, value in opts.items():
        name = "--" + key.rstrip("_").replace("_", "-")
        if value is True:
            out.append(name)
        elif isinstance(value, tuple):
            out += [name, ",".join(str(v) for v in value)]
        else:
            out += [name, str(value)]
    return out


def command(*args):
    done = subprocess.run([DDA_BIN, *args], capture_output=True, text=True, check=False)
    return done.returncode, done.stdout, done.stderr


def stdout(*args):
    rc, out, err = command(*args)
    assert rc == 0, err
    return out


@pytest.mark.parametrize("opts", ARCS, ids=lambda o: " ".join(args_of(o)))
def test_trace_is_what_the_command_prints(opts):
    plan = dda.plan(**opts)
    for fmt in ("csv", "table"):
        assert dda.trace(plan, fmt) == stdout("trace", *args_of(opts), "--format", fmt)


@pytest.mark.parametrize("opts", [PAPER, ARCS[2], ARCS[3]], ids=["paper", "cw", "rotated"])
def test_records_are_the_commands_json_records(opts):
    printed = json.loads(stdout("trace", *args_of(opts), "--format", "json"))
    plan = dda.plan(**opts)
    records = dda.run(plan)
    assert len(records) == len(printed["iterations"]) > 0
    for r, j in zip(records, printed["iterations"]):
        assert (r.iter, r.piece) == (j["iter"], j["seg"])
        assert (r.active_x, r.active_y, r.step_x, r.step_y) == (j["active_x"], j["active_y"], j["step_x"], j["step_y"])
        assert (r.jv_x, r.jv_y, r.sum_x, r.sum_y) == (j["jv_x"], j["jv_y"], j["sum_x"], j["sum_y"])
        assert (r.after.jr_x, r.after.jr_y, r.after.cnt_x, r.after.cnt_y) == (j["jr_x"], j["jr_y"], j["cnt_x"], j["cnt_y"])
        assert (r.after.jv_x, r.after.jv_y) == (j["jv_x_next"], j["jv_y_next"])
        assert (("-" if r.dir_x_neg else "+"), ("-" if r.dir_y_neg else "+")) == (j["dir_x"], j["dir_y"])
        assert r.pos[:2] == (j["x"], j["y"])
    for piece, seg in zip(plan.pieces, printed["segments"]):
        c = piece.command
        assert piece.from_[:2] == tuple(seg["from"]) and piece.to[:2] == tuple(seg["to"])
        assert (c.jv_x, c.jv_y, c.jr_x, c.jr_y, c.cap, c.cnt_x, c.cnt_y) == tuple(
            seg[k] for k in ("jv_x", "jv_y", "jr_x", "jr_y", "cap", "cnt_x", "cnt_y"))
        assert (c.inc_x_on_x, c.inc_x_on_y, c.inc_y_on_x, c.inc_y_on_y) == tuple(
            seg[k] for k in ("inc_x_on_x", "inc_x_on_y", "inc_y_on_x", "inc_y_on_y"))


@pytest.mark.parametrize("opts", [LATHE, ARCS[4]], ids=["lathe", "line"])
def test_path_and_stats_are_the_commands(opts):
    plan = dda.plan(**opts)
    rows = list(csv.DictReader(io.StringIO(stdout("path", *args_of(opts), "--format", "csv"))))
    assert [p[:2] for p in dda.path(plan)] == [(int(r["x"]), int(r["y"])) for r in rows]
    printed = json.loads(stdout("stats", *args_of(opts), "--format", "json"))
    stats = dda.stats(plan)
    for key in ("iterations", "moves", "pulses_x", "pulses_y", "points"):
        assert stats[key] == printed[key], key
    assert stats["max_dev"] == pytest.approx(printed["max_dev"], rel=1e-12)
    assert list(stats["max_dev_at"][:2]) == printed["max_dev_at"]


def test_a_programs_run_follows_the_commands_path():
    program = str(SOURCE / "examples" / "circles.ngc")
    plan = dda.plan(program=program)
    assert plan.kind == "program"
    rows = list(csv.DictReader(io.StringIO(stdout("path", "--program", program, "--format", "csv"))))
    points = [plan.from_[:2]]
    dda.run(plan, lambda r: points.append(r.pos[:2]) if r.step_x or r.step_y else None)
    assert points == [(int(r["x"]), int(r["y"])) for r in rows]


def machine_xyz(plane, u, v, w):
    """A point of a move's plane (u, v) and its normal w as machine X, Y, Z."""
    return {17: (u, v, w), 18: (v, w, u), 19: (w, u, v)}[plane]


@pytest.mark.parametrize("name", ["planes.ngc", "lathe-paper-native.ngc"])
def test_read_program_gives_the_commands_blocks(name):
    program = str(SOURCE / "examples" / name)
    machine = "lathe" if "lathe" in name else "mill"
    moves = dda.read_program(program=program, machine=machine)
    printed = [json.loads(line) for line in stdout("blocks", "--program", program, "--machine", machine,
                                                   "--format", "json").splitlines()]
    assert printed[-1]["end"] and printed[-1]["blocks"] == len(moves) > 0
    for mv, j in zip(moves, printed):
        assert (mv.line, mv.n, mv.kind, mv.plane) == (j["line"], j["n"], j["kind"], j["plane"])
        assert [c / 1e6 for c in machine_xyz(mv.plane, *mv.to)] == pytest.approx(j["to"], abs=1e-9)
        assert [c / 1e6 for c in machine_xyz(mv.plane, *mv.from_)] == pytest.approx(j["from"], abs=1e-9)


def test_the_core_model_makes_the_golden_iterations():
    """The cycle-level model driven edge by edge from Python: one load edge, then one
    iteration per edge, each equal to the golden model's record."""
    plan = dda.plan(**PAPER)
    records = dda.run(plan)
    core = dda.CoreModel()
    core.edge(rst_n=False)
    assert all(v == 0 for v in core.state.values())
    assert core.cmd_ready() and core.outputs()["busy_o"] == 0
    assert core.edge(cmd=plan.pieces[0].command)["load"]
    state = core.state
    assert (state["u_int_x.jv_q"], state["u_int_y.jv_q"]) == (0, 360)
    for r in records:
        did = core.edge()
        assert did["iterate"]
        out = core.outputs()
        state = core.state
        assert (out["step_x_o"], out["step_y_o"]) == (r.step_x, r.step_y)
        assert (state["u_int_x.jr_q"], state["u_int_y.jr_q"]) == (r.after.jr_x, r.after.jr_y)
        assert (state["u_cnt_x.cnt_q"], state["u_cnt_y.cnt_q"]) == (r.after.cnt_x, r.after.cnt_y)
        assert did["finishing"] == r.piece_end
    assert core.outputs()["done_o"] == 1 and core.outputs()["busy_o"] == 0


def test_command_fields_are_the_hardware_fields():
    c = dda.plan(**PAPER).pieces[0].command
    fields = dda.command_fields(c)
    assert (fields["jv_y"], fields["cap"], fields["cnt_x"], fields["cnt_y"]) == (360, 960, 10, 6)
    assert fields["inc_y_on_x"] == (1 << dda.acc_width) - 36  # two's complement at the width


@pytest.mark.parametrize("opts", [
    {"a": 0, "b": 6},
    {"a": 10, "b": 6, "bits": 2},
    {"a": 10, "b": 6, "preload": "full"},
    {"a": 10, "b": 6, "from_": "10"},
    {"a": 10, "b": 6, "frm": (1, 2)},
    {"program": "/nonexistent/part.ngc"},
])
def test_a_refusal_is_the_commands_message(opts):
    rc, _, err = command("trace", *args_of(opts))
    assert rc == 2
    with pytest.raises(dda.InputError) as refused:
        dda.plan(**opts)
    assert isinstance(refused.value, ValueError)
    assert str(refused.value) in err.strip()
    assert len(str(refused.value)) > 10


@pytest.mark.parametrize("opts", ARCS)
def test_entry_words_are_the_commands(opts):
    """Each piece's entry words, as `dda entries --format json` prints them; their command
    bits are the command word the hardware takes (dda.command_fields' packing)."""
    plan = dda.plan(**opts)
    got = dda.entry_words(plan)
    printed = json.loads(subprocess.run([DDA_BIN, "entries", *args_of(opts), "--format", "json"], check=True,
                                        capture_output=True, text=True).stdout)
    assert printed["accel"] is None
    assert got == [{**p, "from": tuple(p["from"]), "to": tuple(p["to"])} for p in printed["pieces"]]
    assert len(got) == len(plan.pieces)
    for entry, piece in zip(got, plan.pieces):
        assert len(entry["words"]) == 27
        assert entry["from"] == piece.from_ and entry["to"] == piece.to
        assert entry["words"][22:] == [0, 0, 0, 0, 0]  # no pacing: the core's full rate


def test_program_entry_words_are_the_commands():
    """A program's entries at its planned speeds: the module's and the command's agree."""
    prog = str(SOURCE / "examples" / "lines.ngc")
    config = str(SOURCE / "examples" / "machine-sim.json")
    got = dda.program_entry_words(program=prog, machine_config=config)
    printed = json.loads(subprocess.run([DDA_BIN, "entries", "--program", prog, "--machine-config", config,
                                         "--format", "json"], check=True, capture_output=True, text=True).stdout)
    assert got["pieces"] == [{**p, "from": tuple(p["from"]), "to": tuple(p["to"])} for p in printed["pieces"]]
    assert (got["accel"], got["vmin"], got["clock_hz"]) == (printed["accel"], printed["vmin"], printed["clock_hz"])
    assert got["clock_hz"] == 500000 and got["accel"] > 0 and got["vmin"] > 0
    assert [e["line"] for e in got["pieces"]] == [7, 8, 9, 10, 11, 12, 13]
    assert all(e["words"][22] > 0 for e in got["pieces"])  # a cruise speed: paced
    with pytest.raises(dda.InputError):
        dda.program_entry_words(program=prog, machine_config=config, clock=-1)
