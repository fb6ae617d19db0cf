#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Make LinuxCNC's standalone G-code interpreter `rs274` runnable, as the oracle of
# scripts/rs274-compare.py, with nothing from the network but the Debian archive:
# `apt-get download` Debian bookworm's linuxcnc-uspace (pinned below), `dpkg -x` it into a
# cache folder (nothing is installed system-wide but the few shared libraries rs274 links
# with), write a tool table, check that rs274 runs, and print the command that runs it.
# Idempotent: a second run finds the cache and only checks it.
#
#   usage: scripts/rs274-setup.sh [--quiet]
#   cache: ${RS274_CACHE:-$HOME/.cache/dda-rs274}
#     root/                  the extracted package (root/usr/bin/rs274, root/usr/lib/*.so.0,
#                            root/usr/share/linuxcnc/ncfiles: LinuxCNC's 185 example programs, GPL)
#     tool.tbl               tools 1 to 99, no length offset, no diameter
#     rs274                  a wrapper: LD_LIBRARY_PATH and a private HOME set, then rs274
#     VERSION                the package version the cache holds
# Standard output: one line, the command that runs rs274 on a program (append the
# program's path); everything else goes to standard error.
#
# Why the tool table: without `-t FILE` rs274 prints no canonical call at all and exits
# with status 1 (a missing FILE is accepted, as an empty table); with it, a program
# asking for a tool the table lacks ("Requested tool 4 not found in the tool table")
# is refused, hence 99 tools. D0: cutter radius compensation runs as programmed.
# rs274 maps the tool table into $HOME/.tool.mmap: two running at once with one HOME
# die of SIGBUS, so each gets its own HOME (the wrapper and scripts/rs274-compare.py do).
set -euo pipefail

PACKAGE=linuxcnc-uspace
VERSION='2.9.0~pre1+git20230208.f1270d6ed7-1+deb12u2'
# The shared libraries rs274 links with beyond its own (ldd of the binary above).
RUNTIME_PACKAGES=(libboost-python1.74.0 libpython3.11 libedit2 libtirpc3 libexpat1 zlib1g)

cache=${RS274_CACHE:-$HOME/.cache/dda-rs274}
quiet=0
case "${1:-}" in
  --quiet) quiet=1 ;;
  '') ;;
  -h|--help) sed -n '3,24p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
  *) echo "rs274-setup: unknown option '$1' (usage: scripts/rs274-setup.sh [--quiet])" >&2; exit 2 ;;
esac
say() { [ "$quiet" = 1 ] || echo "rs274-setup: $*" >&2; }
die() { echo "rs274-setup: error: $*" >&2; exit 1; }

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive

mkdir -p "$cache"
root=$cache/root
rs274=$root/usr/bin/rs274

# 1. The package, extracted once.
if [ -x "$rs274" ] && [ "$(cat "$cache/VERSION" 2>/dev/null)" = "$VERSION" ]; then
  say "the cache holds $PACKAGE $VERSION ($root)"
else
  work=$(mktemp -d "$cache/.download.XXXXXX")
  trap 'rm -rf "$work"' EXIT
  chmod 755 "$work"   # apt's _apt user writes the download here when we run as root
  say "downloading $PACKAGE=$VERSION from the Debian archive"
  if ! (cd "$work" && apt-get download -q "$PACKAGE=$VERSION" >"$work/log" 2>&1); then
    say "apt-get download failed; updating the package lists and trying again"
    $SUDO apt-get update -qq
    (cd "$work" && apt-get download -q "$PACKAGE=$VERSION" >"$work/log" 2>&1) ||
      { cat "$work/log" >&2; die "apt-get download $PACKAGE=$VERSION failed (is the bookworm archive in the sources?)"; }
  fi
  deb=$(find "$work" -maxdepth 1 -name "${PACKAGE}_*.deb" | head -n 1)
  [ -n "$deb" ] || die "apt-get download left no .deb in $work"
  say "extracting $(basename "$deb")"
  dpkg -x "$deb" "$work/root"
  [ -x "$work/root/usr/bin/rs274" ] || die "the package holds no usr/bin/rs274"
  rm -rf "$root"
  mv "$work/root" "$root"
  echo "$VERSION" >"$cache/VERSION"
fi

# 2. The shared libraries rs274 needs from the system.
missing=()
for p in "${RUNTIME_PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  say "installing ${missing[*]}"
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null 2>&1 || {
    $SUDO apt-get update -qq
    $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  }
fi
unresolved=$(LD_LIBRARY_PATH=$root/usr/lib ldd "$rs274" | awk '/not found/ { print $1 }' | tr '\n' ' ')
[ -z "$unresolved" ] || die "rs274 still misses the shared libraries: $unresolved"

# 3. The tool table and the wrapper (rewritten each time: cheap, and always current).
{
  echo "; rs274's tool table for scripts/rs274-compare.py: tools 1 to 99, no offset, no diameter"
  for t in $(seq 1 99); do echo "T$t P$t Z0 D0"; done
} >"$cache/tool.tbl.tmp"
mv "$cache/tool.tbl.tmp" "$cache/tool.tbl"
cat >"$cache/rs274.tmp" <<EOF
#!/bin/sh
# Written by scripts/rs274-setup.sh: LinuxCNC's rs274 from the extracted package, with a
# HOME of its own (rs274 maps its tool table into \$HOME/.tool.mmap; two runs sharing one die).
home=\$(mktemp -d) || exit 1
trap 'rm -rf "\$home"' EXIT
HOME=\$home LD_LIBRARY_PATH="$root/usr/lib\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}" "$rs274" "\$@"
EOF
chmod 755 "$cache/rs274.tmp"
mv "$cache/rs274.tmp" "$cache/rs274"

# 4. A smoke test: a line and an arc must come out as canonical calls.
probe=$(mktemp -d)
printf 'G21 G17 G90 F100\nG1 X10\nG3 X0 Y10 R10\nM2\n' >"$probe/probe.ngc"
out=$(cd "$probe" && "$cache/rs274" -g -t "$cache/tool.tbl" probe.ngc 2>"$probe/err" </dev/null) || {
  cat "$probe/err" >&2; rm -rf "$probe"; die "rs274 failed on a two-move program"; }
rm -rf "$probe"
if ! grep -q 'STRAIGHT_FEED(10.0000, 0.0000, 0.0000' <<<"$out" ||
   ! grep -Eq 'ARC_FEED\(0\.0000, 10\.0000, -?0\.0000, -?0\.0000, 1,' <<<"$out"; then
  die "rs274 ran but printed no line and arc for a two-move program: $out"
fi

ncfiles=$root/usr/share/linuxcnc/ncfiles
say "rs274 runs; $(find "$ncfiles" -name '*.ngc' | wc -l) example programs in $ncfiles"
echo "$cache/rs274 -g -t $cache/tool.tbl"
