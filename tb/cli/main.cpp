#include "dda_cli.hpp"

int main(int argc, char** argv) { return dda::cli::main(argc, argv); }
