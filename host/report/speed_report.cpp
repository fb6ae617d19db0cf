// SPDX-License-Identifier: Apache-2.0
#include "host/report/speed_report.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <nlohmann/json.hpp>

#include "host/report/json_stream.hpp"

namespace dda::speed {

namespace {

using program::BlockStatsFormat;

std::string block_no(const program::Move& mv) {
  return mv.block_number ? fmt::format("N{}", *mv.block_number) : std::string("-");
}

double per_min(double mm_s) { return mm_s * 60; }

}  // namespace

SpeedReport::SpeedReport(std::ostream& os, BlockStatsFormat fmt, const MachineLimits& lim, program::Machine m)
    : os_(os), fmt_(fmt), lim_(lim), machine_(m) {}

void SpeedReport::header() {
  if (started_) return;
  started_ = true;
  const double at = path_accel(lim_, machine_), an = normal_accel(lim_, machine_);
  if (fmt_ == BlockStatsFormat::Json) {
    nlohmann::ordered_json j;
    j["machine"] = machine_ == program::Machine::Mill ? "mill" : "lathe";
    j["path_accel_mm_per_s2"] = at;
    j["normal_accel_mm_per_s2"] = an;
    j["rapid_mm_per_min"] = lim_.rapid;
    j["junction_deviation_mm"] = lim_.junction_deviation;
    j["window"] = lim_.window;
    os_ << json_stream::open_object(j) << ",\n \"blocks\": [";
  } else if (fmt_ == BlockStatsFormat::Csv) {
    os_ << "line,block,kind,pieces,length_mm,feed_mm_min,entry_mm_min,cruise_mm_min,exit_mm_min,time_s,dwell_s,rest,"
           "limit\n";
  } else {
    fmt::print(os_,
               "speeds in mm/min; path acceleration {:.4g} mm/s^2, centripetal {:.4g} mm/s^2, rapid {:.6g} mm/min, "
               "junction deviation {:.6g} mm, lookahead {} pieces\n",
               at, an, lim_.rapid, lim_.junction_deviation, lim_.window);
    fmt::print(os_, "| {:>5} | {:>6} | {:<11} | {:>10} | {:>9} | {:>9} | {:>9} | {:>9} | {:>9} | {:>4} | {:<9} |\n",
               "line", "block", "kind", "length mm", "feed", "entry", "cruise", "exit", "time s", "rest", "limit");
    fmt::print(os_,
               "|-------|--------|-------------|------------|-----------|-----------|-----------|-----------|--------"
               "---|------|-----------|\n");
  }
}

void SpeedReport::block(const BlockSpeeds& b) {
  header();
  const program::Move& mv = b.move;
  const char* rest = b.stop ? "yes" : "no";
  if (fmt_ == BlockStatsFormat::Json) {
    nlohmann::ordered_json r;
    r["line"] = mv.pos.line;
    r["block"] = block_no(mv);
    r["kind"] = std::string(program::kind_name(mv.kind));
    r["pieces"] = b.pieces;
    r["length_mm"] = b.length;
    r["feed_mm_min"] = per_min(b.feed);
    r["entry_mm_min"] = per_min(b.entry);
    r["cruise_mm_min"] = per_min(b.cruise);
    r["exit_mm_min"] = per_min(b.exit);
    r["time_s"] = b.time;
    r["dwell_s"] = b.dwell;
    r["rest"] = b.stop;
    r["limit"] = to_string(b.limit);
    os_ << (rows_ == 0 ? "\n" : ",\n") << json_stream::element(r, 2);
  } else if (fmt_ == BlockStatsFormat::Csv) {
    fmt::print(os_, "{},{},{},{},{:.6f},{:.3f},{:.3f},{:.3f},{:.3f},{:.6f},{:.6f},{},{}\n", mv.pos.line, block_no(mv),
               program::kind_name(mv.kind), b.pieces, b.length, per_min(b.feed), per_min(b.entry), per_min(b.cruise),
               per_min(b.exit), b.time, b.dwell, rest, to_string(b.limit));
  } else {
    fmt::print(os_,
               "| {:>5} | {:>6} | {:<11} | {:>10.4f} | {:>9.2f} | {:>9.2f} | {:>9.2f} | {:>9.2f} | {:>9.4f} | {:>4} | "
               "{:<9} |\n",
               mv.pos.line, block_no(mv), program::kind_name(mv.kind), b.length, per_min(b.feed), per_min(b.entry),
               per_min(b.cruise), per_min(b.exit), b.time, rest, to_string(b.limit));
  }
  ++rows_;
}

void SpeedReport::finish(const SpeedTotals& t) {
  header();
  if (fmt_ == BlockStatsFormat::Json) {
    nlohmann::ordered_json j;
    j["blocks"] = t.blocks;
    j["pieces"] = t.pieces;
    j["length_mm"] = t.length;
    j["time_s"] = t.time;
    j["dwell_s"] = t.dwell;
    os_ << (rows_ == 0 ? "]" : "\n ]") << ",\n \"totals\": " << json_stream::nested(j, 1) << "\n}\n";
  } else if (fmt_ == BlockStatsFormat::Text) {
    fmt::print(os_, "blocks: {}\npieces: {}\nlength_mm: {:.4f}\ntime_s: {:.4f}\ndwell_s: {:.4f}\n", t.blocks, t.pieces,
               t.length, t.time, t.dwell);
  }
}

}  // namespace dda::speed
