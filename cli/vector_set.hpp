// SPDX-License-Identifier: Apache-2.0
// A vector set's directory, written atomically and one file at a time: the files go into
// a temporary directory beside the target (removed on an error or a signal), which
// commit() renames into place. An existing target is replaced only if it is a set this
// tool wrote holding nothing but the files its manifest lists, and only those go.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <list>
#include <string>
#include <utility>
#include <vector>

namespace dda::vec {

class SetWriter {
 public:
  // Checks the target (InputError naming what is in the way) and creates the temporary
  // directory.
  explicit SetWriter(std::string out_dir);
  ~SetWriter();
  SetWriter(const SetWriter&) = delete;
  SetWriter& operator=(const SetWriter&) = delete;
  // A new file of the set, open until commit().
  std::ostream& open(const std::string& name);
  void write(const std::string& name, const std::string& text) { open(name) << text; }
  // Closes every file (GuardError if one could not be written) and renames the set into place.
  void commit();

 private:
  void discard() noexcept;
  std::string out_dir_;
  std::filesystem::path dir_, tmp_;
  std::vector<std::filesystem::path> old_files_;
  bool exists_ = false, committed_ = false;
  std::list<std::pair<std::filesystem::path, std::ofstream>> files_;
};

// A whole set of (name, text) files through SetWriter.
void write_set(const std::string& out_dir, const std::vector<std::pair<std::string, std::string>>& files);

// The largest set `dda vectors` writes unless --max-size says otherwise, and the
// option's value: bytes, or with a binary suffix K, M, G or T (InputError if invalid).
constexpr std::uint64_t kDefaultMaxSetSize = std::uint64_t{1} << 30;
std::uint64_t parse_size(const std::string& name, const std::string& text);
// "1.5 GiB": a size for a message.
std::string size_text(std::uint64_t bytes);

}  // namespace dda::vec
