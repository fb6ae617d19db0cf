// SPDX-License-Identifier: Apache-2.0
// The program reader's flow (docs/programs.md, "Dialects" and "Macros"): the dialect
// detected, the structure read in a first pass, then the lines run a line at a time:
// HNC's statements and M98 calls, Fanuc's M98 calls, LinuxCNC's O-words.
#include <fmt/format.h>

#include <cctype>
#include <filesystem>
#include <string>

#include "host/program/reader.hpp"

namespace dda::program::detail {

Reader::Reader(std::istream& in, const std::string& file, const ReadOptions& opt, const Output& out)
    : file_(file), opt_(opt), out_(out), macro_(file), main_(in, file) {
  if (opt.start) sum_.start = *opt.start;
}

ReadSummary Reader::run() {
  dialect_ = opt_.dialect ? *opt_.dialect : detect();
  sum_.dialect = dialect_;
  src_->lines.set_dialect(dialect_);
  macro_.set_dialect(dialect_);
  sync_params();  // (#<_x> and the others hold before the first move)
  // A lathe's X is a diameter on HNC's and Fanuc's controls; LinuxCNC reads a radius
  // until G7.
  m_.diameter = opt_.machine == Machine::Lathe && dialect_ != Dialect::LinuxCnc;
  if (opt_.machine == Machine::Lathe) m_.plane = 180;
  main_.st = structure(main_.lines, file_, dialect_);  // pass 1: every line parsed, the statements matched
  // Pass 2. The main program: the first with a word or a statement; the others are called.
  for (const ProgramText& p : src_->st.programs) {
    if (p.content) {
      exec(p.begin, p.end, 0);
      break;
    }
  }
  if (dialect_ == Dialect::LinuxCnc && !sum_.ended && !src_->st.closed) {
    fail(SourcePos{src_->st.last_line, 1},
         "the program ends without M02, M30 or a closing '%' (LinuxCNC refuses it: end it with M30)");
  }
  fix_lattice();
  sum_.plane = lattice_;
  sum_.dwell_after = dwell_;
  return std::move(sum_);
}

namespace {

// A line's text without its comments, in upper case, from its first character that is
// not a blank, '/' or an N word.
std::string code_of(const std::string& raw) {
  std::string s;
  int depth = 0;
  for (const char c : raw) {
    if (c == ';' && depth == 0) break;
    if (c == '(') ++depth;
    if (depth == 0) s += char(std::toupper(static_cast<unsigned char>(c)));
    if (c == ')' && depth > 0) --depth;
  }
  std::size_t i = s.find_first_not_of(" \t/");
  if (i != std::string::npos && s[i] == 'N') {
    i = s.find_first_not_of("0123456789. \t", i + 1);
  }
  return i == std::string::npos ? std::string() : s.substr(i);
}

bool starts_word(const std::string& s, const char* kw) {
  const std::size_t n = std::char_traits<char>::length(kw);
  return s.compare(0, n, kw) == 0 && (s.size() == n || std::isalnum(static_cast<unsigned char>(s[n])) == 0);
}

// The G codes of a line, as numbers in tenths (G6.2: 62).
bool has_g(const std::string& s, std::initializer_list<int> codes) {
  for (std::size_t i = 0; (i = s.find('G', i)) != std::string::npos; ++i) {
    std::size_t j = s.find_first_not_of(" \t", i + 1);
    if (j == std::string::npos || std::isdigit(static_cast<unsigned char>(s[j])) == 0) continue;
    int t = 0;
    while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j])) != 0 && t < 100000)
      t = 10 * t + (s[j++] - '0');
    t *= 10;
    if (j + 1 < s.size() && s[j] == '.' && std::isdigit(static_cast<unsigned char>(s[j + 1])) != 0) t += s[j + 1] - '0';
    for (const int c : codes)
      if (t == c) return true;
  }
  return false;
}

