#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The tree says what runs where: checks the direction the three homes link and include in,
and the size of the source folders (docs/design.md, "Where to change what").

    check-layout.py --graph BUILD/link-graph.txt [--root DIR] [--plant FROM TO]
                    [--plant-include FILE HEADER]

The homes: model/ (what the hardware does), host/ (what runs on the host), tb/ (what only
tests and measurements use), and cli/ (the dda command).
  - A library of model/ links (and includes) nothing of host/, tb/ or cli/.
  - A library of host/ links (and includes) nothing of tb/ or cli/.
  - A target of cli/ reaches tb/ only through a library marked DDA_LINKS_TEST_BENCH (the
    subcommands that run engines and scenarios); the sources of cli/'s other folders
    include nothing of tb/.
  - No folder of C++ sources outside tests/ holds more than 12 .cpp files; the SystemC
    model (model/systemc/, a file per RTL module) holds no more than rtl/ has modules.
The graph is the one CMake writes at configure time (cmake/link_graph.cmake). --plant adds
a link FROM -> TO to it, --plant-include an include of HEADER to FILE's text, before the
checks: a planted violation must fail (the tests "layout.planted_*").
Exit status: 0 all hold, 1 a rule broken (each on a line of stderr), 2 bad usage.
"""
import argparse
import os
import re
import subprocess
import sys

HOMES = ("model", "host", "tb", "cli")
# What each home may link and include.
ALLOWED = {"model": {"model"}, "host": {"model", "host"}}
MAX_CPP = 12


def read_graph(path):
    graph = {}
    with open(path) as f:
        for line in f:
            parts = line.rstrip("\n").split("\t")
            if len(parts) != 5:
                raise SystemExit(f"check-layout: {path}: a line is not NAME TYPE HOME MARK DEPS: {line!r}")
            name, kind, home, mark, deps = parts
            graph[name] = {"kind": kind, "home": home, "mark": mark, "deps": [d for d in deps.split(";") if d]}
    return graph


def path_to(graph, start, bad, stop=lambda n: False):
    """The first chain of links from start to a target for which bad() holds, not going
    through a target for which stop() holds (start itself excepted); None if none."""
    seen = {start}
    todo = [[start]]
    while todo:
        chain = todo.pop(0)
        for dep in graph[chain[-1]]["deps"]:
            if dep not in graph or dep in seen:
                continue  # not the project's (an imported or system library), or seen
            seen.add(dep)
            if bad(dep):
                return chain + [dep]
            if not stop(dep):
                todo.append(chain + [dep])
    return None


def check_links(graph):
    errors = []
    for name in sorted(graph):
        t = graph[name]
        home = t["home"]
        if home in ALLOWED:
            chain = path_to(graph, name, lambda d: graph[d]["home"] not in ALLOWED[home])
            if chain:
                to = chain[-1]
                errors.append(f"{home} library {name} links {graph[to]['home']} library {to}"
                              + (f" (through {' -> '.join(chain[1:-1])})" if len(chain) > 2 else "")
                              + f": {home}/ links only {' and '.join(sorted(ALLOWED[home]))}/")
        elif home == "cli" and not t["mark"]:
            chain = path_to(graph, name, lambda d: graph[d]["home"] == "tb", stop=lambda d: bool(graph[d]["mark"]))
            if chain:
                errors.append(f"cli target {name} links tb library {chain[-1]} (through {' -> '.join(chain)}): "
                              "only a library marked DDA_LINKS_TEST_BENCH may (cli/CMakeLists.txt)")
    return errors


def sources(root):
    out = subprocess.run(["git", "-C", root, "ls-files", "-co", "--exclude-standard"], capture_output=True, text=True)
    if out.returncode != 0:
        files = []
        for d, _, names in os.walk(root):
            if "/.git" in d or "/build" in d:
                continue
            files += [os.path.relpath(os.path.join(d, n), root) for n in names]
        return sorted(files)
    return sorted(f for f in out.stdout.split("\n") if f and os.path.exists(os.path.join(root, f)))


INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def check_includes(root, files, planted):
    errors = []
    for f in files:
        if not f.endswith((".cpp", ".hpp", ".h")):
            continue
        home = f.split("/")[0]
        if home not in ALLOWED and not (home == "cli" and f.split("/")[1] in ("options", "blocks")):
            continue
        allowed = ALLOWED.get(home, {"model", "host", "cli"})
        with open(os.path.join(root, f), errors="replace") as fh:
            text = fh.read()
        text += "".join(f'\n#include "{h}"\n' for pf, h in planted if pf == f)
        for m in INCLUDE.finditer(text):
            first = m.group(1).split("/")[0]
            if first in HOMES and first not in allowed:
                errors.append(f"{f} includes {m.group(1)}: {'/'.join(f.split('/')[:2])}/ includes only "
                              + " and ".join(sorted(allowed)) + "/")
    return errors


def check_sizes(root, files):
    errors = []
    per_dir = {}
    for f in files:
        if f.endswith(".cpp") and not f.startswith("tests/"):
            per_dir.setdefault(os.path.dirname(f), []).append(f)
    modules = len([f for f in files if re.fullmatch(r"rtl/[^/]+\.v", f)])
    for d, fs in sorted(per_dir.items()):
        limit, why = (modules, f"rtl/'s {modules} modules") if d == "model/systemc" else (MAX_CPP, str(MAX_CPP))
        if len(fs) > limit:
            errors.append(f"{d}/ holds {len(fs)} .cpp files, more than {why}: give it subfolders by responsibility")
    return errors


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--graph", required=True, help="the link graph CMake wrote (BUILD/link-graph.txt)")
    ap.add_argument("--root", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."),
                    help="the source tree (default: this script's)")
    ap.add_argument("--plant", nargs=2, action="append", default=[], metavar=("FROM", "TO"),
                    help="add a link FROM -> TO before checking")
    ap.add_argument("--plant-include", nargs=2, action="append", default=[], metavar=("FILE", "HEADER"),
                    help="add an include of HEADER to FILE before checking")
    a = ap.parse_args()
    graph = read_graph(a.graph)
    for frm, to in a.plant:
        if frm not in graph or to not in graph:
            print(f"check-layout: --plant {frm} {to}: both must be targets of the graph", file=sys.stderr)
            return 2
        graph[frm]["deps"].append(to)
    missing = [h for h in HOMES if not any(t["home"] == h for t in graph.values())]
    if missing:
        print(f"check-layout: the graph has no target of {', '.join(missing)}/: is it this tree's?", file=sys.stderr)
        return 2
    root = os.path.abspath(a.root)
    files = sources(root)
    errors = check_links(graph) + check_includes(root, files, a.plant_include) + check_sizes(root, files)
    for e in errors:
        print("check-layout: " + e, file=sys.stderr)
    if errors:
        return 1
    libs = sum(1 for t in graph.values() if t["home"] in HOMES)
    print(f"check-layout: {libs} targets of model/, host/, tb/ and cli/ link in the one direction; "
          f"includes agree; no source folder over its size")
    return 0


if __name__ == "__main__":
    sys.exit(main())
