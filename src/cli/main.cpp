// prime: command-line front end. Subcommands are registered by their own files.
#include <CLI/CLI.hpp>
#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"PRIME, revived: the 1991 PhotoRealistic Image Modelling Environment"};
  app.require_subcommand(1);
  CLI11_PARSE(app, argc, argv);
  return 0;
}