// The dialect a line shows, if any (docs/programs.md, "Dialects").
std::optional<Dialect> dialect_of(const std::string& code) {
  if (code.find("#<") != std::string::npos) return Dialect::LinuxCnc;
  if (!code.empty() && code[0] == 'O') {
    std::size_t j = code.find_first_not_of(" \t", 1);
    if (j != std::string::npos && code[j] == '<') return Dialect::LinuxCnc;
    const std::size_t k = code.find_first_not_of("0123456789", j);
    if (k != j) {
      const std::size_t a = code.find_first_not_of(" \t", k);
      if (a == std::string::npos) return Dialect::Fanuc;
      if (std::isalpha(static_cast<unsigned char>(code[a])) != 0) return Dialect::LinuxCnc;
    }
  }
  if (!code.empty() && code[0] == '%' && code.size() > 1 && std::isdigit(static_cast<unsigned char>(code[1])) != 0) {
    return Dialect::Hnc;
  }
  if (starts_word(code, "WHILE") || starts_word(code, "IF")) {
    const bool fanuc = code.find("GOTO") != std::string::npos || code.find("THEN") != std::string::npos ||
                       code.find("DO") != std::string::npos;
    return fanuc ? Dialect::Fanuc : Dialect::Hnc;
  }
  if (starts_word(code, "ENDW") || starts_word(code, "ENDIF") || starts_word(code, "ELSE")) return Dialect::Hnc;
  if (has_g(code, {62, 63, 360, 370})) return Dialect::Hnc;
  if (has_g(code, {70, 80})) return Dialect::LinuxCnc;
  return std::nullopt;
}

}  // namespace

// The first line that only one dialect reads decides, but a Fanuc program number line
// ('O1234' alone, which LinuxCNC reads as a title) gives way to an O-word statement or a
// named parameter anywhere after it; a program without any is LinuxCNC's on a mill and
// HNC's on a lathe.
Dialect Reader::detect() {
  std::string raw;
  std::optional<Dialect> fanuc;
  for (LinePos at = src_->lines.first();;) {
    const LinePos next = src_->lines.read_raw(at, raw);
    const std::optional<Dialect> d = dialect_of(code_of(raw));
    if (d == Dialect::Fanuc) {
      if (!fanuc) fanuc = d;
    } else if (d && (!fanuc || d == Dialect::LinuxCnc)) {
      return *d;
    }
    if (src_->lines.at_end()) break;
    at = next;
  }
  if (fanuc) return *fanuc;
  return opt_.machine == Machine::Lathe ? Dialect::Hnc : Dialect::LinuxCnc;
}

// Runs the lines from `begin` to the one before line `end`, each read when it runs:
// statements steer, blocks move (and call).
void Reader::exec(const LinePos& begin, std::size_t end, int depth) {
  Line l;
  for (LinePos pc = begin; pc.number < end;) {
    const LinePos next = src_->lines.read(pc, l);
    if (++executed_ > opt_.max_lines) {
      fail(SourcePos{l.number, 1},
           fmt::format("more than {} lines executed: a loop that does not end?", opt_.max_lines));
    }
    if (l.block_delete && opt_.block_delete) {
      pc = next;
      continue;
    }
    if (l.stmt != Stmt::None) {
      pc = step(l, pc, next, depth);
    } else {
      block(l);
      pc = next;
    }
    if (sum_.ended) return;
    if (return_) {
      return_ = false;
      if (depth == 0 && dialect_ == Dialect::LinuxCnc && l.stmt == Stmt::None) {
        sum_.ended = true;  // M99 in the main program ends it, as rs274 (LinuxCNC's task runs it again)
        return;
      }
      if (depth == 0) {
        fail(l.stmt == Stmt::None ? SourcePos{l.number, 1} : l.stmt_pos,
             l.stmt == Stmt::None ? "M99 in the main program: no caller to return to"
                                  : "o" + l.oname + ": a return outside a call");
      }
      return;
    }
    if (call_) {
      const Call c = *call_;
      call_.reset();
      call(c, depth);
      if (sum_.ended) return;
    }
  }
}

