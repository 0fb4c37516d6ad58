// lac: command-line access to log-aesthetic curves. Subcommands live in cli/*.cpp.
#include "cli/command.hpp"

int main(int argc, char** argv) { return lac::cli::run(argc, argv); }
