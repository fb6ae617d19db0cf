#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Install the Debian packages this project builds and tests with, if any is missing.
# Safe to run again: it asks apt only when a package is absent.
set -euo pipefail

# What the dda command and the demo need (scripts/setup.sh --demo installs only these),
# then the verification and synthesis tools.
DEMO_PACKAGES=(
  build-essential cmake pkg-config
  libsystemc-dev verilator iverilog
  catch2 libcli11-dev nlohmann-json3-dev libfmt-dev tao-pegtl-dev
)
PACKAGES=(
  build-essential cmake pkg-config
  libsystemc-dev verilator iverilog yosys nextpnr-ice40 fpga-icestorm gtkwave
  fpga-icestorm-chipdb  # icetime: the device databases it times a routed design with
  catch2 libcli11-dev nlohmann-json3-dev libfmt-dev libbenchmark-dev
  z3 librsvg2-bin clang-format clang-tidy parallel tao-pegtl-dev python3
  clang libclang-rt-14-dev  # scripts/fuzz-program.sh: libFuzzer and the sanitizers
  time  # GNU time: peak memory in scripts/scale-table.sh and scripts/run-long-program.sh
  pybind11-dev python3-pybind11 python3-pytest  # python/: `import dda` and its tests
  cvc4 cvc5  # scripts/formal.sh --solver: the other SMT solvers yosys-smtbmc drives
)

if [ "${1:-}" = "--demo" ]; then PACKAGES=("${DEMO_PACKAGES[@]}"); fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
