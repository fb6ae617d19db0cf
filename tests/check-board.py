#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The board top's pins and settings against their documentation (docs/board.md).

  usage: tests/check-board.py BUILD_DIR

Checks that
  - every port of rtl/board/dda_hx8k_evn.v has one set_io line in its pin constraint file
    (rtl/board/dda_hx8k_evn.pcf; a bus a line per bit), and no line names another;
  - the pin table of docs/board.md gives each port bit the same ball and the same pull-up
    as the constraint file, and no ball twice;
  - the top's PLL settings are `icepll -i 12 -o` of its ClockHz, and docs/board.md states
    that clock;
  - the block's parameters in the top are `dda build` of its "Board build:" line;
  - the board bench (tb/hdl/dda_board_tb.v) counts the top's power-on reset (PorBits) and
    reset synchronizer (SyncEdges): it drives the reset pin by them.
Exit 1 with every difference listed."""
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TOP = ROOT / "rtl/board/dda_hx8k_evn.v"
PCF = ROOT / "rtl/board/dda_hx8k_evn.pcf"
DOC = ROOT / "docs/board.md"


def ports(text):
    """The top's ports as {name: (width, direction)}."""
    head = text[text.index("module dda_hx8k_evn"):text.index(");", text.index(") (")) + 2]
    out = {}
    for m in re.finditer(r"\b(input|output|inout)\s+wire\s*(\[(\d+):0\])?\s*(\w+)", head):
        out[m.group(4)] = (int(m.group(3)) + 1 if m.group(3) else 1, m.group(1))
    return out


def bits(name, width):
    return [name] if width == 1 else ["%s[%d]" % (name, i) for i in range(width)]


def pcf_pins(text, errors):
    """{port bit: (ball, pulled up)} from the set_io lines (a port given twice: an error)."""
    pins = {}
    for line in text.splitlines():
        line = line.split("#")[0].split()
        if not line or line[0] != "set_io":
            continue
        pull = "-pullup" in line and line[line.index("-pullup") + 1] == "yes"
        rest = [w for i, w in enumerate(line[1:], 1) if not w.startswith("-") and line[i - 1] != "-pullup"]
        if rest[0] in pins:
            errors.append("%s: two set_io lines" % rest[0])
        pins[rest[0]] = (rest[1], pull)
    return pins


