// SPDX-License-Identifier: Apache-2.0
#include "tb/engines/scoreboard.hpp"

#include <sstream>

namespace dda {

namespace {
// cmd_ready_o among the output ports.
constexpr std::size_t ready_out() {
  std::size_t o = 0;
  for (const auto& p : hw::kPorts) {
    if (p.name == "cmd_ready_o") return o;
    o += p.dir == hw::PortDir::Out;
  }
  throw "no cmd_ready_o";
}
constexpr std::size_t kReadyOut = ready_out();
}  // namespace

void Scoreboard::check_ports(const Signals& want, const PortValues& ports, std::uint64_t cycle) const {
  // The ports after the edge (cmd_ready_o, combinational, was compared before it).
  const PortValues want_ports = CoreModel::outputs(want, ports[kReadyOut] != 0);
  if (want_ports == ports) return;
  std::size_t o = 0;
  for (const auto& p : hw::kPorts) {
    if (p.dir != hw::PortDir::Out) continue;
    if (want_ports[o] != ports[o]) {
      std::ostringstream m;
      m << engine_ << " mismatch: output " << p.name << " at iteration " << iters_ << " (cycle " << cycle
        << "): golden " << want_ports[o] << ", " << engine_ << ' ' << ports[o];
      throw MismatchError(m.str());
    }
    ++o;
  }
}

void Scoreboard::after_edge(const CoreInputs& in, bool ready, const Signals& got, const PortValues& ports,
                            std::uint64_t cycle) {
  const CoreEdge e = model_.edge(in);
  iters_ += e.iterate;
  if (in.rst_n && e.ready != ready) {
    std::ostringstream m;
    m << engine_ << " mismatch: output cmd_ready_o before cycle " << cycle << ": golden " << e.ready << ", " << engine_
      << ' ' << ready;
    throw MismatchError(m.str());
  }
  const Signals& want = model_.state();
  if (want == got) {  // the common case: no message to build; then the ports
    check_ports(want, ports, cycle);
    return;
  }
  std::ostringstream m;
  int differ = 0;
  for (std::size_t i = 0; i < hw::kNumSignals; ++i) {
    if (want[i] == got[i]) continue;
    if (differ++ == 0) {
      m << engine_ << " mismatch: register " << hw::kSignals[i].name << " at iteration " << iters_ << " (cycle "
        << cycle << "): golden " << want[i] << ", " << engine_ << ' ' << got[i];
    } else {  // the others of the same edge, in table order: the cause may be among them
      m << (differ == 2 ? "; also " : ", ") << hw::kSignals[i].name << " (golden " << want[i] << ", " << engine_ << ' '
        << got[i] << ')';
    }
  }
  throw MismatchError(m.str());
}

std::string compare_samples(const Signals& a, const Signals& b) {
  for (std::size_t i = 0; i < hw::kNumSignals; ++i) {
    if (a[i] != b[i]) {
      std::ostringstream m;
      m << "register " << hw::kSignals[i].name << ": " << a[i] << " vs " << b[i];
      return m.str();
    }
  }
  return "";
}

}  // namespace dda
