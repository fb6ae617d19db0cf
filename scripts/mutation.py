#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Mutation testing of rtl/: how many injected faults the project's vector sets catch.

  scripts/mutation.py [--count 100] [--seed 1] [--timeout 120] [--jobs N] [--build build]
                     [--files FILE...] [--check-sets]

Draws COUNT mutants (seeded) from every site of the mutation operators below in the
simulated sources of rtl/ (the file lists dda_core.f, dda_motion.f, dda_motion_axil.f,
dda_motion_spi.f; the place-and-route wrappers of rtl/fpga/ are not simulated by any
bench and are not drawn), each one operator applied at one place of a copy of rtl/.
A mutant that does not compile is stillborn and replaced by the next draw. Each mutant
runs the golden vector sets of the tops that include its file (tb/hdl benches on Icarus,
every output and register every cycle, the RTL's assertions on; written by the ctest
fixtures vectors.gen_* and vectors.bus.gen_*, which this script runs first), fastest
first, under a time bound per set; it is killed by the first set that fails or runs out
of time. The report gives the kill rate per module and lists the survivors; survivors
triaged in tests/mutation-triage.json (each with its reason) as equivalent leave the
count, the rate being over the non-equivalent ones. Exit status 1 when a survivor is not
triaged or the rate is below --floor (default 95). Every bus vector set ctest registers
must be run by a top (SETS) or left out with its reason (LEFT_OUT): the script checks
that first, and --check-sets checks only that (ctest tests.mutation_sets).
"""
import argparse
import concurrent.futures
import json
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
RTL = ROOT / "rtl"
# (name, pattern of the token, replacement). Patterns keep the syntax: a token is
# replaced by one of the same kind.
OPERATORS = [
    ("eq-to-ne", r"==", "!="),
    ("ne-to-eq", r"!=", "=="),
    ("land-to-lor", r"&&", "||"),
    ("lor-to-land", r"\|\|", "&&"),
    ("and-to-or", r"(?<=[\w\)\]] )&(?= [\w\(~!{])", "|"),
    ("or-to-and", r"(?<=[\w\)\]] )\|(?= [\w\(~!{])", "&"),
    ("xor-to-or", r"(?<=[\w\)\]] )\^(?= [\w\(~!{])", "|"),
    ("not-dropped", r"~(?=[\w\(])", ""),
    ("lnot-dropped", r"!(?=[\w\(])", ""),
    ("ge-to-gt", r"(?<=\s)>=(?=\s)", ">"),
    ("gt-to-ge", r"(?<=\s)>(?=\s)", ">="),
    ("lt-to-le", r"(?<=\s)<(?=\s)", "<="),
    ("plus-to-minus", r"(?<=[\w\)\]] )\+(?= [\w\(])", "-"),
    ("minus-to-plus", r"(?<=[\w\)\]] )-(?= [\w\(])", "+"),
    ("zero-to-one", r"1'b0", "1'b1"),
    ("one-to-zero", r"1'b1", "1'b0"),
]
# Lines that declare rather than compute, and what the simulators do not synthesize.
DECLARATION = re.compile(r"^\s*(input|output|inout|parameter|localparam|module|`|//|\)|\(|reg\b|integer\b)")


def file_list(name):
    out, lines = [], (RTL / name).read_text().splitlines()
    for line in lines:
        line = line.split("//")[0].strip()
        if not line or line.startswith("+incdir"):
            continue
        if line.startswith("-f"):
            out += file_list(Path(line.split()[1]).name)
        else:
            out.append(Path(line).name)
    return out


TOPS = {"core": file_list("dda_core.f"), "motion": file_list("dda_motion.f"),
        "axil": file_list("dda_motion_axil.f"), "spi": file_list("dda_motion_spi.f")}
# The vector sets each top runs, fastest first (names of the ctest fixtures' folders).
SETS = {
    "core": ["vec_sets/paper", "vec_sets/paper_ce", "vec_sets/second_quadrant", "vec_sets/back_to_back",
             "vec_sets/paper_half", "bus_vec_sets/helix", "bus_vec_sets/lines_3d", "vec_sets/paper_macro"],
    "motion": ["bus_vec_sets/paper", "bus_vec_sets/paper_timed", "bus_vec_sets/reversals", "bus_vec_sets/pocket",
               "bus_vec_sets/queue", "bus_vec_sets/abort", "bus_vec_sets/io_limits", "bus_vec_sets/io_overflow",
               "bus_vec_sets/helix", "bus_vec_sets/paced", "bus_vec_sets/paced_slower", "bus_vec_sets/pace_step",
               "bus_vec_sets/pace_step_less", "bus_vec_sets/soft_stop", "bus_vec_sets/watchdog",
               "bus_vec_sets/io_estop", "bus_vec_sets/io_limit_hard", "bus_vec_sets/io_limit_decel",
               "bus_vec_sets/io_homing", "bus_vec_sets/io_probing", "bus_vec_sets/io_snapshot",
               "bus_vec_sets/io_glitches", "bus_vec_sets/drilling", "bus_vec_sets/planes", "bus_vec_sets/feeds",
               "bus_vec_sets/io_ranges"],
    "axil": ["bus_vec_sets/axil_paper", "bus_vec_sets/axil_queue", "bus_vec_sets/axil_paper_timed"],
    "spi": ["bus_vec_sets/spi_paper", "bus_vec_sets/spi_queue"],
}
# The bus vector sets (tests/rtl_checks.cmake) no top runs, each with its reason; every
# other bus set must be in SETS (--check-sets, ctest tests.mutation_sets).
LEFT_OUT = {
    "bus_vec_sets/lathe": "the lathe example, 869,000 cycles, minutes a mutant under Icarus: the block's "
                          "arcs through the queue are run by paper, queue and planes in a tenth of the cycles",
    "bus_vec_sets/lathe_timed": "the lathe example with drive timings, 927,000 cycles: paper_timed and "
                                "reversals drive the stages' timings in a hundredth of the time",
    "bus_vec_sets/paper_macro": "the lathe paper's macro program, 110,000 cycles: vec_sets/paper_macro runs the "
                                "same program on the core, queue and planes the queue with programs' pieces",
}


def bus_sets_registered(build):
    """The bus vector sets the build's ctest registers (vectors.bus.gen_NAME), as
    bus_vec_sets/NAME."""
    if not (Path(build) / "CTestTestfile.cmake").exists():
        sys.exit(f"mutation: {build} is not a configured build (cmake -S . -B {build} first)")
    out = subprocess.run(["ctest", "-N", "-R", r"^vectors\.bus\.gen_"], cwd=build, capture_output=True, text=True,
                         check=True).stdout
    sets = {"bus_vec_sets/" + n for n in re.findall(r"vectors\.bus\.gen_(\w+)", out)}
    if not sets:
        sys.exit(f"mutation: {build} registers no bus vector set (configured with the RTL tests off?)")
    return sets


def check_sets(build):
    """The sets SETS and LEFT_OUT name against the ones ctest registers: a new set that
    no top runs, or a name that no longer exists, is an error. Returns the errors."""
    registered = bus_sets_registered(build)
    named = {x for sets in SETS.values() for x in sets if x.startswith("bus_vec_sets/")} | set(LEFT_OUT)
    errors = [f"{x}: registered by ctest, but neither in SETS nor in LEFT_OUT" for x in sorted(registered - named)]
    errors += [f"{x}: named in scripts/mutation.py, but ctest registers no such set" for x in sorted(named - registered)]
    return errors


def code_lines(path):
    """(number, text) of the lines that compute: not declarations, comments, the
    assertions' blocks (`ifndef SYNTHESIS ... `endif) or the formal proofs' abstractions
    (`ifdef DDA_FORMAL_ABSTRACT ... `else: plain sums no bench simulates, which the
    proof "lemmas" of scripts/formal.sh holds equal to the code after `else)."""
    skip = 0  # depth of the conditional blocks inside a skipped one
    abstract = False  # the skipped block is an abstraction: its `else branch is simulated
    for n, text in enumerate(path.read_text().splitlines(), 1):
        t = text.strip()
        if t.startswith("`ifndef SYNTHESIS") or t.startswith("`ifdef DDA_FORMAL_ABSTRACT") or \
                (skip and (t.startswith("`ifdef") or t.startswith("`ifndef"))):
            skip += 1
        elif skip == 1 and t.startswith("`else") and abstract:
            skip = 0
            abstract = False
            continue
        elif skip and t.startswith("`endif"):
            skip -= 1
            continue
        if t.startswith("`ifdef DDA_FORMAL_ABSTRACT") and skip == 1:
            abstract = True
        if skip or DECLARATION.match(text):
            continue
        code = text.split("//")[0]
        if re.match(r"^\s*wire\b", code) and "=" not in code:
            continue
        yield n, code


def sites():
    files = sorted(set(f for fl in TOPS.values() for f in fl))
    out = []
    for f in files:
        for n, code in code_lines(RTL / f):
            for op, pat, rep in OPERATORS:
                for k, m in enumerate(re.finditer(pat, code)):
                    out.append({"file": f, "line": n, "op": op, "k": k, "at": m.start(), "len": len(m.group(0)),
                                "rep": rep, "text": code.strip()})
    return out


def key(m):
    return f"{m['file']}|{m['op']}|{m['k']}|{m['text']}"


def make(m, work):
    d = Path(tempfile.mkdtemp(prefix="mutant-", dir=work))
    for f in RTL.iterdir():
        if f.is_file():
            shutil.copy(f, d / f.name)
    lines = (d / m["file"]).read_text().splitlines(keepends=True)
    t = lines[m["line"] - 1]
    lines[m["line"] - 1] = t[:m["at"]] + m["rep"] + t[m["at"] + m["len"]:]
    (d / m["file"]).write_text("".join(lines))
    return d


def tops_of(f):
    return [t for t, fl in TOPS.items() if f in fl]


def compiles(d, m):
    top = "motion_spi" if tops_of(m["file"]) == ["spi"] else "motion_axil" if tops_of(m["file"]) == ["axil"] \
        else "core" if "core" in tops_of(m["file"]) else "motion"
    flist = RTL / f"dda_{top}.f"
    env = dict(os.environ, DDA_RTL=str(d))
    r = subprocess.run(["iverilog", "-g2012", f"-I{d}", f"-I{RTL}", "-o", os.devnull, "-c", str(flist)],
                       env=env, capture_output=True, text=True, check=False)
    return r.returncode == 0


# The core's sets run on its three builds: the small implementation, the fast one and the
# small one with its hand-placed iCE40 cells (DDA_ICE40), so that a mutant of any of them
# meets a bench; the block's sets on the default build and, for a mutant of the core's
# files, on the fast implementation's too (the block's scenarios reach what the core's
# sets do not: stalls, idle axes holding an integrand).
CORE_BUILDS = [[], ["--impl", "fast"], ["--ice40"]]
BLOCK_BUILDS_OF_CORE = [[], ["--impl", "fast"]]


def run_sets(d, m, build, timeout):
    """The first set that fails (killed), or None (survived). Each set runs on every
    build before the next set, so a mutant of code one build alone simulates (the fast
    implementation's, the iCE40 cells') meets the fastest set first there too."""
    for top in tops_of(m["file"]):
        for s in SETS[top]:
            builds = CORE_BUILDS if top == "core" else BLOCK_BUILDS_OF_CORE if "core" in tops_of(m["file"]) else [[]]
            for opts in builds:
                killer = run_set(d, s, opts, build, timeout)
                if killer:
                    return killer
    return None


def run_set(d, s, opts, build, timeout):
    """s (with its build options) if the set fails on the mutant or runs out of time."""
    name = s + ("" if not opts else " " + " ".join(opts))
    cmd = [str(ROOT / "scripts/vector-bench.sh"), "--sim", "icarus", "--rtl", str(d), *opts]
    if s.startswith("bus_vec_sets/"):
        cmd.append("--bus")
    cmd.append(str(Path(build) / "tests" / s))
    env = dict(os.environ, DDA_BUILD_DIR=str(d / "build"))
    try:
        r = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=timeout, check=False)
    except subprocess.TimeoutExpired:
        return name + " (time bound)"
    return name if r.returncode != 0 else None


