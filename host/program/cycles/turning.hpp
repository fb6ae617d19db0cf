// SPDX-License-Identifier: Apache-2.0
// LinuxCNC's lathe turning cycles in the program reader (docs/programs.md, "Lathe turning
// cycles"): G70 (finishing passes along the contour), G71 (roughing along Z) and G72
// (facing along X), with their variants .1 (no pockets) and .2 (the pockets only). The
// contour is a subroutine's lines and arcs, with corners rounded (A) or chamfered (C);
// the passes are derived from it with the geometry of the LinuxCNC that Debian ships
// (2.9.0~pre1, git f1270d6ed7, interp_g7x.cc), so that every pass ends where LinuxCNC's
// ends: the same corner finishes, offsetting of the contour by the finishing allowance,
// depth steps, escapes and pocket search, with the same tolerances (1e-6, 1e-3, 1e-2).
// This is the planner's side: floating point in program units, before the lattice;
// the reader turns each pass into an ordinary block.
#pragma once

#include <complex>
#include <deque>
#include <functional>
#include <list>
#include <stdexcept>
#include <string>

namespace dda::program::detail::turning {

// A point of the Z-X plane as LinuxCNC's cycles hold it: Z the real part, X the imaginary.
using Pt = std::complex<double>;

// A piece of the contour: a line from s to e, or an arc from s to e about c; or a corner
// to finish between its neighbours (s = e = the corner), rounded with radius `finish`
// (an arc) or chamfered by `finish` (a line).
struct Segment {
  bool arc = false;
  bool ccw = false;  // G03
  Pt s, e, c;
  double finish = 0;
};

// What a cycle cannot do with its contour (LinuxCNC refuses the same programs).
class CycleError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Where the passes go, in the program's frame: a line (rapid or feed) or an arc to `end`
// about `centre` (absolute).
struct Pass {
  enum Kind { Rapid, Feed, ArcCw, ArcCcw } kind = Feed;
  Pt end, centre;
};
using Sink = std::function<void(const Pass&)>;

// The words of a cycle's block, in program units (LinuxCNC's defaults).
struct CycleWords {
  double x = 0, z = 0;  // the start of the cycle, and where each pass starts from
  double d = 0;         // G70: the first pass's allowance; G71/G72: the finishing allowance
  double e = 0;         // G70: the last pass's allowance
  double p = 1;         // G70: the number of passes
  double i = 1;         // G71/G72: the depth of each cut
  double r = 0.5;       // G71/G72: the retract
};

// G70: `passes` finishing passes along the contour, from allowance d to e.
void finish(std::list<Segment> contour, const CycleWords& words, const Sink& out);
// G71 (face false) or G72 (face true); variant 0: everything, 1: no pockets, 2: the
// pockets only.
void rough(std::list<Segment> contour, const CycleWords& words, int variant, bool face, const Sink& out);

// ---- one segment (host/program/cycles/turning_segment.cpp) ----

inline const Pt kI(0, 1);
inline constexpr double kTol = 1e-6;  // LinuxCNC's: points this close are one
using Cuts = std::deque<double>;      // the Z of a segment's crossings of a line X = const

double radius(const Segment& g);
// Whether X falls (or stays) along the segment while Z falls: what a roughing pass can
// follow (a corner not finished yet passes).
bool monotonic(const Segment& g);
// The segment's crossings of the line X = x (a line along it: both its ends).
void crossings(const Segment& g, double x, Cuts& is);
// The segment moved by d to its side (an arc: its radius grows by d if counter-clockwise).
void offset(Segment& g, double d);
// f applied to every point of the segment (its ends and centre).
template <typename F>
void map_points(Segment& g, F f) {
  g.s = f(g.s);
  g.e = f(g.e);
  if (g.arc) g.c = f(g.c);
}

// The passes, mapped from the working orientation back to the program's: the mirrors
// undone, then the quarter turn.
class Out {
 public:
  Out(const Sink& sink, int flips) : sink_(sink), flips_(flips) {}
  void line(Pt end, bool rapid) const { sink_({rapid ? Pass::Rapid : Pass::Feed, back(end), {}}); }
  void arc(bool ccw, Pt centre, Pt end) const {
    const bool turned = ccw != (((flips_ & 1) != 0) != ((flips_ & 2) != 0));
    sink_({turned ? Pass::ArcCcw : Pass::ArcCw, back(end), back(centre)});
  }
  void draw(const Segment& g) const {
    if (g.arc) {
      arc(g.ccw, g.c, g.e);
    } else {
      line(g.e, false);
    }
  }

 private:
  Pt back(Pt p) const {
    if (flips_ & 1) p = -std::conj(p);
    if (flips_ & 2) p = std::conj(p);
    if (flips_ & 4) p = kI * p;
    return p;
  }
  const Sink& sink_;
  int flips_;
};

// How a pass follows a segment, and how neighbours are joined (explained where defined).
bool climb(const Segment& g, Pt& at, const Out& out);
void climb_only(const Segment& g, Pt& at, const Out& out);
bool dive(const Segment& g, Pt& at, double x, const Out& out, bool fast);
void join(Segment& prev, Segment& next);
void finish_corner(Segment& h, Segment& prev, Segment& next);

}  // namespace dda::program::detail::turning
