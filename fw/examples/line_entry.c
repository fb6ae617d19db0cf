/* SPDX-License-Identifier: Apache-2.0 */
/* Packs the block entry of a straight line from the origin to (dx, dy, dz) steps, the
 * way firmware does, from the field layout in dda_motion_regs.h alone, and prints its
 * words (hexadecimal, word 0 first): what the host writes to ENTRY + 4k before
 * CTRL.commit (docs/design.md, "The command queue"). The line is Bresenham's, as the
 * project's planner makes it (host/planner/plan_line.cpp): every axis adds its extent
 * to an accumulator whose capacity is the longest extent, preloaded at half of it; the
 * entry runs at the core's full rate (feed increment 0, no pacing fields).
 *
 *   cc -std=c99 -Wall -Wextra -pedantic -I fw fw/examples/line_entry.c -o line_entry
 *   ./line_entry 17 -5 0     # the same words as: dda entries --line --from 0,0 --to 17,-5
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "dda_motion_regs.h"

/* Puts the low `width` bits of v at bit `at` of the entry (bit 0: word 0's bit 0). */
static void put(uint32_t w[DDA_MOTION_ENTRY_WORDS], unsigned at, unsigned width, uint64_t v) {
  unsigned k;
  for (k = 0; k < width; ++k) {
    const unsigned bit = at + k;
    if ((v >> k) & 1u) w[bit / 32u] |= (uint32_t)1u << (bit % 32u);
  }
}

static int64_t magnitude(int64_t v) { return v < 0 ? -v : v; }

int main(int argc, char **argv) {
  uint32_t w[DDA_MOTION_ENTRY_WORDS] = {0};
  int64_t d[3];
  int64_t cap = 0;
  unsigned i;
  if (argc != 4) {
    fprintf(stderr, "usage: %s DX DY DZ (steps)\n", argv[0]);
    return 2;
  }
  for (i = 0; i < 3; ++i) {
    d[i] = strtoll(argv[i + 1], NULL, 10);
    if (magnitude(d[i]) > cap) cap = magnitude(d[i]);
  }
  /* One entry's counters hold at most 2^CntWidth - 1 steps (longer lines are cut into
   * several entries). */
  if (cap == 0 || cap >= ((int64_t)1 << DDA_MOTION_CMD_CNT_X_WIDTH)) {
    fprintf(stderr, "line_entry: the longest axis must move 1 to %lld steps\n",
            (long long)(((int64_t)1 << DDA_MOTION_CMD_CNT_X_WIDTH) - 1));
    return 2;
  }
  put(w, DDA_MOTION_CMD_CAP_AT, DDA_MOTION_CMD_CAP_WIDTH, (uint64_t)cap);
  put(w, DDA_MOTION_CMD_JV_X_AT, DDA_MOTION_CMD_JV_X_WIDTH, (uint64_t)magnitude(d[0]));
  put(w, DDA_MOTION_CMD_JV_Y_AT, DDA_MOTION_CMD_JV_Y_WIDTH, (uint64_t)magnitude(d[1]));
  put(w, DDA_MOTION_CMD_JR_X_AT, DDA_MOTION_CMD_JR_X_WIDTH, (uint64_t)(cap / 2));
  put(w, DDA_MOTION_CMD_JR_Y_AT, DDA_MOTION_CMD_JR_Y_WIDTH, (uint64_t)(cap / 2));
  put(w, DDA_MOTION_CMD_CNT_X_AT, DDA_MOTION_CMD_CNT_X_WIDTH, (uint64_t)magnitude(d[0]));
  put(w, DDA_MOTION_CMD_CNT_Y_AT, DDA_MOTION_CMD_CNT_Y_WIDTH, (uint64_t)magnitude(d[1]));
  put(w, DDA_MOTION_CMD_DIR_X_AT, DDA_MOTION_CMD_DIR_X_WIDTH, d[0] < 0);
  put(w, DDA_MOTION_CMD_DIR_Y_AT, DDA_MOTION_CMD_DIR_Y_WIDTH, d[1] < 0);
  /* The third axis on the core's linear integrator, the same capacity; without Z motion
   * its capacity is 1 (a capacity is never 0) and the rest 0. */
  put(w, DDA_MOTION_CMD_CAP_Z_AT, DDA_MOTION_CMD_CAP_Z_WIDTH, d[2] != 0 ? (uint64_t)cap : 1u);
  if (d[2] != 0) {
    put(w, DDA_MOTION_CMD_JV_Z_AT, DDA_MOTION_CMD_JV_Z_WIDTH, (uint64_t)magnitude(d[2]));
    put(w, DDA_MOTION_CMD_JR_Z_AT, DDA_MOTION_CMD_JR_Z_WIDTH, (uint64_t)(cap / 2));
    put(w, DDA_MOTION_CMD_CNT_Z_AT, DDA_MOTION_CMD_CNT_Z_WIDTH, (uint64_t)magnitude(d[2]));
    put(w, DDA_MOTION_CMD_DIR_Z_AT, DDA_MOTION_CMD_DIR_Z_WIDTH, d[2] < 0);
  }
  /* The axes (0: the core's x, y, z drive X, Y, Z), the feed increment (0: the full
   * rate) and the pacing fields (a cruise speed of 0: paced by the feed) stay 0. */
  for (i = 0; i < DDA_MOTION_ENTRY_WORDS; ++i) printf("%s%08lx", i ? " " : "", (unsigned long)w[i]);
  printf("\n");
  return 0;
}
