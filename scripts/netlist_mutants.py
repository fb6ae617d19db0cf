#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Single-LUT mutants of a Yosys iCE40 netlist (write_verilog -noattr after synth_ice40),
for scripts/netlist-sim.sh and scripts/board-sim.sh: a copy of the netlist with one
SB_LUT4's LUT_INIT changed, so that a simulation against the golden vectors shows whether
it can fail; and the LUT coverage of a run (tb/hdl/sb_lut4_cov.v).

  usage: netlist_mutants.py NETLIST OUT --drives NET [--bit K]
         netlist_mutants.py NETLIST OUT --random SEED [--kind init|bit] [--coverage FILE]
         netlist_mutants.py NETLIST OUT --routed-drives PORT
         netlist_mutants.py NETLIST --coverage-report FILE
--drives NET changes the LUT whose output is NET (a port such as step_x_o), or, when a
flip-flop's Q is NET (a register such as dat_q[0]), the LUT at that flip-flop's D;
--bit K flips bit K of its init, --bit all every bit (the LUT's output inverted, for
any input; the default).

--random picks a LUT from SEED and changes its function. A LUT's live combinations are
those of its 16 that can occur: an input tied to a constant, or one net on two inputs,
leaves the others unreachable, and a change there is no change of the netlist (an
equivalent mutant, which no comparison can see): they are never drawn. --kind init (the
default) replaces the init by a random one that differs on at least one live
combination; --kind bit flips the init at one live combination. Prints the LUT's
instance name, the inits and how many live combinations changed; with --coverage (the
file --coverage-report reads), also how many of those the run reached.

--routed-drives PORT works on icebox_vlog's netlist of a routed bitstream, where a LUT is
`assign nK = /* LUT x y z */ EXPR;`: it inverts the LUT whose net the port is assigned
from (`assign PORT = nK;`) and prints the LUT's place.

