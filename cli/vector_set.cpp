// SPDX-License-Identifier: Apache-2.0
// A vector set's directory, written atomically (vector_set.hpp).
#include "cli/vector_set.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "cli/options/temp_files.hpp"
#include "model/datapath/errors.hpp"

namespace dda::vec {

namespace fs = std::filesystem;

namespace {

// The files of the vector set in `dir` that a replacement may remove: its manifest and
// the files the manifest lists. Anything else in the directory, or a manifest this tool
// did not write, and the directory is not replaced (InputError naming what is there).
std::vector<fs::path> set_files(const fs::path& dir, const std::string& out_dir) {
  const std::string what = "out-dir = '" + out_dir + "' is invalid: ";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(what + "it exists and is not a directory");
  if (fs::is_empty(dir, ec)) return {};
  nlohmann::json m;
  {
    std::ifstream in(dir / "manifest.json", std::ios::binary);
    if (!in) throw InputError(what + "it is not empty and holds no vector set (no manifest.json): nothing is replaced");
    m = nlohmann::json::parse(in, nullptr, false);
  }
  const bool ours = m.is_object() && m.contains("generator") && m["generator"].is_string() &&
                    m["generator"].get<std::string>().rfind("dda vectors", 0) == 0 && m.contains("files") &&
                    m["files"].is_object();
  if (!ours) throw InputError(what + "its manifest.json is not one `dda vectors` wrote: nothing is replaced");
  std::vector<fs::path> own{dir / "manifest.json"};
  for (const auto& [name, _] : m["files"].items()) {
    if (name.find('/') != std::string::npos || name == ".." || name == ".") {
      throw InputError(what + "its manifest lists '" + name + "', which is not a file of a set: nothing is replaced");
    }
    own.push_back(dir / name);
  }
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (std::find(own.begin(), own.end(), entry.path()) == own.end() || !entry.is_regular_file()) {
      throw InputError(what + "it holds '" + entry.path().filename().string() +
                       "', which is not a file of its vector set: nothing is replaced");
    }
  }
  return own;
}

}  // namespace

SetWriter::SetWriter(std::string out_dir) : out_dir_(std::move(out_dir)), dir_(out_dir_) {
  std::error_code ec;
  exists_ = fs::exists(fs::symlink_status(dir_, ec));
  if (exists_) old_files_ = set_files(dir_, out_dir_);
  cli::remove_stale_temps(dir_.string());
  tmp_ = dir_.parent_path() / (dir_.filename().string() + ".tmp." + std::to_string(::getpid()));
  cli::register_temp(tmp_.string());
  if (!fs::create_directories(tmp_, ec) || ec) {
    cli::release_temp(tmp_.string());
    throw GuardError("vectors: cannot create " + tmp_.string() + ": " + ec.message());
  }
}

SetWriter::~SetWriter() {
  if (!committed_) discard();
}

std::ostream& SetWriter::open(const std::string& name) {
  const fs::path p = tmp_ / name;
  cli::register_temp(p.string());
  files_.emplace_back(p, std::ofstream(p, std::ios::binary));
  if (!files_.back().second) throw GuardError("vectors: cannot write " + p.string());
  return files_.back().second;
}

void SetWriter::commit() {
  for (auto& [p, f] : files_) {
    f.close();
    if (!f) throw GuardError("vectors: cannot write " + p.string());
  }
  const std::string pid = std::to_string(::getpid());
  if (exists_) {
    std::error_code ec;
    const fs::path old = dir_.parent_path() / (dir_.filename().string() + ".old." + pid);
    fs::rename(dir_, old);
    fs::rename(tmp_, dir_);
    for (const fs::path& f : old_files_) fs::remove(old / f.filename(), ec);
    fs::remove(old, ec);
  } else {
    fs::rename(tmp_, dir_);
  }
  committed_ = true;
  for (const auto& [p, f] : files_) cli::release_temp(p.string());
  cli::release_temp(tmp_.string());
}

void SetWriter::discard() noexcept {
  std::error_code ec;
  for (auto& [p, f] : files_) {
    f.close();
    fs::remove(p, ec);
  }
  fs::remove(tmp_, ec);
  for (const auto& [p, f] : files_) cli::release_temp(p.string());
  cli::release_temp(tmp_.string());
}

void write_set(const std::string& out_dir, const std::vector<std::pair<std::string, std::string>>& files) {
  SetWriter w(out_dir);
  for (const auto& [name, text] : files) w.write(name, text);
  w.commit();
}

std::uint64_t parse_size(const std::string& name, const std::string& text) {
  const std::string rule = "a size in bytes (a whole number, optionally with K, M, G or T: binary multiples)";
  std::size_t digits = 0;
  while (digits < text.size() && text[digits] >= '0' && text[digits] <= '9') ++digits;
  const std::string unit = text.substr(digits);
  int shift = -1;
  if (unit.empty()) shift = 0;
  if (unit == "K" || unit == "k") shift = 10;
  if (unit == "M") shift = 20;
  if (unit == "G") shift = 30;
  if (unit == "T") shift = 40;
  if (digits == 0 || shift < 0) throw InputError(name + " = '" + text + "' is invalid: " + rule);
  if (digits > 15) throw InputError(name + " = '" + text + "' is out of range: at most 2^50 bytes");
  const std::uint64_t v = std::stoull(text.substr(0, digits));
  if (v == 0 || v > (std::uint64_t{1} << (50 - shift))) {
    throw InputError(name + " = '" + text + "' is out of range: from 1 byte to 2^50 bytes");
  }
  return v << shift;
}

std::string size_text(std::uint64_t bytes) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB"};
  double v = double(bytes);
  int u = 0;
  while (v >= 1024 && u < 5) v /= 1024, ++u;
  return u == 0 ? fmt::format("{} bytes", bytes) : fmt::format("{:.1f} {}", v, units[u]);
}

}  // namespace dda::vec
