#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The motion tops' port tables in docs/design.md ("Ports") against the RTL.

  usage: tests/check-ports.py

Each top's ports (rtl/dda_motion.v, rtl/dda_motion_axil.v, rtl/dda_motion_spi.v: name,
direction, width, widths evaluated with rtl/dda_motion_regs.vh's macros) must be exactly
the rows of the table marked `<!-- ports: common -->` and of the one marked with the
top's name: no port missing, none extra, the same direction and width. A row may name
several ports (`a`, `b`) of one direction and width ("1 each", "2 each"). Exit 1 with
every difference listed."""
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TOPS = ("dda_motion", "dda_motion_axil", "dda_motion_spi")


def macros():
    text = (ROOT / "rtl/dda_motion_regs.vh").read_text()
    return {m.group(1): m.group(2) for m in re.finditer(r"^`define\s+(\w+)\s+(\d+)\s*$", text, re.M)}


def rtl_ports(top, defs):
    text = (ROOT / "rtl" / (top + ".v")).read_text()
    head = text[text.index("module " + top):]
    head = head[head.index(") (") + 3:head.index(");")]
    out = {}
    for m in re.finditer(r"\b(input|output|inout)\s+wire\s*(\[[^\]]*\])?\s*(\w+)", head):
        width = 1
        if m.group(2):
            rng = re.sub(r"`(\w+)", lambda d: defs[d.group(1)], m.group(2)[1:-1])
            hi, lo = rng.split(":")
            width = eval(hi, {}) - eval(lo, {}) + 1  # (integer arithmetic of the macros)
        out[m.group(3)] = ({"input": "in", "output": "out", "inout": "inout"}[m.group(1)], width)
    return out


def doc_ports(doc, name):
    marker = "<!-- ports: %s -->" % name
    if marker not in doc:
        return None
    rows = doc[doc.index(marker) + len(marker):].lstrip("\n").split("\n\n", 1)[0].splitlines()[2:]
    out = {}
    for row in rows:
        cells = [c.strip() for c in row.strip().strip("|").split("|")]
        names = re.findall(r"`(\w+)`", cells[0])
        width = int(re.match(r"(\d+)", cells[2]).group(1))
        for n in names:
            out[n] = (cells[1], width)
    return out


def main():
    doc = (ROOT / "docs/design.md").read_text()
    defs = macros()
    errors = []
    common = doc_ports(doc, "common")
    if common is None:
        sys.exit("check-ports: docs/design.md has no table marked <!-- ports: common -->")
    for top in TOPS:
        own = doc_ports(doc, top)
        if own is None:
            errors.append("docs/design.md has no table marked <!-- ports: %s -->" % top)
            continue
        want = dict(common, **own)
        got = rtl_ports(top, defs)
        for n in sorted(set(want) | set(got)):
            if n not in got:
                errors.append("%s: docs/design.md lists %s, the RTL has no such port" % (top, n))
            elif n not in want:
                errors.append("%s: port %s is in no table of docs/design.md" % (top, n))
            elif want[n] != got[n]:
                errors.append("%s: %s is %s %d in docs/design.md, %s %d in the RTL" % (top, n, *want[n], *got[n]))
    for e in errors:
        print("check-ports: " + e)
    if errors:
        sys.exit(1)
    print("check-ports: the ports of %s agree with docs/design.md" % ", ".join(TOPS))


main()
