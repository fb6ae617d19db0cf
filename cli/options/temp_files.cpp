// SPDX-License-Identifier: Apache-2.0
#include "cli/options/temp_files.hpp"

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>

namespace dda::cli {

namespace {

// Fixed slots the signal handler can read without allocating: each a strdup'ed path.
constexpr std::size_t kSlots = 256;
std::array<std::atomic<char*>, kSlots> g_paths{};
std::atomic<std::size_t> g_used{0};
std::mutex g_mutex;

extern "C" void on_signal(int sig) {
  for (std::size_t i = g_used.load(); i-- > 0;) {
    if (char* p = g_paths[i].load()) {
      if (::unlink(p) != 0) ::rmdir(p);
    }
  }
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

}  // namespace

void install_signal_cleanup() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (const int sig : {SIGINT, SIGTERM, SIGHUP}) ::signal(sig, on_signal);
  });
}

void register_temp(const std::string& path) {
  std::lock_guard<std::mutex> lock(g_mutex);
  const std::size_t n = g_used.load();
  for (std::size_t i = 0; i < n; ++i) {
    if (!g_paths[i].load()) {
      g_paths[i].store(::strdup(path.c_str()));
      return;
    }
  }
  if (n < kSlots) {
    g_paths[n].store(::strdup(path.c_str()));
    g_used.store(n + 1);
  }
}

void release_temp(const std::string& path) {
  std::lock_guard<std::mutex> lock(g_mutex);
  for (std::size_t i = 0; i < g_used.load(); ++i) {
    char* p = g_paths[i].load();
    if (p && path == p) {
      g_paths[i].store(nullptr);
      std::free(p);
    }
  }
}

void remove_stale_temps(const std::string& target) {
  namespace fs = std::filesystem;
  const fs::path t(target);
  const fs::path dir = t.parent_path().empty() ? fs::path(".") : t.parent_path();
  const std::string base = t.filename().string();
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    for (const char* tag : {".tmp.", ".old."}) {
      const std::string prefix = base + tag;
      if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
      const std::string pid = name.substr(prefix.size());
      if (pid.find_first_not_of("0123456789") != std::string::npos || pid.size() > 9) continue;
      const long n = std::strtol(pid.c_str(), nullptr, 10);
      if (n <= 0 || n == ::getpid() || ::kill(pid_t(n), 0) == 0 || errno != ESRCH) continue;
      std::error_code rm;
      fs::remove_all(it->path(), rm);
    }
  }
}

}  // namespace dda::cli