def draw(args):
    rng = random.Random(args.seed)
    pool = sites()
    if args.files:
        unknown = sorted(set(args.files) - set(s["file"] for s in pool))
        if unknown:
            raise SystemExit(f"mutation: --files names what no bench simulates: {', '.join(unknown)}")
        pool = [s for s in pool if s["file"] in args.files]
    rng.shuffle(pool)
    return pool


def module_of(f):
    return f[:-2] if f.endswith(".v") else f


def report(results, triage, floor):
    per = {}
    untriaged = []
    for m, killer in results:
        mod = module_of(m["file"])
        s = per.setdefault(mod, {"drawn": 0, "killed": 0, "equivalent": 0, "survivors": []})
        s["drawn"] += 1
        verdict = triage.get(key(m))
        if killer:
            s["killed"] += 1
        elif verdict and verdict.get("verdict") == "equivalent":
            s["equivalent"] += 1
            s["survivors"].append((m, "equivalent: " + verdict["reason"]))
        else:
            s["survivors"].append((m, "not triaged" if not verdict else verdict["verdict"] + ": " + verdict["reason"]))
            if not verdict:
                untriaged.append(m)
    print("| module | drawn | killed | equivalent | kill rate (non-equivalent) |")
    print("|---|---|---|---|---|")
    tot = {"drawn": 0, "killed": 0, "equivalent": 0}
    for mod in sorted(per):
        s = per[mod]
        for k in tot:
            tot[k] += s[k]
        live = s["drawn"] - s["equivalent"]
        print(f"| `{mod}` | {s['drawn']} | {s['killed']} | {s['equivalent']} | "
              + (f"{100.0 * s['killed'] / live:.1f}%" if live else "-") + " |")
    live = tot["drawn"] - tot["equivalent"]
    rate = 100.0 * tot["killed"] / live if live else 100.0
    print(f"| all | {tot['drawn']} | {tot['killed']} | {tot['equivalent']} | {rate:.1f}% |")
    print()
    for mod in sorted(per):
        for m, why in per[mod]["survivors"]:
            print(f"survivor {m['file']}:{m['line']} {m['op']} #{m['k']}: `{m['text']}` -- {why}")
    return rate, untriaged


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--count", type=int, default=100)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=120)
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--build", default=str(ROOT / "build"))
    ap.add_argument("--floor", type=float, default=95.0)
    ap.add_argument("--list", action="store_true", help="print the drawn mutants and stop")
    ap.add_argument("--files", nargs="+", metavar="FILE",
                    help="draw only in these files of rtl/ (e.g. the ones a change touched)")
    ap.add_argument("--check-sets", action="store_true",
                    help="check that every bus vector set ctest registers is run by a top or left out with its "
                         "reason, and stop")
    a = ap.parse_args()
    # Absolute: iverilog reads a nested file list's relative paths from the list's own
    # folder (rtl/), so a relative mutant folder would fail every block mutant's compile.
    a.build = str(Path(a.build).resolve())
    errors = check_sets(a.build)
    for e in errors:
        print(f"mutation: {e}", file=sys.stderr)
    if a.check_sets or errors:
        if not errors:
            print(f"mutation: every bus vector set is run ({sum(len(v) for v in SETS.values())} runs by the tops) "
                  f"or left out ({len(LEFT_OUT)}) with its reason")
        return 1 if errors else 0
    work = Path(a.build) / "mutation"
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    pool = draw(a)
    print(f"mutation: {len(pool)} sites of {len(OPERATORS)} operators in "
          f"{len(set(s['file'] for s in pool))} files; drawing {a.count} (seed {a.seed})")
    chosen, stillborn = [], 0
    for m in pool:
        if len(chosen) == a.count:
            break
        d = make(m, work)
        if compiles(d, m):
            chosen.append((m, d))
        else:
            stillborn += 1
            shutil.rmtree(d)
    if a.list:
        for m, _ in chosen:
            print(f"{m['file']}:{m['line']} {m['op']} #{m['k']}: {m['text']}")
        return 0
    print(f"mutation: {stillborn} stillborn (did not compile) replaced")
    # The operators rarely break the syntax: many stillborn mutants mean the compile
    # itself fails (a path, a tool), which would leave whole files undrawn.
    if stillborn > len(chosen) // 10:
        print("mutation: more than one mutant in ten does not compile: check the compile step", file=sys.stderr)
        return 1
    gen = subprocess.run(["ctest", "--test-dir", a.build, "-R", r"^vectors\.(bus\.)?gen_"], capture_output=True,
                         text=True, check=False)
    if gen.returncode != 0:
        print(gen.stdout[-2000:], file=sys.stderr)
        return 1
    # A set missing (renamed in tests/rtl_checks.cmake) would fail every run and count
    # every mutant as killed: refuse to start instead.
    missing = [x for sets in SETS.values() for x in sets if not (Path(a.build) / "tests" / x / "manifest.json").exists()]
    if missing:
        print(f"mutation: vector sets not written by the ctest fixtures: {', '.join(missing)}", file=sys.stderr)
        return 1

    def one(md):
        m, d = md
        killer = run_sets(d, m, a.build, a.timeout)
        shutil.rmtree(d, ignore_errors=True)
        print(f"  {m['file']}:{m['line']} {m['op']}: " + (f"killed by {killer}" if killer else "SURVIVED"),
              flush=True)
        return m, killer

    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as ex:
        results = list(ex.map(one, chosen))
    triage_file = ROOT / "tests" / "mutation-triage.json"
    triage = json.loads(triage_file.read_text()) if triage_file.exists() else {}
    rate, untriaged = report(results, triage, a.floor)
    if untriaged:
        print(f"mutation: {len(untriaged)} survivors not triaged (tests/mutation-triage.json)")
    return 1 if untriaged or rate < a.floor else 0


if __name__ == "__main__":
    sys.exit(main())
