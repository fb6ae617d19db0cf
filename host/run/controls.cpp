// SPDX-License-Identifier: Apache-2.0
#include "host/run/controls.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <termios.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "model/datapath/errors.hpp"

namespace dda::live {

namespace {
std::atomic<int> g_stops{0}, g_hold{0}, g_resume{0};
extern "C" void on_stop(int) { g_stops.fetch_add(1); }
extern "C" void on_hold(int) { g_hold.fetch_add(1); }
extern "C" void on_resume(int) { g_resume.fetch_add(1); }
struct sigaction g_old[4];
constexpr int kSignals[4] = {SIGINT, SIGTERM, SIGUSR1, SIGUSR2};
}  // namespace

SignalControls::SignalControls() {
  g_stops = g_hold = g_resume = 0;
  for (int k = 0; k < 4; ++k) {
    struct sigaction sa {};
    sa.sa_handler = k < 2 ? on_stop : k == 2 ? on_hold : on_resume;
    sigemptyset(&sa.sa_mask);
    sigaction(kSignals[k], &sa, &g_old[k]);
  }
}

SignalControls::~SignalControls() {
  for (int k = 0; k < 4; ++k) sigaction(kSignals[k], &g_old[k], nullptr);
}

std::optional<ControlRequest> SignalControls::poll(double) {
  const int stops = g_stops.load();
  if (stops > stops_seen_) {
    // (A second signal while the first one's soft stop runs: a hard stop.)
    const bool hard = stops_seen_ > 0 || stops > 1;
    stops_seen_ = stops;
    return ControlRequest{hard ? Control::HardStop : Control::SoftStop};
  }
  if (g_hold.load() > 0) {
    g_hold.fetch_sub(1);
    return ControlRequest{Control::Hold};
  }
  if (g_resume.load() > 0) {
    g_resume.fetch_sub(1);
    return ControlRequest{Control::Resume};
  }
  return std::nullopt;
}

struct TerminalControls::Saved {
  termios t;
};

TerminalControls::TerminalControls(int fd) : fd_(fd) {
  // (A run in the background of its terminal takes no keys: touching the terminal would
  // stop it, SIGTTOU.)
  // (A terminal that is not the process' controlling one has no foreground group: -1.)
  const pid_t fg = tcgetpgrp(fd_);
  if (fg > 0 && fg != getpgrp()) return;
  termios t{};
  if (tcgetattr(fd_, &t) != 0) return;
  saved_ = std::make_unique<Saved>(Saved{t});
  t.c_lflag &= tcflag_t(~(ICANON | ECHO));
  t.c_cc[VMIN] = 0;
  t.c_cc[VTIME] = 0;
  tcsetattr(fd_, TCSANOW, &t);
}

TerminalControls::~TerminalControls() {
  if (saved_) tcsetattr(fd_, TCSANOW, &saved_->t);
}

const char* TerminalControls::keys() {
  return "keys: '!' or space feed hold, '~' or 'r' resume, '+' '-' override by 10%, 's' soft stop, Ctrl-C soft stop "
         "(twice: hard stop)";
}

std::optional<ControlRequest> TerminalControls::poll(double) {
  if (!saved_) return std::nullopt;
  char c = 0;
  while (::read(fd_, &c, 1) == 1) {
    switch (c) {
      case '!':
      case ' ':
        return ControlRequest{Control::Hold};
      case '~':
      case 'r':
        return ControlRequest{Control::Resume};
      case '+':
        return ControlRequest{Control::OverrideUp};
      case '-':
        return ControlRequest{Control::OverrideDown};
      case 's':
        return ControlRequest{Control::SoftStop};
      default:
        break;  // (other keys do nothing)
    }
  }
  return std::nullopt;
}

ControlFile::ControlFile(const std::string& path) : path_(path), fd_(::open(path.c_str(), O_RDONLY | O_NONBLOCK)) {
  if (fd_ < 0) throw InputError("--control '" + path + "': cannot read it: " + std::strerror(errno));
}

ControlFile::~ControlFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::optional<std::string> ControlFile::next_line() {
  for (;;) {
    if (const auto nl = partial_.find('\n'); nl != std::string::npos) {
      std::string line = partial_.substr(0, nl);
      partial_.erase(0, nl + 1);
      return line;
    }
    char buf[512];
    const ssize_t n = ::read(fd_, buf, sizeof buf);
    // (0: the end for now, the file may grow or a FIFO's writer come; -1: EAGAIN or EINTR)
    if (n <= 0) return std::nullopt;
    partial_.append(buf, std::size_t(n));
  }
}

std::optional<ControlRequest> ControlFile::poll(double seconds) {
  for (;;) {
    if (waiting_) {
      if (seconds < waiting_->first) return std::nullopt;
      const ControlRequest r = waiting_->second;
      waiting_.reset();
      return r;
    }
    // The next whole line, as the file grows.
    std::optional<std::string> next = next_line();
    if (!next) return std::nullopt;
    std::string line = std::move(*next);
    ++line_;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string w;
    if (!(words >> w)) continue;
    const auto bad = [&](const std::string& why) {
      throw InputError(
          fmt::format("{}:{}: {} (a line: [@SECONDS] hold | resume | override PERCENT|+|- | stop | "
                      "hard-stop)",
                      path_, line_, why));
    };
    double at = 0;
    if (w[0] == '@') {
      char* end = nullptr;
      at = std::strtod(w.c_str() + 1, &end);
      if (w.size() < 2 || *end != '\0' || !(at >= 0)) bad("'" + w + "' is not a time in seconds");
      if (!(words >> w)) bad("a time without a request");
    }
    ControlRequest r;
    if (w == "hold") {
      r.what = Control::Hold;
    } else if (w == "resume") {
      r.what = Control::Resume;
    } else if (w == "stop") {
      r.what = Control::SoftStop;
    } else if (w == "hard-stop") {
      r.what = Control::HardStop;
    } else if (w == "override") {
      std::string v;
      if (!(words >> v)) bad("override needs a value");
      if (v == "+") {
        r.what = Control::OverrideUp;
      } else if (v == "-") {
        r.what = Control::OverrideDown;
      } else {
        char* end = nullptr;
        r.what = Control::Override;
        r.percent = std::strtod(v.c_str(), &end);
        if (*end != '\0' || !(r.percent >= 0 && r.percent <= 200)) bad("override '" + v + "': percent, 0 to 200");
      }
    } else {
      bad("'" + w + "' is not a request");
    }
    if (words >> w) bad("'" + w + "' after the request");
    waiting_ = std::make_pair(at, r);
  }
}

std::optional<ControlRequest> AllControls::poll(double seconds) {
  for (const auto& c : all_)
    if (std::optional<ControlRequest> r = c->poll(seconds)) return r;
  return std::nullopt;
}

}  // namespace dda::live
