#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Per-module code coverage of rtl/ from Verilator's coverage data (verilator --coverage).

  coverage.py table DAT RTL_DIR [--exclusions FILE]     the summary table (Markdown)
  coverage.py check DAT RTL_DIR --floors FILE [--exclusions FILE]
                                                        exit 1 naming every module below its
                                                        floor and its uncovered points
  coverage.py uncovered DAT RTL_DIR [--module M] [--exclusions FILE]
                                                        every uncovered point, file:line

DAT is one coverage file (verilator_coverage --write merges several). A point counts for
the module of its `page` (v_line/, v_branch/, v_toggle/, v_user/<module>) when its file
lies in RTL_DIR; the instances and parameter variants of a module (Verilator's
<module>__<suffix>) are one: a point is covered when any of them hit it. A line point (a statement block, or a branch of an if or a case: Verilator 5.006
writes those as v_branch, counted here with the lines) is covered with a count of at
least 1; a toggle point (one
bit of a signal) with at least 2, that is both ways. An exclusion (JSON: a list of
{"module", "kind": "line"|"toggle", "match": regex, "reason"}) takes out the points whose
signal (toggle) or source line (line) matches; each must take out at least one point, so
that none outlives the code it names.
"""
import argparse
import json
import re
import sys
from collections import defaultdict
from pathlib import Path

KINDS = ("line", "toggle", "user")


def parse(dat):
    """{(kind, module): {point key: (count, file, line, what)}}, instances merged."""
    points = defaultdict(dict)
    with open(dat, encoding="latin-1") as f:
        for raw in f:
            if not raw.startswith("C '"):
                continue
            body, count = raw[3:].rstrip("\n").rsplit("' ", 1)
            fields = dict(kv.split("\x02", 1) for kv in body.split("\x01") if kv)
            page = fields.get("page", "")
            if not page.startswith("v_") or "/" not in page:
                continue
            kind, module = page[2:].split("/", 1)
            module = module.split("__", 1)[0]  # Verilator's name of a parameter variant: the module's
            if kind == "branch":  # the branches of an if or a case: line coverage counts them
                kind = "line"
            key = (fields.get("f"), fields.get("l"), fields.get("n"), fields.get("o"), fields.get("S"))
            old = points[(kind, module)].get(key, (0,))[0]
            points[(kind, module)][key] = (old + int(count), fields.get("f"), int(fields.get("l", 0)), fields.get("o", ""))
    return points


def covered(kind, count):
    return count >= (2 if kind == "toggle" else 1)


class Coverage:
    def __init__(self, dat, rtl_dir, exclusions=None):
        self.rtl = Path(rtl_dir).resolve()
        self.sources = {}
        self.rules = json.loads(Path(exclusions).read_text()) if exclusions else []
        self.used = [0] * len(self.rules)
        self.modules = defaultdict(dict)  # module -> kind -> [(count, file, line, what)]
        for (kind, module), pts in parse(dat).items():
            kept = [p for p in pts.values() if p[1] and self.in_rtl(p[1])]
            kept = [p for p in kept if not self.excluded(kind, module, p)]
            if kept:
                self.modules[module][kind] = kept

    def in_rtl(self, file):
        p = Path(file).resolve()
        return p.parent == self.rtl or self.rtl in p.parents

    def source_line(self, file, line):
        if file not in self.sources:
            self.sources[file] = Path(file).read_text(encoding="utf-8").splitlines()
        lines = self.sources[file]
        return lines[line - 1] if 0 < line <= len(lines) else ""

    def excluded(self, kind, module, point):
        for i, r in enumerate(self.rules):
            if r["module"] != module or r["kind"] != kind:
                continue
            text = point[3] if kind == "toggle" else self.source_line(point[1], point[2])
            if re.search(r["match"], text):
                self.used[i] += 1
                return True
        return False

    def stale_rules(self):
        return [r for r, n in zip(self.rules, self.used) if n == 0]

    def figures(self, module, kind):
        pts = self.modules[module].get(kind, [])
        hit = sum(1 for p in pts if covered(kind, p[0]))
        return hit, len(pts)

    def uncovered(self, module, kind):
        return sorted((p for p in self.modules[module].get(kind, []) if not covered(kind, p[0])),
                      key=lambda p: (p[1], p[2], p[3]))


def pct(hit, total):
    return 100.0 if total == 0 else 100.0 * hit / total


def cell(hit, total):
    return "-" if total == 0 else f"{pct(hit, total):.1f}% ({hit}/{total})"


def table(cov):
    excluded = defaultdict(int)
    for r, n in zip(cov.rules, cov.used):
        excluded[r["module"]] += n
    out = ["| module | line (branches included) | toggle | user | points excluded |", "|---|---|---|---|---|"]
    for m in sorted(cov.modules):
        out.append(f"| `{m}` | " + " | ".join(cell(*cov.figures(m, k)) for k in KINDS) + f" | {excluded[m]} |")
    return "\n".join(out)


def describe(kind, p):
    where = f"{Path(p[1]).name}:{p[2]}"
    return f"{where} {p[3]} (count {p[0]})" if kind == "toggle" else f"{where} {p[3]}"


def check(cov, floors):
    spec = json.loads(Path(floors).read_text())
    default = spec.get("default", {})
    failed = False
    for r in cov.stale_rules():
        print(f"coverage: exclusion of {r['module']} {r['kind']} /{r['match']}/ takes out no point: remove it")
        failed = True
    for m in sorted(cov.modules):
        want = dict(default, **spec.get("modules", {}).get(m, {}))
        for kind, floor in want.items():
            hit, total = cov.figures(m, kind)
            if pct(hit, total) + 1e-9 >= floor:
                continue
            failed = True
            print(f"coverage: {m} {kind} {pct(hit, total):.1f}% ({hit}/{total}) is below its floor {floor}%:")
            for p in cov.uncovered(m, kind)[:40]:
                print(f"  uncovered {describe(kind, p)}")
    for m in spec.get("modules", {}):
        if m not in cov.modules:
            print(f"coverage: module {m} has a floor but no coverage point")
            failed = True
    return 1 if failed else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("action", choices=("table", "check", "uncovered"))
    ap.add_argument("dat")
    ap.add_argument("rtl_dir")
    ap.add_argument("--exclusions")
    ap.add_argument("--floors")
    ap.add_argument("--module")
    a = ap.parse_args()
    cov = Coverage(a.dat, a.rtl_dir, a.exclusions)
    if not cov.modules:
        print(f"coverage: no point of {a.rtl_dir} in {a.dat}", file=sys.stderr)
        return 1
    if a.action == "table":
        print(table(cov))
        return 0
    if a.action == "check":
        if not a.floors:
            ap.error("check needs --floors FILE")
        return check(cov, a.floors)
    for m in sorted(cov.modules):
        if a.module and m != a.module:
            continue
        for kind in KINDS:
            for p in cov.uncovered(m, kind):
                print(f"{m} {kind} {describe(kind, p)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
