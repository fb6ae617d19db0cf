# SPDX-License-Identifier: Apache-2.0
"""LinuxCNC's rs274 for scripts/rs274-compare.py: running it on a program (from the cache
scripts/rs274-setup.sh fills) and reading its canonical calls into motion blocks in
machine millimetres, the offsets applied as LinuxCNC's emccanon.cc applies them."""

import math
import os
import re
import subprocess
import tempfile

MOTION_CALLS = ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED", "ARC_FEED", "STRAIGHT_PROBE", "RIGID_TAP", "NURBS_FEED")
KIND_OF_CALL = {
    "STRAIGHT_TRAVERSE": "rapid",
    "STRAIGHT_FEED": "line",
    "STRAIGHT_PROBE": "probe",
    "RIGID_TAP": "rigid tap",
    "NURBS_FEED": "nurbs",
}
MM_PER_INCH = 25.4
PRINT_HALF_ULP = 0.00005  # rs274 prints %.4f: half a unit of its last digit
EOF_REFUSAL = "File ended with no percent sign or program end"

# One canonical call: "%5d " sequence number, the block's N word ("N....." when none,
# else N and its digits padded to 6), the call and its arguments.
CANON_LINE = re.compile(r"^\s*\d+ (?:N(?:\.\.\.\.\.|\d*) *)?([A-Za-z_][A-Za-z0-9_.]*)\((.*)\)\s*$")
NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")

class RunError(Exception):
    """A failure of the comparison's run, not a classification."""


# ---------------------------------------------------------------------------- rs274


class Offset:
    """An offset in millimetres and the print error it carries."""

    def __init__(self):
        self.v = [0.0, 0.0, 0.0]
        self.err = 0.0

    def set(self, values, unit):
        self.v = [x * unit for x in values[:3]]
        self.err = PRINT_HALF_ULP * unit if any(values[:3]) else 0.0


def parse_rs274(text):
    """rs274's standard output -> (number of canonical calls, motion blocks in machine mm)."""
    unit = 1.0
    plane = 17
    g5x, g92, tool = Offset(), Offset(), Offset()
    rotation = 0.0
    calls = 0
    blocks = []
    for raw in text.splitlines():
        m = CANON_LINE.match(raw)
        if not m:
            if any(c + "(" in raw for c in MOTION_CALLS):
                raise RunError("rs274 printed a motion call this script cannot read: " + raw.strip())
            continue
        calls += 1
        name, args = m.group(1), m.group(2)
        if name == "USE_LENGTH_UNITS":
            unit = MM_PER_INCH if "INCHES" in args else 1.0
            if "UNKNOWN" in args:
                raise RunError("rs274 printed " + raw.strip())
        elif name == "SELECT_PLANE":
            plane = {"CANON_PLANE_XY": 17, "CANON_PLANE_XZ": 18, "CANON_PLANE_YZ": 19}.get(args.strip())
            if plane is None:
                raise RunError("rs274 printed an unknown plane: " + raw.strip())
        elif name == "SET_G5X_OFFSET":
            g5x.set(floats(args)[1:], unit)
        elif name == "SET_G92_OFFSET":
            g92.set(floats(args), unit)
        elif name == "USE_TOOL_LENGTH_OFFSET":
            tool.set(floats(args), unit)
        elif name == "SET_XY_ROTATION":
            rotation = floats(args)[0]
        elif name in MOTION_CALLS:
            blocks.append(motion_block(name, floats(args), raw.strip(), unit, plane, g5x, g92, tool, rotation))
    return calls, blocks


def floats(args):
    return [float(x) for x in NUMBER.findall(args)]


def motion_block(name, a, raw, unit, plane, g5x, g92, tool, rotation):
    block = {"kind": KIND_OF_CALL.get(name), "plane": plane, "center": None, "turns": 0, "raw": raw}
    if name == "ARC_FEED":
        fe, se, fa, sa, rot, ne = a[:6]
        rot = int(rot)
        block["kind"] = "arc cw" if rot < 0 else "arc ccw"
        block["turns"] = abs(rot)
        if plane == 17:
            end, centre = (fe, se, ne), (fa, sa, ne)
        elif plane == 18:
            end, centre = (se, ne, fe), (sa, ne, fa)
        else:
            end, centre = (ne, fe, se), (ne, fa, sa)
    elif name == "NURBS_FEED":
        end = centre = None
    else:
        end, centre = tuple(a[:3]), None
    block["to"], block["tol"] = to_machine(end, unit, g5x, g92, tool, rotation) if end else (None, 0.0)
    if centre is not None:
        block["center"] = to_machine(centre, unit, g5x, g92, tool, rotation)[0]
    return block


