#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Single-LUT mutants of a Yosys iCE40 netlist (write_verilog -noattr after synth_ice40),
for scripts/netlist-sim.sh: a copy of the netlist with one SB_LUT4's LUT_INIT changed in
one bit, so that a simulation against the golden vectors shows whether it can fail.

  usage: netlist_mutants.py NETLIST OUT --drives NET [--bit K]
         netlist_mutants.py NETLIST OUT --random SEED
         netlist_mutants.py NETLIST OUT --routed-drives PORT
--drives NET changes the LUT whose output is NET (a port such as step_x_o), or, when a
flip-flop's Q is NET (a register such as dat_q[0]), the LUT at that flip-flop's D;
--bit K flips bit K of its init, --bit all every bit (the LUT's output inverted, for
any input; the default). --random picks a LUT and one bit from SEED. Prints the LUT's instance name, the bit and the inits.
--routed-drives PORT works on icebox_vlog's netlist of a routed bitstream, where a LUT is
`assign nK = /* LUT x y z */ EXPR;`: it inverts the LUT whose net the port is assigned
from (`assign PORT = nK;`) and prints the LUT's place.
"""
import random
import re
import sys

LUT = re.compile(r"SB_LUT4 #\(\s*\.LUT_INIT\(16'h([0-9a-fA-F]{4})\)\s*\)\s*(\S+)\s*\((.*?)\);", re.S)


def port(body, name):
    m = re.search(r"\." + name + r"\(([^()]*)\)", body)
    return m.group(1).strip() if m else None


def routed(text, out, port_name):
    m = re.search(r"assign\s+" + re.escape(port_name) + r"\s*=\s*(n\d+)\s*;", text)
    if m is None:
        sys.exit("netlist_mutants: the routed netlist assigns no net to " + port_name)
    lut = re.search(r"(assign\s+" + m.group(1) + r"\s*=\s*/\* LUT ([^*]*)\*/\s*)(.*?);", text)
    if lut is None:
        sys.exit("netlist_mutants: no LUT drives %s (%s)" % (port_name, m.group(1)))
    open(out, "w").write(text[:lut.start(3)] + "!(" + lut.group(3) + ")" + text[lut.end(3):])
    print("LUT %s(%s) inverted" % (m.group(1), lut.group(2).strip()))


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    src, out, mode = argv[1], argv[2], argv[3]
    text = open(src).read()
    if mode == "--routed-drives":
        return routed(text, out, argv[4])
    luts = list(LUT.finditer(text))
    if not luts:
        sys.exit("netlist_mutants: no SB_LUT4 in " + src)
    bit = "all"
    if mode == "--drives":
        net = argv[4]
        if "--bit" in argv:
            bit = argv[argv.index("--bit") + 1]
            bit = bit if bit == "all" else int(bit)
        target = next((m for m in luts if port(m.group(3), "O") == net), None)
        if target is None:  # a register: the LUT at its flip-flop's D
            ff = re.search(r"SB_DFF\w*\s+\S+\s*\(((?:(?!\);).)*?\.Q\(" + re.escape(net) + r"\).*?)\);", text, re.S)
            if ff is None:
                sys.exit("netlist_mutants: no LUT or flip-flop drives " + net)
            d = port(ff.group(1), "D")
            target = next((m for m in luts if port(m.group(3), "O") == d), None)
            if target is None:
                sys.exit("netlist_mutants: the flip-flop of %s takes %s, which no LUT drives" % (net, d))
    elif mode == "--random":
        rng = random.Random(int(argv[4]))
        target = luts[rng.randrange(len(luts))]
        bit = rng.randrange(16)
    else:
        sys.exit(__doc__)
    old = int(target.group(1), 16)
    new = old ^ (0xFFFF if bit == "all" else 1 << bit)
    start, end = target.span(1)
    open(out, "w").write(text[:start] + "%04x" % new + text[end:])
    print("%s bit %s: 16'h%04x -> 16'h%04x" % (target.group(2), bit, old, new))


if __name__ == "__main__":
    main(sys.argv)
