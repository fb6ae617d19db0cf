// SPDX-License-Identifier: Apache-2.0
// The programs' structure (host/program/macro/macro.hpp), read in the reader's first pass: the
// programs of a file (HNC's '%N', Fanuc's 'O1234', LinuxCNC's '%' text), HNC's
// WHILE/ENDW and IF/ELSE/ENDIF and LinuxCNC's O-words matched, kept as the offsets of
// the lines that steer the run.
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <optional>

#include "host/program/macro/macro.hpp"

namespace dda::program::detail {

namespace {

// Builds the structure line by line; keeps the first error of each kind, thrown once
// every line has been parsed (a syntax error anywhere comes first).
class Builder {
 public:
  Builder(const std::string& file, const LinePos& first, Dialect d) : file_(file), dialect_(d) { cur_.begin = first; }
  // Returns false at the line that ends the text read (LinuxCNC's and Fanuc's closing '%').
  bool add(const Line& l, const LinePos& at, const LinePos& next);
  Structure finish(std::size_t end);  // end: the last line's number + 1

 private:
  void close(std::size_t end);  // the program being read ends before line `end`
  void match(const Line& l, const LinePos& at, const LinePos& next);
  void o_match(const Line& l, std::size_t i);
  void o_close(const Line& l, std::size_t i, std::initializer_list<Stmt> opens, const char* what);
  std::optional<std::size_t> o_enclosing(const Line& l, bool sub) const;
  void defer(std::optional<ProgramError>& first, const SourcePos& p, const std::string& msg) const {
    if (!first) first.emplace(file_, p.line, p.column, msg);
  }
  std::string file_;
  Dialect dialect_;
  Structure st_;
  ProgramText cur_;                              // the program being read
  std::map<std::int64_t, std::size_t> headers_;  // a program's number: its header's line
  std::vector<std::size_t> open_;                // its open WHILE and IF marks (an IF's ELSE replaces it)
  struct OOpen {
    std::size_t mark;
    std::string name;
    std::vector<std::size_t> chain;  // an if's marks so far
  };
  std::vector<OOpen> o_open_;                      // open O-word blocks
  std::vector<ProgramText> labels_;                // LinuxCNC's numbered labels (M98's subprograms)
  std::optional<ProgramError> twice_, unmatched_;  // a program defined twice; a statement unmatched
};

bool Builder::add(const Line& l, const LinePos& at, const LinePos& next) {
  if (l.header && l.header_text && dialect_ == Dialect::LinuxCnc) {
    defer(unmatched_, SourcePos{l.number, 1}, "a '%' line holds nothing but the '%' (LinuxCNC's rule)");
  }
  if (l.header && l.program < 0 && dialect_ != Dialect::Hnc) {
    // LinuxCNC and Fanuc: a '%' before anything else opens the text, one after it ends
    // the text (what follows is not read).
    if (cur_.content) return false;
    cur_.begin = next;
    return true;
  }
  if (l.header && dialect_ == Dialect::LinuxCnc) {
    // LinuxCNC 2.9: 'O1234' alone is a label the main program runs through, and the
    // start of the subprogram M98 P1234 runs until M99.
    labels_.push_back(ProgramText{l.program, next, 0, true});
    return true;
  }
  if (l.header) {  // programs are cut at headers; text before the first is a program without a number
    close(at.number);
    cur_ = ProgramText{l.program, next, 0, false};
    return true;
  }
  cur_.content = cur_.content || !l.words.empty() || l.stmt != Stmt::None || !l.assigns.empty();
  if (l.stmt != Stmt::None && l.stmt != Stmt::Assign) match(l, at, next);
  return true;
}

void Builder::close(std::size_t end) {
  cur_.end = end;
  if (cur_.number >= 0) {
    const std::size_t header = cur_.begin.number - 1;
    const auto [first, fresh] = headers_.emplace(cur_.number, header);
    if (!fresh) {
      defer(twice_, SourcePos{header, 1},
            fmt::format("program %{} is defined twice (first at line {})", cur_.number, first->second));
    }
  }
  if (!open_.empty()) {
    const StmtMark& m = st_.marks[open_.back()];
    defer(unmatched_, m.pos,
          m.stmt == Stmt::While ? "WHILE without ENDW in its program" : "IF without ENDIF in its program");
    open_.clear();
  }
  if (!o_open_.empty()) {
    const StmtMark& m = st_.marks[o_open_.back().mark];
    defer(unmatched_, m.pos,
          "o" + o_open_.back().name + ": a block opened here is not closed (sub, if, while, do or repeat)");
    o_open_.clear();
  }
  if (cur_.content || cur_.number >= 0) st_.programs.push_back(cur_);
}

// Matches WHILE/ENDW and IF/ELSE/ENDIF inside the program being read.
void Builder::match(const Line& l, const LinePos& at, const LinePos& next) {
  const std::size_t i = st_.marks.size();
  st_.marks.push_back(StmtMark{at, next, l.stmt, l.stmt_pos, 0, 0, false});
  if (is_oword(l.stmt)) return o_match(l, i);
  const auto top_is = [&](Stmt k) { return !open_.empty() && st_.marks[open_.back()].stmt == k; };
  switch (l.stmt) {
    case Stmt::While:
    case Stmt::If:
      open_.push_back(i);
      return;
    case Stmt::EndW:
      if (!top_is(Stmt::While)) {
        return defer(unmatched_, l.stmt_pos, open_.empty() ? "ENDW without WHILE" : "ENDW inside an open IF");
      }
      st_.marks[i].jump = open_.back();
      st_.marks[open_.back()].jump = i;
      open_.pop_back();
      return;
    case Stmt::Else:
      if (!top_is(Stmt::If)) {
        return defer(unmatched_, l.stmt_pos, open_.empty() ? "ELSE without IF" : "ELSE inside an open WHILE or ELSE");
      }
      st_.marks[open_.back()].jump = i;  // a false condition goes past the ELSE
      open_.back() = i;
      return;
    case Stmt::EndIf:
      if (!top_is(Stmt::If) && !top_is(Stmt::Else)) {
        return defer(unmatched_, l.stmt_pos, open_.empty() ? "ENDIF without IF" : "ENDIF inside an open WHILE");
      }
      st_.marks[open_.back()].jump = i;
      open_.pop_back();
      return;
    default:
      return;
  }
}

// The O-word statements: each closing one matches the innermost open block, which must
// carry the same name (LinuxCNC's rule).
void Builder::o_match(const Line& l, std::size_t i) {
  if (l.oname == "#" && l.stmt != Stmt::OCall) {
    return defer(unmatched_, l.stmt_pos, "a computed O-word name (o#<name>) goes with call only");
  }
  const auto top_is = [&](std::initializer_list<Stmt> ks) {
    if (o_open_.empty() || o_open_.back().name != l.oname) return false;
    for (const Stmt k : ks)
      if (st_.marks[o_open_.back().mark].stmt == k) return true;
    return false;
  };
  switch (l.stmt) {
    case Stmt::OSub:
      if (!o_open_.empty())
        return defer(unmatched_, l.stmt_pos,
                     "o" + l.oname + " sub inside another block: subroutines are defined at the top level");
      if (st_.subs.count(l.oname)) return defer(unmatched_, l.stmt_pos, "o" + l.oname + " sub: defined twice");
      st_.subs[l.oname] = i;
      o_open_.push_back({i, l.oname, {}});
      return;
    case Stmt::OIf:
    case Stmt::ORepeat:
    case Stmt::ODo:
      o_open_.push_back({i, l.oname, {i}});
      return;
    case Stmt::OWhile:
      if (top_is({Stmt::ODo})) {  // the tail of a do loop
        st_.marks[i].do_tail = true;
        st_.marks[i].jump = o_open_.back().mark;
        st_.marks[o_open_.back().mark].jump = i;
        o_open_.pop_back();
        return;
      }
      o_open_.push_back({i, l.oname, {i}});
      return;
    case Stmt::OElseIf:
    case Stmt::OElse:
      if (!top_is({Stmt::OIf, Stmt::OElseIf}))
        return defer(
            unmatched_, l.stmt_pos,
            "o" + l.oname + (l.stmt == Stmt::OElse ? " else" : " elseif") + " without its o" + l.oname + " if");
      st_.marks[o_open_.back().mark].jump = i;
      o_open_.back().mark = i;
      o_open_.back().chain.push_back(i);
      return;
    case Stmt::OEndIf:
      return o_close(l, i, {Stmt::OIf, Stmt::OElseIf, Stmt::OElse}, " endif without its if");
    case Stmt::OEndSub:
      return o_close(l, i, {Stmt::OSub}, " endsub without its sub");
    case Stmt::OEndWhile:
      return o_close(l, i, {Stmt::OWhile}, " endwhile without its while");
    case Stmt::OEndRepeat:
      return o_close(l, i, {Stmt::ORepeat}, " endrepeat without its repeat");
    case Stmt::OBreak:
    case Stmt::OContinue:
    case Stmt::OReturn: {
      const std::optional<std::size_t> in = o_enclosing(l, l.stmt == Stmt::OReturn);
      if (!in)
        return defer(unmatched_, l.stmt_pos,
                     "o" + l.oname +
                         (l.stmt == Stmt::OReturn ? " return outside its o" + l.oname + " sub"
                                                  : " break or continue outside an o" + l.oname +
                                                        " while or do loop (LinuxCNC's repeat takes neither)"));
      st_.marks[i].jump = *in;
      return;
    }
    default:
      return;
  }
}

void Builder::o_close(const Line& l, std::size_t i, std::initializer_list<Stmt> opens, const char* what) {
  bool ok = false;
  if (!o_open_.empty() && o_open_.back().name == l.oname) {
    for (const Stmt k : opens) ok = ok || st_.marks[o_open_.back().mark].stmt == k;
  }
  if (!ok) return defer(unmatched_, l.stmt_pos, "o" + l.oname + what);
  const OOpen& o = o_open_.back();
  st_.marks[o.mark].jump = i;
  st_.marks[i].jump = o.chain.empty() ? o.mark : o.chain.front();
  for (const std::size_t k : o.chain) st_.marks[k].end = i;
  o_open_.pop_back();
}

// The loop (or, for return, the sub) of the same name that a break, continue or return
// leaves: its head's mark.
std::optional<std::size_t> Builder::o_enclosing(const Line& l, bool sub) const {
  for (auto it = o_open_.rbegin(); it != o_open_.rend(); ++it) {
    if (it->name != l.oname) continue;
    const Stmt k = st_.marks[it->chain.empty() ? it->mark : it->chain.front()].stmt;
    if (sub ? k == Stmt::OSub : (k == Stmt::OWhile || k == Stmt::ODo)) {
      return it->chain.empty() ? it->mark : it->chain.front();
    }
  }
  return std::nullopt;
}

Structure Builder::finish(std::size_t end) {
  close(end);
  for (ProgramText& p : labels_) {
    p.end = end;
    st_.programs.push_back(p);
  }
  if (twice_) throw *twice_;
  if (unmatched_) throw *unmatched_;
  return std::move(st_);
}

}  // namespace

const StmtMark& Structure::mark(std::uint64_t offset) const {
  return *std::lower_bound(marks.begin(), marks.end(), offset,
                           [](const StmtMark& m, std::uint64_t o) { return m.at.offset < o; });
}

Structure structure(LineStream& lines, const std::string& file, Dialect dialect) {
  Builder b(file, lines.first(), dialect);
  Line l;
  for (LinePos at = lines.first();;) {
    const LinePos next = lines.read(at, l);
    if (!b.add(l, at, next)) {
      Structure st = b.finish(at.number);
      st.closed = true;
      st.last_line = at.number;
      return st;
    }
    if (lines.at_end()) {
      Structure st = b.finish(next.number);
      st.last_line = at.number;
      return st;
    }
    at = next;
  }
}

}  // namespace dda::program::detail
