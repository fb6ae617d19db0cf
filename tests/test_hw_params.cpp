// SPDX-License-Identifier: Apache-2.0
// One source of truth: the generated Verilog header and the design document's tables
// must equal what hw_params.hpp generates now, and the command packing must put every
// field where the header says.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "model/datapath/hw_command.hpp"
#include "model/datapath/hw_params.hpp"

namespace {
std::string read_file(const std::string& p) {
  std::ifstream f(p, std::ios::binary);
  REQUIRE(f.good());
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

std::uint64_t bits(const std::vector<std::uint32_t>& w, int lsb, int width) {
  std::uint64_t v = 0;
  for (int k = 0; k < width; ++k) {
    const int b = lsb + k;
    v |= std::uint64_t((w[b / 32] >> (b % 32)) & 1u) << k;
  }
  return v;
}
}  // namespace

TEST_CASE("hw_params: rtl/dda_params.vh is in sync with hw_params.hpp", "[hw_params][default-widths]") {
  INFO("regenerate with: dda gen-params --kind verilog --out rtl/dda_params.vh");
  CHECK(read_file(std::string(DDA_SOURCE_DIR) + "/rtl/dda_params.vh") == dda::hw::verilog_header());
}

TEST_CASE("hw_params: design doc tables match hw_params", "[hw_params][default-widths]") {
  const std::string doc = read_file(std::string(DDA_SOURCE_DIR) + "/docs/design.md");
  const std::string begin = "<!-- BEGIN GENERATED: dda gen-params --kind markdown -->\n";
  const auto i = doc.find(begin);
  const auto j = doc.find("<!-- END GENERATED -->", i);
  REQUIRE(i != std::string::npos);
  REQUIRE(j != std::string::npos);
  INFO("regenerate the block with: dda gen-params --kind markdown");
  CHECK(doc.substr(i + begin.size(), j - i - begin.size()) == dda::hw::markdown_tables());
}

TEST_CASE("hw_params: every command field lands at its offset", "[hw_params]") {
  dda::Command c;
  c.jv_x = 0x123456789ab;
  c.jv_y = 0x2fedcba9876;
  c.jr_x = 0x3;
  c.jr_y = (std::int64_t{1} << (dda::hw::kAccWidth - 1)) - 1;  // largest accumulator value
  c.cap = 0x1000000;
  c.cnt_x = 0x1abcd & dda::hw::kCntMax;  // all 17 bits at the default widths
  c.cnt_y = 1;
  c.dir_x_neg = true;
  c.dir_y_neg = false;
  c.inc_x_on_x = -1;
  c.inc_x_on_y = 100;
  c.inc_y_on_x = -36;
  c.inc_y_on_y = -(std::int64_t{1} << (dda::hw::kAccWidth - 1));
  const auto w = dda::hw::pack_command(c);
  REQUIRE(int(w.size()) * 32 >= dda::hw::kCmdWidth);
  const auto f = dda::hw::command_fields(c);
  int off = 0;
  for (std::size_t i = 0; i < dda::hw::kCmdFields.size(); ++i) {
    const auto& fd = dda::hw::kCmdFields[i];
    INFO("field " << fd.name);
    CHECK(dda::hw::cmd_offset(fd.name) == off);
    CHECK(bits(w, off, fd.width) == f[i]);
    off += fd.width;
  }
  CHECK(off == dda::hw::kCmdWidth);
  const std::uint64_t mask = dda::hw::kAccMask;
  CHECK(f[9] == mask);  // -1 in two's complement
  CHECK(f[11] == ((~std::uint64_t{36} + 1) & mask));
  CHECK(bits(w, dda::hw::cmd_offset("dir_x"), 1) == dda::hw::kDirNeg);
  // Nothing above the command's width.
  for (int b = dda::hw::kCmdWidth; b < int(w.size()) * 32; ++b) CHECK(((w[b / 32] >> (b % 32)) & 1u) == 0);
}

TEST_CASE("hw_params: values that do not fit the hardware are refused by name", "[hw_params]") {
  dda::Command c;
  // cap must stay below 2^(AccWidth-1): every integrand up to it is then positive.
  c.cap = std::int64_t{1} << (dda::hw::kAccWidth - 1);
  CHECK_THROWS_WITH(dda::hw::pack_command(c),
                    Catch::Contains("cap = ") && Catch::Contains(std::to_string(dda::hw::kAccWidth) + "-bit"));
  c.cap = (std::int64_t{1} << (dda::hw::kAccWidth - 1)) - 1;
  CHECK_NOTHROW(dda::hw::pack_command(c));
  c.cap = 10;
  c.cnt_y = std::int64_t{1} << dda::hw::kCntWidth;
  CHECK_THROWS_WITH(dda::hw::pack_command(c), Catch::Contains("cnt_y = "));
  c.cnt_y = 0;
  c.inc_y_on_x = std::int64_t{1} << (dda::hw::kAccWidth - 1);
  CHECK_THROWS_WITH(dda::hw::pack_command(c), Catch::Contains("inc_y_on_x = "));
}

TEST_CASE("hw_params: the default widths hold ellipses 2^16 steps across", "[hw_params][default-widths]") {
  // Semi-axes up to 32768 with half preload's four extra bits.
  CHECK(dda::hw::max_semi_axis(4) >= 32768);
  CHECK(dda::hw::max_semi_axis(0) >= dda::hw::max_semi_axis(4));
}
