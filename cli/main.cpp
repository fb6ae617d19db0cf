// SPDX-License-Identifier: Apache-2.0
// Entry point of the `dda` command.
//
// libsystemc also defines main(), which calls sc_main() and, after it returns, prints
// SystemC's banner on stderr; that would break the command's one-line error contract.
// The executable's own main() takes precedence and runs the command directly (the
// SystemC kernel needs no more than that). sc_main is defined for libsystemc's link
// and runs the same command.
#include <systemc>  // declares sc_main with the linkage libsystemc expects

#include "cli/dda_cli.hpp"

int main(int argc, char* argv[]) { return dda::cli::main(argc, argv); }

int sc_main(int argc, char* argv[]) { return dda::cli::main(argc, argv); }