def to_machine(p, unit, g5x, g92, tool, rotation):
    """A program point (in the unit in force) -> machine mm, and its print error in mm."""
    x, y, z = (c * unit + o for c, o in zip(p, g92.v))
    err = PRINT_HALF_ULP * unit + g92.err + g5x.err + tool.err
    if rotation:
        t = math.radians(rotation)
        x, y = x * math.cos(t) - y * math.sin(t), x * math.sin(t) + y * math.cos(t)
        err += math.hypot(x, y) * math.radians(PRINT_HALF_ULP)
    return [x + g5x.v[0] + tool.v[0], y + g5x.v[1] + tool.v[1], z + g5x.v[2] + tool.v[2]], err


def rs274_input(program, machine, tmp):
    """The file rs274 reads: the program, or for a lathe a copy with G18 put first."""
    if machine != "lathe":
        return program
    with open(program, "rb") as f:
        lines = f.read().splitlines(keepends=True)
    at = 0
    while at < len(lines) and not lines[at].strip():
        at += 1
    at = at + 1 if at < len(lines) and lines[at].strip().startswith(b"%") else 0
    lines.insert(at, b"G18\n")
    copy = os.path.join(tmp, os.path.basename(program))
    with open(copy, "wb") as f:
        f.writelines(lines)
    return copy


def run_rs274(args, program, machine):
    root = os.path.join(args.cache, "root")
    with tempfile.TemporaryDirectory(prefix="rs274-") as tmp:
        # HOME: rs274 maps its tool table into $HOME/.tool.mmap; two at once on one file
        # die of SIGBUS, so each gets its own.
        env = dict(os.environ, LD_LIBRARY_PATH=os.path.join(root, "usr", "lib"), HOME=tmp)
        cmd = [os.path.join(root, "usr", "bin", "rs274"), "-g", "-t", os.path.join(args.cache, "tool.tbl")]
        if args.subroutine_path:
            ini = os.path.join(tmp, "rs274.ini")
            with open(ini, "w") as f:
                f.write("[RS274NGC]\nSUBROUTINE_PATH = %s\n" % args.subroutine_path)
            cmd += ["-i", ini]
        cmd.append(rs274_input(os.path.abspath(program), machine, tmp))
        try:
            p = subprocess.run(cmd, cwd=os.path.dirname(os.path.abspath(program)), env=env,
                               stdin=subprocess.DEVNULL, capture_output=True, timeout=args.timeout)
        except subprocess.TimeoutExpired:
            raise RunError("rs274 timed out after %g s" % args.timeout)
    out = p.stdout.decode("utf-8", "replace")
    err = [line for line in p.stderr.decode("utf-8", "replace").splitlines() if line.strip()]
    # rs274 writes "executing" (no newline) to stderr first; an error adds the message and
    # the offending line, and the exit status is 1.
    if err and err[0].startswith("executing"):
        err[0] = err[0][len("executing"):]
        err = [line for line in err if line.strip()]
    calls, blocks = parse_rs274(out)
    if calls == 0:
        raise RunError("rs274 printed no canonical call at all (exit status %d; is its tool table there?)%s"
                       % (p.returncode, ": " + err[0] if err else ""))
    if p.returncode < 0:
        raise RunError("rs274 died of signal %d" % -p.returncode)
    if p.returncode not in (0, 1) or (p.returncode == 1) != bool(err):
        raise RunError("rs274 exited with status %d and %s on stderr" % (p.returncode, err or "nothing"))
    accepted = p.returncode == 0 or (args.eof_ends_program and err and err[0].startswith(EOF_REFUSAL))
    return {"accepted": accepted, "message": " | ".join(err), "blocks": blocks}