// A statement line at `at`: where the program goes on.
LinePos Reader::step(const Line& l, const LinePos& at, const LinePos& next, int depth) {
  if (is_oword(l.stmt)) return o_step(l, at, next, depth);
  const auto match = [&]() -> const StmtMark& { return src_->st.marks[src_->st.mark(at.offset).jump]; };
  switch (l.stmt) {
    case Stmt::Assign:
      macro_.assign(l);
      return next;
    case Stmt::While:  // a false condition goes past its ENDW, or its ELSE or ENDIF
    case Stmt::If:
      return macro_.truth(l) ? next : match().next;
    case Stmt::EndW:  // back to its WHILE's test
      return match().at;
    case Stmt::Else:  // the end of the IF's true branch: past its ENDIF
      return match().next;
    default:
      return next;
  }
}

// An if chain's branch from mark `i` on (an elseif or else reached by a false
// condition): the first elseif whose condition holds, the else, or past the endif.
LinePos Reader::o_branch(std::size_t i) {
  Line l;
  while (src_->st.marks[i].stmt == Stmt::OElseIf) {
    src_->lines.read(src_->st.marks[i].at, l);
    if (macro_.truth(l)) return src_->st.marks[i].next;
    i = src_->st.marks[i].jump;
  }
  return src_->st.marks[i].next;
}

// LinuxCNC's O-words (docs/programs.md, "Dialects").
LinePos Reader::o_step(const Line& l, const LinePos& at, const LinePos& next, int depth) {
  const std::size_t i = std::size_t(&src_->st.mark(at.offset) - src_->st.marks.data());
  const StmtMark& m = src_->st.marks[i];
  const auto after = [&](std::size_t k) { return src_->st.marks[k].next; };
  switch (l.stmt) {
    case Stmt::OSub:  // a definition: skipped where it stands
      return after(m.jump);
    case Stmt::OEndSub:
    case Stmt::OReturn:
      macro_.set_named("_value", l.value >= 0 ? macro_.eval(l, l.value) : 0);  // (none: 0, as LinuxCNC)
      macro_.set_named("_value_returned", l.value >= 0 ? 1 : 0);
      return_ = true;
      return next;
    case Stmt::OCall:
      o_call(l, depth);
      return next;
    case Stmt::OIf:
      return macro_.truth(l) ? next : o_branch(m.jump);
    case Stmt::OElseIf:  // reached at the end of a branch taken: past the endif
    case Stmt::OElse:
      return after(m.end);
    case Stmt::OWhile:
      if (m.do_tail) return macro_.truth(l) ? after(m.jump) : next;
      return macro_.truth(l) ? next : after(m.jump);
    case Stmt::OEndWhile:
      return src_->st.marks[m.jump].at;
    case Stmt::ORepeat: {
      const double n = macro_.eval(l, l.value);
      repeats_[i] = std::int64_t(std::llround(n));
      return repeats_[i] > 0 ? next : after(m.jump);
    }
    case Stmt::OEndRepeat:
      return --repeats_[m.jump] > 0 ? after(m.jump) : next;
    case Stmt::OBreak: {
      const StmtMark& head = src_->st.marks[m.jump];
      return after(head.jump);  // past the loop's end (a do loop's closing while)
    }
    case Stmt::OContinue: {
      const StmtMark& head = src_->st.marks[m.jump];
      // A while loop tests again; a do loop tests at its tail.
      return head.stmt == Stmt::OWhile ? head.at : src_->st.marks[head.jump].at;
    }
    default:
      return next;
  }
}

// o<name> call [a] [b] ...: the subroutine of the file runs with #1, #2 ... its arguments.
void Reader::o_call(const Line& l, int depth) {
  // A computed name: the number the parameter holds (o#<sub> call with #<sub> = 2: o2).
  const std::string name = l.oname == "#" ? std::to_string(std::llround(macro_.eval(l, l.target))) : l.oname;
  if (l.args.size() > std::size_t(kCallArgs)) fail(l.stmt_pos, fmt::format("more than {} arguments", kCallArgs));
  std::vector<double> args;
  for (const int a : l.args) args.push_back(macro_.eval(l, a));
  run_sub(name, args, l.stmt_pos, depth);
}