def doc_pins(text, errors):
    """{port bit: (ball, pulled up, header pin, direction)} from the table of
    docs/board.md whose header is | port | ball | header pin | direction | pull-up | ...
    (a port in two rows: an error)"""
    pins, on = {}, False
    for line in text.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")] if line.startswith("|") else None
        if cells and cells[:5] == ["port", "ball", "header pin", "direction", "pull-up"]:
            on = True
            continue
        if not on:
            continue
        if not cells:
            on = False
            continue
        if set(cells[0]) <= set("-: "):
            continue
        name = cells[0].strip("`")
        if name in pins:
            errors.append("%s: two rows in the pin table of docs/board.md" % name)
        pins[name] = (cells[1], cells[4] == "yes", cells[2], cells[3])
    return pins


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    build = Path(sys.argv[1])
    errors = []
    top = TOP.read_text()
    port_dirs = {b: d for n, (w, d) in ports(top).items() for b in bits(n, w)}
    want = list(port_dirs)
    pcf = pcf_pins(PCF.read_text(), errors)
    doc_text = DOC.read_text()
    doc = doc_pins(doc_text, errors)
    # The direction column: "in", or "out" (an inout of the top is an output with an enable).
    for b, d in port_dirs.items():
        if b in doc and doc[b][3].split()[0] != ("in" if d == "input" else "out"):
            errors.append("%s: docs/board.md says '%s', the top has an %s" % (b, doc[b][3], d))
    for b in want:
        if b not in pcf:
            errors.append("%s: no set_io line in %s" % (b, PCF.name))
        if b not in doc:
            errors.append("%s: not in the pin table of docs/board.md" % b)
    for b in pcf:
        if b not in want:
            errors.append("%s: a set_io line for no port of the top" % b)
    for b in doc:
        if b not in want:
            errors.append("%s: in the pin table of docs/board.md, not a port of the top" % b)
    for b in set(pcf) & set(doc):
        if pcf[b] != doc[b][:2]:
            errors.append("%s: %s has ball %s%s, docs/board.md %s%s" % (
                b, PCF.name, pcf[b][0], " pulled up" if pcf[b][1] else "", doc[b][0],
                " pulled up" if doc[b][1] else ""))
    balls = [v[0] for v in pcf.values()]
    for ball in sorted(set(balls)):
        if balls.count(ball) > 1:
            errors.append("ball %s set twice in %s" % (ball, PCF.name))
    headers = [v[2] for v in doc.values() if v[2] not in ("", "-", "—")]
    for h in sorted(set(headers)):
        if headers.count(h) > 1:
            errors.append("header pin %s twice in docs/board.md" % h)

    # The clock: the PLL's settings are icepll's for ClockHz, and the docs state it.
    def param(name):
        m = re.search(r"parameter\s+(?:integer|\[\d+:0\])\s+%s\s*=\s*(?:\d+'d)?([0-9_]+)" % name, top)
        return int(m.group(1).replace("_", "")) if m else None
    hz = param("ClockHz")
    mhz = hz / 1e6
    try:
        out = subprocess.run(["icepll", "-i", "12", "-o", "%g" % mhz], capture_output=True, text=True).stdout
    except FileNotFoundError:
        sys.exit("check-board: icepll not found (scripts/setup.sh installs IceStorm)")
    got = {k: int(re.search(k + r":\s+(\d+)", out).group(1)) for k in ("DIVR", "DIVF", "DIVQ", "FILTER_RANGE")}
    if "%.3f MHz (achieved)" % mhz not in out:
        errors.append("icepll does not reach %g MHz exactly from 12 MHz" % mhz)
    for k, p in (("DIVR", "PllDivr"), ("DIVF", "PllDivf"), ("DIVQ", "PllDivq"), ("FILTER_RANGE", "PllFilter")):
        if param(p) != got[k]:
            errors.append("%s is %s, icepll -i 12 -o %g gives %s %d" % (p, param(p), mhz, k, got[k]))
    if "**%g MHz**" % mhz not in doc_text or "icepll -i 12 -o %g" % mhz not in doc_text:
        errors.append("docs/board.md does not state the board's clock, **%g MHz** (icepll -i 12 -o %g)" % (mhz, mhz))

    # The board's build: the instance's parameters are dda build's.
    spec = re.search(r"^// Board build: *(\S+)", top, re.M).group(1)
    dda = build / "bin/dda"
    def build_params(s):
        if not dda.exists():
            sys.exit("check-board: %s not built" % dda)
        run = subprocess.run([str(dda), "build", s], capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit("check-board: dda build '%s': %s" % (s, run.stderr.strip()))
        return dict(line.split() for line in run.stdout.splitlines())
    params, defaults = build_params(spec), build_params("")
    inst = top[top.index("dda_motion_spi #("):top.index(") u_block")]
    given = dict(re.findall(r"\.(\w+)\s*\((\d+)\)", inst))
    for k, v in params.items():
        if k not in given and defaults[k] == v:
            continue  # (a parameter the top leaves at the block's default)
        if given.get(k) != v:
            errors.append("the block's %s in the top is %s, `dda build %s` gives %s" % (k, given.get(k), spec, v))
    for k in given:
        if k not in params:
            errors.append("the top sets %s, which is no build parameter" % k)

    # The bench's reset timing: the top's power-on count and synchronizer depth.
    bench = (ROOT / "tb/hdl/dda_board_tb.v").read_text()
    for name in ("PorBits", "SyncEdges"):
        m_top = re.search(r"(?:parameter|localparam)\s+integer\s+%s\s*=\s*(\d+)" % name, top)
        m_tb = re.search(r"localparam\s+integer\s+%s\s*=\s*(\d+)" % name, bench)
        if not m_top or not m_tb:
            errors.append("%s not found in %s" % (name, TOP.name if not m_top else "tb/hdl/dda_board_tb.v"))
        elif m_top.group(1) != m_tb.group(1):
            errors.append("tb/hdl/dda_board_tb.v's %s is %s, the top's %s" % (name, m_tb.group(1), m_top.group(1)))

    for e in errors:
        print("check-board: " + e)
    if errors:
        sys.exit(1)
    print("check-board: %d pins in %s and docs/board.md agree; PLL %g MHz; build %s" % (len(want), PCF.name, mhz, spec))


main()
