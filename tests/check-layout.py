#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The tree says what runs where: checks the direction the three homes link and include in,
and the size of the source folders (docs/design.md, "Where to change what").

    check-layout.py --graph BUILD/link-graph.txt [--root DIR] [--plant FROM TO]
                    [--plant-include FILE HEADER]

The homes: model/ (what the hardware does), host/ (what runs on the host), tb/ (what only
tests and measurements use), and cli/ (the dda command).
  - A target of model/ links nothing of host/, tb/ or cli/, a target of host/ nothing of
    tb/ or cli/, through any chain of links; and their sources are their home's.
  - Of the dda command, only libraries marked DDA_LINKS_TEST_BENCH link tb/, and only a
    library whose sources are all in cli/ itself may carry the mark (the subcommands that
    run engines and scenarios). Any other library of cli/ reaches neither tb/ nor a marked
    library; the command's executable reaches tb/ only through a marked library.
  - Includes, followed from header to header: a source of model/ reaches only model/
    headers, one of host/ only model/ and host/ ones, one of a subfolder of cli/ (its
    options, the subcommands that run no engine) no tb/ header and no header of cli/
    itself (which is the marked library's).
  - No folder of C++ sources outside tests/ holds more than 12 .cpp files; the SystemC
    model (model/systemc/, a file per RTL module) holds no more than rtl/ has modules.
  - Every link to a name of the project's (dda_*) is to a target CMake defines (CMake
    would take any other name for a system library and fail only when linking), and no
    link is a generator expression the graph cannot follow.
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
# What the libraries of each home may link.
ALLOWED = {"model": {"model"}, "host": {"model", "host"}}
MAX_CPP = 12


def read_graph(path):
    graph = {}
    with open(path) as f:
        for line in f:
            parts = line.rstrip("\n").split("\t")
            if len(parts) != 6:
                raise SystemExit(f"check-layout: {path}: a line is not NAME TYPE HOME MARK DEPS SOURCES: {line!r}")
            name, kind, home, mark, deps, srcs = parts
            graph[name] = {"kind": kind, "home": home, "mark": mark, "deps": [d for d in deps.split(";") if d],
                           "sources": [s for s in srcs.split(";") if s]}
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


def through(chain):
    return f" (through {' -> '.join(chain[1:-1])})" if len(chain) > 2 else ""


def check_links(graph):
    errors = []
    for name in sorted(graph):
        t = graph[name]
        home = t["home"]
        for dep in t["deps"]:
            if dep.startswith("dda_") and dep not in graph:
                errors.append(f"{name} links {dep}, which no CMake target of the project defines")
            if "$<" in dep:
                errors.append(f"{name} links {dep}: a generator expression the layout check cannot follow")
        if home in ALLOWED:
            chain = path_to(graph, name, lambda d: graph[d]["home"] not in ALLOWED[home])
            if chain:
                to = chain[-1]
                errors.append(f"{home} library {name} links {graph[to]['home']} library {to}{through(chain)}: "
                              f"{home}/ links only {' and '.join(sorted(ALLOWED[home]))}/")
            for s in t["sources"]:
                if s.split("/")[0] != home:
                    errors.append(f"{home} library {name} compiles {s}: its sources are {home}/'s")
        elif home == "cli":
            if t["mark"]:
                stray = [s for s in t["sources"] if os.path.dirname(s) != "cli"]
                if stray:
                    errors.append(f"cli library {name} is marked DDA_LINKS_TEST_BENCH but compiles {stray[0]}: "
                                  "only cli/'s own sources run engines and scenarios")
            elif t["kind"] == "EXECUTABLE":
                chain = path_to(graph, name, lambda d: graph[d]["home"] == "tb", stop=lambda d: bool(graph[d]["mark"]))
                if chain:
                    errors.append(f"cli target {name} links tb library {chain[-1]}{through(chain)}: "
                                  "only a library marked DDA_LINKS_TEST_BENCH may (cli/CMakeLists.txt)")
            else:
                chain = path_to(graph, name, lambda d: graph[d]["home"] == "tb" or bool(graph[d]["mark"]))
                if chain:
                    to = chain[-1]
                    what = f"tb library {to}" if graph[to]["home"] == "tb" else f"the marked library {to}"
                    errors.append(f"cli target {name} links {what}{through(chain)}: only a library marked "
                                  "DDA_LINKS_TEST_BENCH may reach the test bench (cli/CMakeLists.txt)")
    return errors


def sources(root):
    out = subprocess.run(["git", "-C", root, "ls-files", "-co", "--exclude-standard"], capture_output=True, text=True)
    if out.returncode == 0:
        return sorted(f for f in out.stdout.split("\n") if f and os.path.isfile(os.path.join(root, f)))
    files = []
    for d, dirs, names in os.walk(root):
        rel = os.path.relpath(d, root)
        if rel == ".":
            dirs[:] = [x for x in dirs if x != ".git" and not x.startswith("build")]
        files += [os.path.normpath(os.path.join(rel, n)) for n in names]
    return sorted(files)


INCLUDE = re.compile(r'^\s*#\s*include\s*["<]([^">]+)[">]', re.M)
CXX = (".cpp", ".hpp", ".h")


def includes_of(root, files, planted):
    """Each C++ file's includes of the tree's own files (as paths from the root: the
    project's one include directory; or beside the including file)."""
    known = set(files)
    inc = {}
    for f in files:
        if not f.endswith(CXX):
            continue
        with open(os.path.join(root, f), errors="replace") as fh:
            text = fh.read()
        text += "".join(f'\n#include "{h}"\n' for pf, h in planted if pf == f)
        found = []
        for m in INCLUDE.finditer(text):
            name = m.group(1)
            beside = os.path.normpath(os.path.join(os.path.dirname(f), name))
            if name in known or name.split("/")[0] in HOMES:
                found.append(name)
            elif beside in known:
                found.append(beside)
        inc[f] = found
    return inc


def forbidden(f):
    """What a source may not reach by includes, and the rule's words; None if unchecked."""
    parts = f.split("/")
    if parts[0] == "model":
        return lambda h: h.split("/")[0] in ("host", "tb", "cli"), "model/ includes only model/"
    if parts[0] == "host":
        return lambda h: h.split("/")[0] in ("tb", "cli"), "host/ includes only model/ and host/"
    if parts[0] == "cli" and len(parts) > 2:
        return (lambda h: h.split("/")[0] == "tb" or (h.startswith("cli/") and h.count("/") == 1),
                f"cli/{parts[1]}/ includes neither tb/ nor cli/'s own headers (the marked library's)")
    return None


def check_includes(root, files, planted):
    errors = []
    inc = includes_of(root, files, planted)
    for f in sorted(inc):
        rule = forbidden(f)
        if rule is None:
            continue
        bad, words = rule
        seen = {f}
        todo = [[f]]
        while todo:
            chain = todo.pop(0)
            hit = None
            for h in inc.get(chain[-1], []):
                if h in seen:
                    continue
                seen.add(h)
                if bad(h):
                    hit = chain + [h]
                    break
                todo.append(chain + [h])
            if hit:
                via = f" (through {' -> '.join(hit[1:-1])})" if len(hit) > 2 else ""
                errors.append(f"{f} includes {hit[-1]}{via}: {words}")
                break
    return errors


def check_sizes(files):
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
    for f, _ in a.plant_include:
        if f not in files:
            print(f"check-layout: --plant-include {f}: no such file in the tree", file=sys.stderr)
            return 2
    errors = check_links(graph) + check_includes(root, files, a.plant_include) + check_sizes(files)
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
