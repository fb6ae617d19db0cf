#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Compare the part-program reader with LinuxCNC's G-code interpreter `rs274`.

For each program of a corpus, run rs274 (scripts/rs274-setup.sh puts it in a cache) and
`dda blocks --program FILE --format json`, and classify the program:

  agree               both accept, the same motion blocks: kind (rapid, line, arc and its
                      direction), plane, turns, every end (X, Y, Z) and every arc centre
                      within half a step plus rs274's print precision (4 decimals of the
                      unit in force, of each offset and of the XY rotation); the column
                      "agree and run" counts those the planner and the golden model then
                      run too (`dda stats --program FILE`, exit 0: every block planned,
                      the third axis included, and on its rounded end)
  refused by both     both refuse (at any line)
  no motion           otherwise, neither prints a motion (rs274: no STRAIGHT_TRAVERSE,
                      STRAIGHT_FEED, ARC_FEED, STRAIGHT_PROBE, RIGID_TAP or NURBS_FEED;
                      ours: no block): excluded from the comparison, counted
  refused by feature  rs274 accepts; our reader refuses with "... is/are not supported",
                      naming a feature of the still-refused list (FEATURES), tallied by it
  disagree            anything else: we accept and rs274 refuses (then whether the blocks
                      rs274 printed before its refusal agree is reported), we refuse
                      without naming a feature, a different block (the first is reported)
A timeout, a crash, rs274 printing no canonical call at all (its tool table missing), or
our reader exiting with a status other than 0 or 2 (or 2 without its one-line message)
is an error of the run: reported loudly on standard error, never a classification.

rs274 prints program coordinates: this script applies the offsets as LinuxCNC's
emccanon.cc does (machine = rotate(program + G92 offset, XY rotation) + G5x offset +
tool length offset), each in the unit in force when rs274 printed it.

Per-program options for our reader: the nearest file OPTIONS.txt in the program's folder
or above it, lines `PATTERN OPTION...` (fnmatch, relative to that file's folder, every
matching line applies, later ones override), e.g. `lathe/* --machine lathe`. Without
one, LinuxCNC's own example programs whose path names a lathe run with
--machine lathe. With --machine lathe rs274 reads the program with a G18 line put first
(after a leading % line), as a lathe configuration's start-up code would select it.

