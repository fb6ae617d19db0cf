#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The testplan: tests/testplan.json says what each layer verifies and which ctest
entries do it (in the spirit of lowRISC's testplans). Each testpoint is
  {"name", "layer", "what", "how", "where", "tests": [regular expressions]}
and a pattern claims the ctest entries whose whole name it matches (Python re,
fullmatch). A testpoint whose work runs outside ctest has "tests": [] and says where in
"outside_ctest".

  scripts/testplan.py check BUILD_DIR [--plan FILE]
      fails (exit 1) naming every ctest entry no testpoint matches, every testpoint
      that matches no entry and every pattern that matches nothing
  scripts/testplan.py table [--build BUILD_DIR] [--plan FILE]
      prints the Markdown table (| what | how | where |, and a "ctest" column with the
      number of entries each testpoint matches if --build is given)
  scripts/testplan.py write-doc [--build BUILD_DIR] [--plan FILE] [--doc FILE]
      writes that table into docs/verification.md between its markers
  scripts/testplan.py check-doc [--build BUILD_DIR] [--plan FILE] [--doc FILE]
      fails (exit 1, with a diff) unless the doc's table is what `table` prints
"""
import argparse
import difflib
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PLAN = os.path.join(ROOT, "tests", "testplan.json")
DOC = os.path.join(ROOT, "docs", "verification.md")
BEGIN = "<!-- BEGIN GENERATED: scripts/testplan.py -->"
END = "<!-- END GENERATED: scripts/testplan.py -->"
TEXT_KEYS = ("name", "layer", "what", "how", "where")
OPTIONAL_KEYS = ("outside_ctest",)


class Failure(Exception):
    """A check that failed: its messages are printed, the exit status is 1."""

    def __init__(self, messages):
        super().__init__("\n".join(messages))
        self.messages = messages


def rel(path):
    return os.path.relpath(path, ROOT) if path.startswith(ROOT + os.sep) else path


def load_plan(path):
    """The testpoints of `path`, each with its patterns compiled ("_patterns")."""
    try:
        with open(path, encoding="utf-8") as f:
            plan = json.load(f)
    except (OSError, ValueError) as e:
        raise Failure([f"testplan: cannot read {rel(path)}: {e}"])
    if not isinstance(plan, list) or not plan:
        raise Failure([f"testplan: {rel(path)} must hold a non-empty list of testpoints"])
    errors, names = [], set()
    for i, tp in enumerate(plan):
        where = f"testplan: {rel(path)}: testpoint {i + 1}"
        if not isinstance(tp, dict):
            errors.append(f"{where} is not an object")
            continue
        where += f" ('{tp.get('name', '?')}')"
        for key in TEXT_KEYS:
            if not isinstance(tp.get(key), str) or not tp[key].strip():
                errors.append(f"{where}: '{key}' must be a non-empty string")
            elif "\n" in tp[key]:
                errors.append(f"{where}: '{key}' must be one line")
        unknown = set(tp) - set(TEXT_KEYS) - set(OPTIONAL_KEYS) - {"tests"}
        if unknown:
            errors.append(f"{where}: unknown key(s) {', '.join(sorted(unknown))}")
        if tp.get("name") in names:
            errors.append(f"{where}: the name is taken by an earlier testpoint")
        names.add(tp.get("name"))
        tests = tp.get("tests")
        if not isinstance(tests, list) or not all(isinstance(t, str) and t for t in tests):
            errors.append(f"{where}: 'tests' must be a list of regular expressions")
            continue
        if not tests and not tp.get("outside_ctest"):
            errors.append(f"{where}: no tests: give patterns, or say where it runs in 'outside_ctest'")
        if tests and "outside_ctest" in tp:
            errors.append(f"{where}: 'outside_ctest' goes with an empty 'tests' only")
        tp["_patterns"] = []
        for t in tests:
            try:
                tp["_patterns"].append((t, re.compile(t)))
            except re.error as e:
                errors.append(f"{where}: pattern '{t}' is not a regular expression: {e}")
    if errors:
        raise Failure(errors)
    return plan


def ctest_entries(build):
    """The names of the ctest entries of the build tree `build`."""
    try:
        out = subprocess.run(["ctest", "--show-only=json-v1"], cwd=build, capture_output=True, text=True)
    except OSError as e:
        raise Failure([f"testplan: cannot run ctest in {build}: {e}"])
    if out.returncode != 0:
        raise Failure([f"testplan: ctest --show-only=json-v1 in {build} failed: {out.stderr.strip()}"])
    try:
        names = [t["name"] for t in json.loads(out.stdout)["tests"]]
    except (ValueError, KeyError, TypeError) as e:
        raise Failure([f"testplan: ctest in {build} printed no test list: {e}"])
    if not names:
        raise Failure([f"testplan: {build} has no ctest entry (is it a configured build tree?)"])
    return names


def matches(plan, names):
    """For each testpoint, for each of its patterns, the entries it matches."""
    return [[(t, [n for n in names if p.fullmatch(n)]) for t, p in tp["_patterns"]] for tp in plan]


def check(plan, names, plan_path):
    found = matches(plan, names)
    covered = {n for per_tp in found for _, ns in per_tp for n in ns}
    errors = [f"testplan: ctest entry '{n}' is matched by no testpoint" for n in names if n not in covered]
    uncovered = len(errors)
    for tp, per_tp in zip(plan, found):
        if not tp["_patterns"]:
            continue
        if not any(ns for _, ns in per_tp):
            errors.append(f"testplan: testpoint '{tp['name']}' matches no ctest entry")
            continue
        errors += [f"testplan: testpoint '{tp['name']}': pattern '{t}' matches no ctest entry"
                   for t, ns in per_tp if not ns]
    if errors:
        errors.append(f"testplan: {uncovered} of {len(names)} ctest entries uncovered, "
                      f"{len(errors) - uncovered} testpoint(s) or pattern(s) matching nothing ({rel(plan_path)})")
        raise Failure(errors)
    inside = [tp for tp in plan if tp["_patterns"]]
    outside = [f"{tp['name']}: {tp['outside_ctest']}" for tp in plan if not tp["_patterns"]]
    line = f"testplan: {len(inside)} testpoints cover all {len(names)} ctest entries"
    if outside:
        line += f"; {len(outside)} more outside ctest ({'; '.join(outside)})"
    print(line)


def cell(text):
    return text.replace("|", "\\|")


def table(plan, names=None):
    """The Markdown table of the plan, as lines; with `names`, a column of counts."""
    head, rule = "| what | how | where |", "|---|---|---|"
    if names is not None:
        head, rule = head + " ctest |", rule + "---|"
        counts = [len({n for _, ns in per_tp for n in ns}) for per_tp in matches(plan, names)]
    lines = [head, rule]
    for i, tp in enumerate(plan):
        row = f"| {cell(tp['what'])} | {cell(tp['how'])} | {cell(tp['where'])} |"
        if names is not None:
            row += f" {counts[i]} |"
        lines.append(row)
    return lines


def split_doc(path):
    """The doc's lines before the generated table, the table, and after it."""
    try:
        with open(path, encoding="utf-8") as f:
            lines = f.read().split("\n")
    except OSError as e:
        raise Failure([f"testplan: cannot read {rel(path)}: {e}"])
    if lines.count(BEGIN) != 1 or lines.count(END) != 1 or lines.index(BEGIN) > lines.index(END):
        raise Failure([f"testplan: {rel(path)} must hold one line '{BEGIN}' and, after it, one line '{END}'"])
    b, e = lines.index(BEGIN), lines.index(END)
    return lines[:b + 1], lines[b + 1:e], lines[e:]


def main(argv):
    ap = argparse.ArgumentParser(prog="scripts/testplan.py", description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    c = sub.add_parser("check", help="every ctest entry is matched, every testpoint matches")
    c.add_argument("build", metavar="BUILD_DIR")
    c.add_argument("--plan", default=PLAN, help="the plan (default tests/testplan.json)")
    for name, what in (("table", "print the Markdown table"), ("write-doc", "write the table into the doc"),
                       ("check-doc", "the doc's table is what `table` prints")):
        p = sub.add_parser(name, help=what)
        p.add_argument("--build", metavar="BUILD_DIR", help="add a column: the ctest entries each testpoint matches")
        p.add_argument("--plan", default=PLAN, help="the plan (default tests/testplan.json)")
        if name != "table":
            p.add_argument("--doc", default=DOC, help="the doc (default docs/verification.md)")
    args = ap.parse_args(argv)
    try:
        plan = load_plan(args.plan)
        if args.cmd == "check":
            check(plan, ctest_entries(args.build), args.plan)
            return 0
        want = table(plan, ctest_entries(args.build) if args.build else None)
        if args.cmd == "table":
            print("\n".join(want))
            return 0
        before, have, after = split_doc(args.doc)
        if args.cmd == "write-doc":
            if have == want:
                print(f"testplan: {rel(args.doc)}: the table of {len(plan)} testpoints is up to date")
                return 0
            with open(args.doc, "w", encoding="utf-8") as f:
                f.write("\n".join(before + want + after))
            print(f"testplan: {rel(args.doc)}: the table of {len(plan)} testpoints written")
            return 0
        if have != want:
            diff = difflib.unified_diff(have, want, f"{rel(args.doc)} (the table)",
                                        f"scripts/testplan.py table{' --build ' + args.build if args.build else ''}",
                                        lineterm="")
            raise Failure(list(diff) + [f"testplan: {rel(args.doc)}'s table is not what {rel(args.plan)} gives: "
                                        f"run scripts/testplan.py write-doc"
                                        f"{' --build ' + args.build if args.build else ' (without --build)'}"])
        print(f"testplan: {rel(args.doc)}'s table is the plan's ({len(plan)} testpoints)")
        return 0
    except Failure as f:
        for m in f.messages:
            print(m, file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
