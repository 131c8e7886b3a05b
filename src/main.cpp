// src/main.cpp: the sepax program.  Everything but main() is in sepax_cli_lib.
#include "dispatch.hpp"

int main(int argc, char** argv) { return sepax::cli::run(argc, argv); }