rs274 refuses a program that ends without M2, M30 or a closing % ("File ended with no
percent sign or program end"), as LinuxCNC does; --eof-ends-program counts that refusal as
an acceptance, for programs written for controllers that stop at the last line.

Exit status: 0 no disagreement and no error, 1 otherwise, 2 bad usage.
"""

import argparse
import concurrent.futures
import fnmatch
import json
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rs274_canon import EOF_REFUSAL, RunError, run_rs274  # noqa: E402

EXTENSIONS = (".ngc", ".nc", ".gcode", ".tap", ".cnc")
# The features the reader still refuses (docs/programs.md, "The modal state"): a refusal
# naming one of them counts as "refused by feature"; a refusal naming another feature is
# a disagreement (a gap), reported with its message.
FEATURES = (
    "radius compensation",
    "threading",
    "probing",
    "splines",
    "rotary axes",
    "secondary linear axes",
    "polar coordinates",
    "axis normal to the plane",
    "helices",
    "canned cycles",
)
BEGIN_MARKER = "<!-- rs274-table begin -->"
END_MARKER = "<!-- rs274-table end -->"
CLASSES = ("agree", "refused by both", "refused by feature", "disagree", "no motion")

OUR_ERROR = re.compile(r"^(.*):(\d+):(\d+): (.*)$")



# ---------------------------------------------------------------------------- ours


def run_ours(args, program, options):
    cmd = [args.dda, "blocks", "--program", os.path.abspath(program), "--format", "json"]
    for key in ("--dialect", "--machine"):
        if options.get(key):
            cmd += [key, options[key]]
    for key, value in options.items():
        if key not in ("--dialect", "--machine"):
            cmd += [key] + ([value] if value is not None else [])
    if args.subroutine_path:  # the same folders for both
        cmd += ["--subroutine-path", ":".join(os.path.abspath(d) for d in args.subroutine_path.split(":"))]
    try:
        p = subprocess.run(cmd, cwd=os.path.dirname(os.path.abspath(program)), stdin=subprocess.DEVNULL,
                           capture_output=True, timeout=args.timeout)
    except subprocess.TimeoutExpired:
        raise RunError("our reader timed out after %g s" % args.timeout)
    except OSError as e:
        raise RunError("cannot run %s: %s" % (args.dda, e))
    err = p.stderr.decode("utf-8", "replace").strip()
    blocks, end = [], False
    for n, line in enumerate(p.stdout.decode("utf-8", "replace").splitlines(), 1):
        if not line.strip():
            continue
        try:
            obj = json.loads(line)
        except ValueError:
            raise RunError("our reader printed a line that is not JSON (line %d): %s" % (n, line[:120]))
        if end:
            raise RunError("our reader printed a line after its end object (line %d)" % n)
        if obj.get("end"):
            end = True
            continue
        for key in ("line", "kind", "plane", "to", "center", "turns"):
            if key not in obj:
                raise RunError("our reader's block (line %d) has no %r: %s" % (n, key, line[:120]))
        blocks.append(obj)
    if p.returncode == 0:
        if not end:
            raise RunError("our reader exited 0 without its end object")
        return {"accepted": True, "message": "", "blocks": blocks}
    m = OUR_ERROR.match(err)
    if p.returncode == 2 and m and "\n" not in err:
        return {"accepted": False, "message": m.group(4), "where": "%s:%s" % (m.group(2), m.group(3)),
                "blocks": blocks}
    raise RunError("our reader exited with status %d: %s" % (p.returncode, err[:300] or "(nothing on stderr)"))


def run_stats(args, program, options):
    """(ran, message): `dda stats` on the golden model, the planner and the run."""
    cmd = [args.dda, "stats", "--program", os.path.abspath(program), "--format", "json"]
    for key, value in options.items():
        cmd += [key] + ([value] if value is not None else [])
    if args.subroutine_path:
        cmd += ["--subroutine-path", ":".join(os.path.abspath(d) for d in args.subroutine_path.split(":"))]
    try:
        p = subprocess.run(cmd, cwd=os.path.dirname(os.path.abspath(program)), stdin=subprocess.DEVNULL,
                           capture_output=True, timeout=args.timeout)
    except subprocess.TimeoutExpired:
        return False, "dda stats timed out after %g s" % args.timeout
    if p.returncode != 0:
        return False, "dda stats: " + (p.stderr.decode("utf-8", "replace").strip()[:300] or "status %d" % p.returncode)
    if '"on_ends": true' not in p.stdout.decode("utf-8", "replace"):
        return False, "dda stats: not every block on its rounded end"
    return True, ""


def feature_key(message):
    if "is not supported" not in message and "are not supported" not in message:
        return None
    low = message.lower()
    for feature in FEATURES:
        if feature in low:
            return feature
    return None


# ---------------------------------------------------------------------------- comparison


def fmt(p):
    return "(" + ", ".join("%.4f" % c for c in p) + ")" if p is not None else "-"


def first_difference(theirs, ours, half_step):
    """The first block that differs, as a sentence, or None."""
    for i, (t, o) in enumerate(zip(theirs, ours)):
        what = None
        tol = half_step + t["tol"]
        if t["kind"] != o["kind"]:
            what = "kind: rs274 %s, ours %s" % (t["kind"], o["kind"])
        elif t["to"] is None or o["to"] is None or max(abs(a - b) for a, b in zip(t["to"], o["to"])) > tol:
            what = "end: rs274 %s, ours %s" % (fmt(t["to"]), fmt(o["to"]))
        elif t["kind"].startswith("arc"):
            axes = {17: (0, 1), 18: (2, 0), 19: (1, 2)}[t["plane"]]
            if t["plane"] != o["plane"]:
                what = "plane: rs274 G%d, ours G%d" % (t["plane"], o["plane"])
            elif o["center"] is None or max(abs(t["center"][k] - o["center"][k]) for k in axes) > tol:
                what = "centre: rs274 %s, ours %s" % (fmt(t["center"]), fmt(o["center"]))
            elif t["turns"] != o["turns"]:
                what = "turns: rs274 %d, ours %d" % (t["turns"], o["turns"])
        if what:
            return "motion block %d (our line %s; rs274 `%s`): %s (tolerance %.5f mm)" % (
                i + 1, o["line"], t["raw"], what, tol)
    if len(theirs) != len(ours):
        n = min(len(theirs), len(ours))
        extra = ("rs274 `%s`" % theirs[n]["raw"]) if len(theirs) > n else ("ours at line %s, %s to %s" % (
            ours[n]["line"], ours[n]["kind"], fmt(ours[n]["to"])))
        return "%d motion blocks in rs274, %d in ours; the first extra: %s" % (len(theirs), len(ours), extra)
    return None


def prefix_note(theirs, ours, half_step):
    """Whether the motion blocks rs274 printed before refusing agree with our first ones."""
    n = len(theirs)
    if n == 0:
        return "no block before to compare"
    if len(ours) < n:
        return "ours has fewer blocks (%d) than rs274 printed before refusing (%d)" % (len(ours), n)
    diff = first_difference(theirs, ours[:n], half_step)
    return ("the %d blocks before agree" % n) if diff is None else ("before it: " + diff)


def classify(theirs, ours, half_step):
    """(class, detail, feature key or None)."""
    if not theirs["accepted"] and not ours["accepted"]:
        return "refused by both", "rs274: %s; ours at %s: %s" % (theirs["message"], ours["where"], ours["message"]), None
    if not theirs["blocks"] and not ours["blocks"]:
        return "no motion", "rs274 %s, ours %s" % (
            "accepts" if theirs["accepted"] else "refuses: " + theirs["message"],
            "accepts" if ours["accepted"] else "refuses at %s: %s" % (ours["where"], ours["message"])), None
    if theirs["accepted"] and not ours["accepted"]:
        key = feature_key(ours["message"])
        if key:
            return "refused by feature", "at %s: %s" % (ours["where"], ours["message"]), key
        gap = " (a feature outside the still-refused list)" if "not supported" in ours["message"] else ""
        return "disagree", "rs274 accepts (%d motion blocks); ours refuses at %s: %s%s" % (
            len(theirs["blocks"]), ours["where"], ours["message"], gap), None
    if not theirs["accepted"]:
        return "disagree", "ours accepts (%d blocks); rs274 refuses after %d motion blocks: %s; %s" % (
            len(ours["blocks"]), len(theirs["blocks"]), theirs["message"],
            prefix_note(theirs["blocks"], ours["blocks"], half_step)), None
    diff = first_difference(theirs["blocks"], ours["blocks"], half_step)
    if diff:
        return "disagree", diff, None
    return "agree", "%d motion blocks" % len(ours["blocks"]), None


# ---------------------------------------------------------------------------- corpus


def find_programs(paths):
    found = []
    for path in paths:
        if os.path.isdir(path):
            for d, dirs, files in os.walk(path):
                dirs.sort()
                found += [os.path.join(d, f) for f in sorted(files) if f.lower().endswith(EXTENSIONS)]
        elif os.path.isfile(path):
            found.append(path)
        else:
            raise SystemExit("rs274-compare: no such file or folder: %s" % path)
    return found


def options_for(program, ncfiles):
    """Our reader's options for a program: the OPTIONS.txt files above it, else the built-in rule."""
    options = {}
    d = os.path.dirname(os.path.abspath(program))
    while True:
        listing = os.path.join(d, "OPTIONS.txt")
        if os.path.isfile(listing):
            rel = os.path.relpath(os.path.abspath(program), d)
            with open(listing) as f:
                for line in f:
                    words = line.split("#", 1)[0].split()
                    if len(words) >= 2 and fnmatch.fnmatch(rel, words[0]):
                        it = iter(words[1:])
                        for w in it:
                            options[w] = next(it, None)
            return options
        parent = os.path.dirname(d)
        if parent == d:
            break
        d = parent
    if ncfiles and os.path.abspath(program).startswith(os.path.abspath(ncfiles) + os.sep):
        rel = os.path.relpath(program, ncfiles).lower()
        if "lathe" in rel or os.path.basename(rel) == "g76.ngc":
            options["--machine"] = "lathe"
    return options


def source_of(program, roots):
    """The row a program is counted in: its corpus root and first folder below it."""
    ap = os.path.abspath(program)
    for label, root in roots:
        if ap.startswith(root + os.sep):
            rel = os.path.relpath(ap, root)
            head = rel.split(os.sep)[0] if os.sep in rel else ""
            return (label + "/" + head if head else label), os.path.join(label, rel)
    return os.path.dirname(program) or ".", program


def compare_one(args, program, ncfiles):
    options = options_for(program, ncfiles)
    if args.dialect:
        options["--dialect"] = args.dialect
    machine = options.get("--machine") or "mill"
    try:
        theirs = run_rs274(args, program, machine)
        if args.rs274_only:
            return {"theirs": theirs}
        ours = run_ours(args, program, options)
    except RunError as e:
        return {"error": str(e)}
    cls, detail, key = classify(theirs, ours, args.step / 2)
    result = {"class": cls, "detail": detail, "feature": key, "theirs": theirs}
    if cls == "agree":
        result["ran"], why = run_stats(args, program, options)
        if why:
            result["detail"] += "; not run: " + why
    return result


# ---------------------------------------------------------------------------- report


def table(results, rows):
    head = ("| source | programs | no motion | compared | agree | agree and run | refused by both | refused by feature "
            "| disagree |\n|---|---|---|---|---|---|---|---|---|")
    lines = [head]
    tally = {}

    def row(name, rs):
        n = {c: sum(1 for r in rs if r.get("class") == c) for c in CLASSES}
        errors = sum(1 for r in rs if "error" in r)
        compared = len(rs) - n["no motion"] - errors
        ran = sum(1 for r in rs if r.get("ran"))
        cells = [name, len(rs), n["no motion"], compared, n["agree"], ran] + [n[c] for c in CLASSES[1:4]]
        text = "| " + " | ".join(str(c) for c in cells) + " |"
        return text + (" (%d errors)" % errors if errors else "")

    for name in rows:
        lines.append(row("`%s`" % name, [r for r in results if r["source"] == name]))
    if len(rows) > 1:
        lines.append(row("**all**", results))
    for r in results:
        if r.get("feature"):
            tally[r["feature"]] = tally.get(r["feature"], 0) + 1
    if tally:
        lines += ["", "| refused by feature: our message names | programs |", "|---|---|"]
        for key, count in sorted(tally.items(), key=lambda kv: (-kv[1], kv[0])):
            lines.append("| %s | %d |" % (key.replace("|", "\\|"), count))
    return "\n".join(lines) + "\n"


def rs274_table(results, rows):
    lines = ["| source | programs | rs274 accepts, with motion | accepts, no motion | refuses |", "|---|---|---|---|---|"]
    for name in rows + (["**all**"] if len(rows) > 1 else []):
        rs = [r for r in results if name == "**all**" or r["source"] == name]
        ok = [r for r in rs if "theirs" in r]
        acc = sum(1 for r in ok if r["theirs"]["accepted"] and r["theirs"]["blocks"])
        nom = sum(1 for r in ok if r["theirs"]["accepted"] and not r["theirs"]["blocks"])
        ref = sum(1 for r in ok if not r["theirs"]["accepted"])
        label = name if name == "**all**" else "`%s`" % name
        lines.append("| %s | %d | %d | %d | %d |%s" % (label, len(rs), acc, nom, ref,
                                                       " (%d errors)" % (len(rs) - len(ok)) if len(rs) > len(ok) else ""))
    return "\n".join(lines) + "\n"


def write_table(path, text):
    with open(path) as f:
        content = f.read()
    b, e = content.find(BEGIN_MARKER), content.find(END_MARKER)
    if b < 0 or e < 0 or e < b or content.count(BEGIN_MARKER) != 1 or content.count(END_MARKER) != 1:
        raise SystemExit("rs274-compare: %s does not hold the two marker lines %s and %s (once each, in order)"
                         % (path, BEGIN_MARKER, END_MARKER))
    b += len(BEGIN_MARKER)
    new = content[:b] + "\n" + text + content[e:]
    tmp = path + ".rs274-compare.tmp"
    with open(tmp, "w") as f:
        f.write(new)
    os.replace(tmp, path)


def main():
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 epilog="Without PATH: the cache's LinuxCNC example programs and tests/programs/.")
    ap.add_argument("paths", nargs="*", metavar="PATH", help="programs or folders (recursive: %s)" % " ".join(
        "*" + e for e in EXTENSIONS))
    ap.add_argument("--cache", default=os.environ.get("RS274_CACHE", os.path.expanduser("~/.cache/dda-rs274")),
                    help="rs274's cache (scripts/rs274-setup.sh; default $RS274_CACHE or ~/.cache/dda-rs274)")
    ap.add_argument("--dda", default=os.path.join(os.environ.get("DDA_BUILD_DIR", os.path.join(repo, "build")),
                                                  "bin", "dda"), help="the dda command (default build/bin/dda)")
    ap.add_argument("--dialect", choices=("linuxcnc", "hnc", "fanuc"),
                    help="our reader's dialect for every program (default: OPTIONS.txt, else the reader detects it)")
    ap.add_argument("--step", type=float, default=0.001, help="the lattice step in mm; ends agree within half of it "
                    "plus rs274's print precision (default 0.001)")
    ap.add_argument("--timeout", type=float, default=20.0, help="seconds per program and side (default 20)")
    ap.add_argument("--jobs", type=int, default=2, help="programs run at once (default 2)")
    ap.add_argument("--subroutine-path", help="SUBROUTINE_PATH (colon-separated folders) for o<name> call, rs274's and our "
                    "reader's (--subroutine-path); both look in the program's own folder first")
    ap.add_argument("--eof-ends-program", action="store_true", help="count rs274's refusal \"%s\" as an "
                    "acceptance (LinuxCNC needs M2, M30 or %%%%; other controllers end a program at its last line)"
                    % EOF_REFUSAL)
    ap.add_argument("--rs274-only", action="store_true", help="run rs274 alone: what it accepts, with or without motion")
    ap.add_argument("--verbose", action="store_true", help="a line per program after the table")
    ap.add_argument("--write", metavar="FILE", help="put the table between the marker lines %s and %s of FILE"
                    % (BEGIN_MARKER, END_MARKER))
    args = ap.parse_args()
    args.cache = os.path.abspath(args.cache)

    if not os.access(os.path.join(args.cache, "root", "usr", "bin", "rs274"), os.X_OK) or \
            not os.path.isfile(os.path.join(args.cache, "tool.tbl")):
        raise SystemExit("rs274-compare: no rs274 in %s: run scripts/rs274-setup.sh first" % args.cache)
    if not args.rs274_only and not os.access(args.dda, os.X_OK):
        raise SystemExit("rs274-compare: no dda command at %s (build it, or give --dda, or --rs274-only)" % args.dda)
    if args.write:
        with open(args.write) as f:
            content = f.read()
        if content.count(BEGIN_MARKER) != 1 or content.count(END_MARKER) != 1 or \
                content.find(END_MARKER) < content.find(BEGIN_MARKER):
            raise SystemExit("rs274-compare: %s does not hold the two marker lines %s and %s (once each, in order)"
                             % (args.write, BEGIN_MARKER, END_MARKER))
    ncfiles = os.path.join(args.cache, "root", "usr", "share", "linuxcnc", "ncfiles")
    paths = args.paths or [ncfiles, os.path.join(repo, "tests", "programs")]
    programs = find_programs(paths)
    if not programs:
        raise SystemExit("rs274-compare: no program found in %s" % " ".join(paths))

    roots = [("ncfiles", os.path.abspath(ncfiles)), ("tests/programs", os.path.join(repo, "tests", "programs"))]
    roots += [(os.path.relpath(os.path.abspath(p), os.getcwd()), os.path.abspath(p)) for p in paths if os.path.isdir(p)]
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        results = list(pool.map(lambda p: compare_one(args, p, ncfiles), programs))
    rows = []
    for program, r in zip(programs, results):
        r["source"], r["name"] = source_of(program, roots)
        if r["source"] not in rows:
            rows.append(r["source"])

    text = rs274_table(results, rows) if args.rs274_only else table(results, rows)
    print(text, end="")
    if args.verbose:
        print()
        for r in results:
            if "error" in r:
                print("- `%s`: ERROR: %s" % (r["name"], r["error"]))
            elif args.rs274_only:
                t = r["theirs"]
                state = ("accepts, %d motion blocks" % len(t["blocks"])) if t["accepted"] else (
                    "refuses after %d motion blocks: %s" % (len(t["blocks"]), t["message"]))
                print("- `%s`: %s" % (r["name"], state))
            else:
                print("- `%s`: %s: %s" % (r["name"], r["class"], r["detail"]))
    errors = [r for r in results if "error" in r]
    for r in errors:
        print("rs274-compare: ERROR: %s: %s" % (r["name"], r["error"]), file=sys.stderr)
    if errors:
        print("rs274-compare: %d of %d programs could not be compared (errors above)" % (len(errors), len(results)),
              file=sys.stderr)
    if args.write:
        if errors:
            raise SystemExit("rs274-compare: %s not written: the run had errors" % args.write)
        write_table(args.write, text)
    disagree = sum(1 for r in results if r.get("class") == "disagree")
    return 1 if disagree or errors else 0


if __name__ == "__main__":
    sys.exit(main())