// Runs o<name> sub of this text, or of the file name.ngc beside the program.
void Reader::run_sub(const std::string& name, const std::vector<double>& args, const SourcePos& at, int depth) {
  Source* const caller = src_;
  auto it = src_->st.subs.find(name);
  if (it == src_->st.subs.end()) {
    Source* f = subroutine_file(name, at);
    it = f->st.subs.find(name);
    src_ = f;
    macro_.set_file(f->file);
  }
  if (depth + 1 > kMaxCallDepth) fail(at, fmt::format("subprogram calls nested deeper than {}", kMaxCallDepth));
  const StmtMark& sub = src_->st.marks[it->second];
  macro_.push_frame(args);
  call_saved_.emplace_back();
  exec(sub.next, src_->st.marks[sub.jump].at.number + 1, depth + 1);
  if (call_saved_.back()) m_ = *call_saved_.back();  // M73's state comes back
  call_saved_.pop_back();
  macro_.pop_frame();
  src_ = caller;
  macro_.set_file(caller->file);
}

// A subroutine LinuxCNC would find in its subroutine path: the file <name>.ngc (the name
// without its angle brackets) in the program's folder or, failing that, in the folders
// of --subroutine-path in order, read and structured once, which must define o<name> sub.
Reader::Source* Reader::subroutine_file(const std::string& name, const SourcePos& at) {
  if (const auto it = files_.find(name); it != files_.end()) return it->second.get();
  const std::string bare = name.front() == '<' ? name.substr(1, name.size() - 2) : name;
  std::vector<std::filesystem::path> dirs{main_.file == "<stdin>" ? std::filesystem::path(".")
                                                                  : std::filesystem::path(main_.file).parent_path()};
  for (const std::string& d : opt_.subroutine_path) dirs.emplace_back(d);
  std::filesystem::path path;
  std::string tried;
  for (const auto& dir : dirs) {
    const std::filesystem::path p = dir / (bare + ".ngc");
    std::error_code ec;
    if (std::filesystem::is_regular_file(p, ec)) {
      path = p;
      break;
    }
    tried += (tried.empty() ? "" : ", ") + p.string();
  }
  if (path.empty()) {
    fail(at, "o" + name + " call: no o" + name + " sub in this program, nor a file " + tried +
                 " (the program's folder, then --subroutine-path)");
  }
  auto src = std::make_unique<Source>(open_program(path.string()), path.string());
  src->lines.set_dialect(dialect_);
  src->st = structure(src->lines, src->file, dialect_);
  if (!src->st.subs.count(name)) fail(at, "o" + name + " call: " + path.string() + " defines no o" + name + " sub");
  return files_.emplace(name, std::move(src)).first->second.get();
}

// M98: runs the subprogram c.program c.repeats times.
void Reader::call(const Call& c, int depth) {
  std::size_t target = src_->st.programs.size();
  for (std::size_t i = 0; i < src_->st.programs.size(); ++i) {
    if (src_->st.programs[i].number == c.program) target = i;
  }
  const char* sign = dialect_ == Dialect::Hnc ? "%" : "O";
  if (target == src_->st.programs.size())
    fail(c.pos, fmt::format("M98 calls program {}{}: there is none", sign, c.program));
  if (depth + 1 > kMaxCallDepth) {
    fail(c.pos, fmt::format("subprogram calls nested deeper than {}", kMaxCallDepth));
  }
  for (std::int64_t k = 0; k < c.repeats && !sum_.ended; ++k) {
    if (dialect_ == Dialect::Hnc) {
      // #30 and #32 (lathe: X as programmed and Z) or #30 and #31 (mill: the plane's
      // first and second axes) hold the current position at each call, in the
      // program's unit (G20/G21).
      fix_lattice();
      const PlaneAxes pa = plane_axes(lattice_);
      const bool lathe = opt_.machine == Machine::Lathe;
      const double unit = double(kNmPerMm) * (m_.inch ? 25.4 : 1.0);
      const double u = double(pos_[std::size_t(pa.u)]) / unit, v = double(pos_[std::size_t(pa.v)]) / unit;
      macro_.set(30, lathe ? (m_.diameter ? 2 * v : v) : u);
      macro_.set(lathe ? 32 : 31, lathe ? u : v);
    }
    exec(src_->st.programs[target].begin, src_->st.programs[target].end, depth + 1);
  }
}

}  // namespace dda::program::detail
