// SPDX-License-Identifier: Apache-2.0
// The motion block's build-time choices (model/motion/build.hpp): the RTL's tops have
// exactly kBuildParams' parameters, in order; specs parse and refuse as documented.
#include <catch2/catch.hpp>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "model/datapath/errors.hpp"
#include "model/motion/build.hpp"

using namespace dda;
using namespace dda::motion;

namespace {

// The names of a module's parameters (its #( ... ) list) in rtl/FILE.
std::vector<std::string> rtl_parameters(const std::string& file) {
  std::ifstream in(std::string(DDA_SOURCE_DIR) + "/rtl/" + file);
  REQUIRE(in);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  const auto start = text.find("#(", text.find("\nmodule "));
  const auto end = text.find(") (", start);
  REQUIRE(start != std::string::npos);
  REQUIRE(end != std::string::npos);
  const std::string list = text.substr(start, end - start);
  std::vector<std::string> names;
  const std::regex param(R"(parameter\s+integer\s+(\w+))");
  for (auto it = std::sregex_iterator(list.begin(), list.end(), param); it != std::sregex_iterator(); ++it)
    names.push_back((*it)[1]);
  return names;
}

}  // namespace

TEST_CASE("build: the block's tops take kBuildParams' parameters, in order", "[build]") {
  std::vector<std::string> want;
  for (const auto& p : kBuildParams) want.emplace_back(p.rtl);
  for (const char* f : {"dda_motion.v", "dda_motion_axil.v", "dda_motion_spi.v"}) {
    INFO(f);
    CHECK(rtl_parameters(f) == want);
  }
}

TEST_CASE("build: a spec sets the choices it names, the others keep their defaults", "[build]") {
  const Build d = parse_build("");
  CHECK(d.depth_log2 == kMaxDepthLog2);
  CHECK(d.inputs);
  const Build b = parse_build("inputs=0,depth_log2=3");
  CHECK(b.depth_log2 == 3);
  CHECK(!b.inputs);
  CHECK(b.axes == 3);
  CHECK(b.pacer);
  CHECK(build_spec(b) == "depth_log2=3,inputs=0,axes=3,pacer=1");
  CHECK(parse_build(build_spec(b)).depth_log2 == 3);
  const auto p = rtl_params(b);
  REQUIRE(p.size() == kBuildParams.size());
  CHECK(p[0] == std::pair<std::string, int>{"DepthLog2", 3});
  CHECK(p[1] == std::pair<std::string, int>{"Inputs", 0});
  CHECK(p[2] == std::pair<std::string, int>{"Axes", 3});
  CHECK(p[3] == std::pair<std::string, int>{"Pacer", 1});
  CHECK(parse_build("axes=2").axes == 2);
  CHECK(!parse_build("pacer=0").pacer);
  for (const char* bad : {"inputs", "inputs=2", "inputs=-1", "depth_log2=0", "depth_log2=8", "axes=1", "axes=4",
                          "lathe=1", "pacer=2", "inputs=1,inputs=0", "inputs=1x", "inputs=", "inputs=0,"}) {
    INFO(bad);
    CHECK_THROWS_AS(parse_build(bad), InputError);
  }
}

TEST_CASE("build: the core's linear axis is the command's last fields, idle as a block of two axes reads it",
          "[build]") {
  // The RTL masks the fields from jv_z up (rtl/dda_motion.v, core_cmd): they must be
  // the last, in the order jv_z, jr_z, cap_z, cnt_z, dir_z.
  const std::size_t n = hw::kCmdFields.size();
  const std::array<std::string_view, 5> z{{"jv_z", "jr_z", "cap_z", "cnt_z", "dir_z"}};
  for (std::size_t i = 0; i < z.size(); ++i) CHECK(hw::kCmdFields[n - z.size() + i].name == z[i]);
  for (std::size_t i = 0; i + z.size() < n; ++i) CHECK(hw::kCmdFields[i].name.find("_z") == std::string_view::npos);
  CmdFields c{};
  for (std::size_t i = 0; i < n; ++i) c[i] = 5 + i;
  const CmdFields idle = idle_linear_axis(c);
  for (std::size_t i = 0; i < n; ++i) {
    INFO(hw::kCmdFields[i].name);
    const std::string_view name = hw::kCmdFields[i].name;
    CHECK(idle[i] == (i + z.size() < n ? c[i] : name == "cap_z" ? 1u : 0u));
  }
}
