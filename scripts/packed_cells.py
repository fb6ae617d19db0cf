#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# What the logic cells of a design packed by nextpnr-ice40 (--pack-only --write FILE)
# hold: an iCE40 logic cell has one LUT4, one flip-flop and one carry, and a flip-flop
# whose input is not a LUT4 of its own (a register loaded from a bus, a RAM or another
# register, or from a LUT4 whose output is also used elsewhere) takes a cell of its
# own with a pass-through LUT4. Used by scripts/area-budget.sh.
#   usage: scripts/packed_cells.py PACKED.json [--alone N]
#   prints: "cells N lut_ff N lut N ff_alone N carry_alone N other N" (other: a cell with
#   none of the three, a constant) and, with --alone N, the N
#   registers with the most flip-flops packed alone ("count name" lines).
import argparse
import collections
import json
import re
import sys


def bit(params, name):
    v = str(params.get(name, "0"))
    return int(v, 2) if set(v) <= {"0", "1"} else int(v)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("packed")
    ap.add_argument("--alone", type=int, default=0)
    args = ap.parse_args()
    with open(args.packed) as f:
        design = json.load(f)
    modules = list(design["modules"].values())
    if len(modules) != 1:
        sys.exit("packed_cells: expected one (flattened) module")
    top = modules[0]
    # The shortest name of each net (a register's own name before the names Yosys
    # derives from it).
    names = {}
    for name, net in top["netnames"].items():
        for b in net["bits"]:
            if isinstance(b, int) and (b not in names or len(name) < len(names[b])):
                names[b] = name
    kinds = collections.Counter()
    alone = collections.Counter()
    for cell in top["cells"].values():
        if cell["type"] != "ICESTORM_LC":
            continue
        p = cell["parameters"]
        ff, carry, lut = bit(p, "DFF_ENABLE"), bit(p, "CARRY_ENABLE"), int(str(p["LUT_INIT"]), 2)
        kinds["cells"] += 1
        if ff and lut == 2:  # nextpnr's pass-through LUT4 (output = input 0)
            kinds["ff_alone"] += 1
            out = cell["connections"]["O"][0]
            alone[re.sub(r"\[\d+\]$", "", names.get(out, "?"))] += 1
        elif lut != 0:
            kinds["lut_ff" if ff else "lut"] += 1
        elif carry:
            kinds["carry_alone"] += 1
        else:
            kinds["other"] += 1
    print(" ".join(f"{k} {kinds[k]}" for k in ("cells", "lut_ff", "lut", "ff_alone", "carry_alone", "other")))
    for name, n in alone.most_common(args.alone):
        print(n, name)


if __name__ == "__main__":
    main()