--coverage-report FILE: FILE holds the lines "LUTCOV INSTANCE MASK" of runs of the
netlist with tb/hdl/sb_lut4_cov.v (each run's lines; a mask's bit k set when the LUT's
inputs were combination k at a clock edge). Prints how many of the netlist's live
combinations the runs reached, in all and per unit of the design.
"""
import random
import re
import sys

LUT = re.compile(r"SB_LUT4 #\(\s*\.LUT_INIT\(16'h([0-9a-fA-F]{4})\)\s*\)\s*(\S+)\s*\((.*?)\);", re.S)
CONST = {"1'h0": 0, "1'b0": 0, "1'h1": 1, "1'b1": 1}


def port(body, name):
    m = re.search(r"\." + name + r"\(([^()]*)\)", body)
    return m.group(1).strip() if m else None


def live(body):
    """The LUT's live combinations: those its inputs' connections let occur (an
    unconnected input is 0)."""
    nets = [port(body, "I%d" % i) or "1'h0" for i in range(4)]
    out = []
    for k in range(16):
        value = {}
        ok = True
        for i, net in enumerate(nets):
            bit = (k >> i) & 1
            if net in CONST:
                ok = ok and CONST[net] == bit
            elif value.setdefault(net, bit) != bit:
                ok = False
        if ok:
            out.append(k)
    return out


def instance(m):
    return m.group(2).lstrip("\\")


def read_coverage(path):
    """{instance: mask} of every run in the file, ORed."""
    seen = {}
    for line in open(path):
        f = line.split()
        if len(f) == 3 and f[0] == "LUTCOV":
            name = f[1].split(".", 2)[2] if f[1].count(".") >= 2 else f[1]  # (less the bench and the top)
            seen[name] = seen.get(name, 0) | int(f[2], 16)
    if not seen:
        sys.exit("netlist_mutants: no LUTCOV line in " + path)
    return seen


def coverage_report(luts, path):
    seen = read_coverage(path)
    names = {instance(m) for m in luts}
    missing = [n for n in seen if n not in names]
    if missing:
        sys.exit("netlist_mutants: %s has %d LUTs the netlist does not (%s, ...): another netlist's run?"
                 % (path, len(missing), missing[0]))
    units = {}
    total = [0, 0, 0]
    for m in luts:
        name = instance(m)
        cells = live(m.group(3))
        reached = sum(1 for k in cells if seen.get(name, 0) >> k & 1)
        parts = name.split("_SB_")[0].split(".")
        unit = ".".join(parts[:3]) if len(parts) > 3 else ".".join(parts[:-1]) or "(top)"
        u = units.setdefault(unit, [0, 0, 0])
        for t in (u, total):
            t[0] += 1
            t[1] += len(cells)
            t[2] += reached
    print("LUT coverage: %d LUTs, %d live combinations, %d reached (%.1f%%); "
          "%d LUTs never left one combination" % (total[0], total[1], total[2], 100.0 * total[2] / total[1],
                                                  sum(1 for m in luts if bin(seen.get(instance(m), 0)).count("1") <= 1)))
    print("%-40s %6s %8s %8s" % ("unit", "LUTs", "live", "reached"))
    for unit, (n, cells, reached) in sorted(units.items(), key=lambda kv: -kv[1][1]):
        if cells >= 100:
            print("%-40s %6d %8d %7.1f%%" % (unit, n, cells, 100.0 * reached / cells))
    print("(units of fewer than 100 live combinations left out)")


def main(argv):
    if len(argv) >= 4 and argv[2] == "--coverage-report":
        text = open(argv[1]).read()
        return coverage_report(list(LUT.finditer(text)), argv[3])
    if len(argv) < 4:
        sys.exit(__doc__)
    src, out, mode = argv[1], argv[2], argv[3]
    text = open(src).read()
    if mode == "--routed-drives":
        return routed(text, out, argv[4])
    luts = list(LUT.finditer(text))
    if not luts:
        sys.exit("netlist_mutants: no SB_LUT4 in " + src)
    opt = dict(zip(argv[5::2], argv[6::2]))
    if mode == "--drives":
        target = by_net(text, luts, argv[4])
        bit = opt.get("--bit", "all")
        old = int(target.group(1), 16)
        new = old ^ (0xFFFF if bit == "all" else 1 << int(bit))
        write(text, target, new, out)
        print("%s bit %s: 16'h%04x -> 16'h%04x" % (instance(target), bit, old, new))
        return
    if mode != "--random":
        sys.exit(__doc__)
    kind = opt.get("--kind", "init")
    if kind not in ("init", "bit"):
        sys.exit("netlist_mutants: --kind is init or bit, not " + kind)
    rng = random.Random(int(argv[4]))
    target = luts[rng.randrange(len(luts))]
    cells = live(target.group(3))
    old = int(target.group(1), 16)
    if kind == "bit":
        new = old ^ (1 << rng.choice(cells))
    else:
        new = old
        while all((new >> k & 1) == (old >> k & 1) for k in cells):
            new = rng.randrange(1 << 16)
    changed = [k for k in cells if (new ^ old) >> k & 1]
    write(text, target, new, out)
    note = ""
    if "--coverage" in opt:
        mask = read_coverage(opt["--coverage"]).get(instance(target), 0)
        note = ", %d reached by the sets" % sum(1 for k in changed if mask >> k & 1)
    print("%s: 16'h%04x -> 16'h%04x (%d of %d live combinations changed%s)"
          % (instance(target), old, new, len(changed), len(cells), note))


def by_net(text, luts, net):
    target = next((m for m in luts if port(m.group(3), "O") == net), None)
    if target is not None:
        return target
    # a register: the LUT at its flip-flop's D
    ff = re.search(r"SB_DFF\w*\s+\S+\s*\(((?:(?!\);).)*?\.Q\(" + re.escape(net) + r"\).*?)\);", text, re.S)
    if ff is None:
        sys.exit("netlist_mutants: no LUT or flip-flop drives " + net)
    d = port(ff.group(1), "D")
    target = next((m for m in luts if port(m.group(3), "O") == d), None)
    if target is None:
        sys.exit("netlist_mutants: the flip-flop of %s takes %s, which no LUT drives" % (net, d))
    return target


def write(text, target, new, out):
    start, end = target.span(1)
    open(out, "w").write(text[:start] + "%04x" % new + text[end:])


def routed(text, out, port_name):
    m = re.search(r"assign\s+" + re.escape(port_name) + r"\s*=\s*(n\d+)\s*;", text)
    if m is None:
        sys.exit("netlist_mutants: the routed netlist assigns no net to " + port_name)
    lut = re.search(r"(assign\s+" + m.group(1) + r"\s*=\s*/\* LUT ([^*]*)\*/\s*)(.*?);", text)
    if lut is None:
        sys.exit("netlist_mutants: no LUT drives %s (%s)" % (port_name, m.group(1)))
    open(out, "w").write(text[:lut.start(3)] + "!(" + lut.group(3) + ")" + text[lut.end(3):])
    print("LUT %s(%s) inverted" % (m.group(1), lut.group(2).strip()))


if __name__ == "__main__":
    main(sys.argv)
