// SPDX-License-Identifier: Apache-2.0
// scripts/bench: the golden model's speed, records off (see bench_main.hpp).
#include "bench/bench_main.hpp"

int main(int argc, char* argv[]) { return dda::bench_main(nullptr, argc, argv); }
