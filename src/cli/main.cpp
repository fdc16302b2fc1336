// prime: the command-line front end. Every error a user can cause (bad scene
// data, missing files) is reported on stderr as "prime: <file:line: ...>" with
// exit status 1; usage errors exit with CLI11's status (106 and friends).
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "legacy_io/common/error.h"
#include "legacy_io/malone/input.h"
#include "src/cli/commands.h"
#include "src/cli/malone/commands.h"

namespace {

// `prime trace`, `prime probe` and `prime export-pov` serve every system: the scene says which.
// --format names it; otherwise a directory is a PRIME scene and a file is
// read for what it is (a stream of numbers: Malone's). Returns the
// subcommand that handles it.
std::string commandFor(const std::string& command, int argc, char** argv) {
  std::string format, scene;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--format" && i + 1 < argc) {
      format = argv[++i];
    } else if (a.rfind("--format=", 0) == 0) {
      format = a.substr(9);
    } else if (scene.empty() && !a.empty() && a[0] != '-') {
      scene = a;
    }
  }
  const bool malone =
      format == "malone" ||
      (format.empty() && !scene.empty() && std::filesystem::is_regular_file(scene) && [&] {
        std::ifstream in(scene, std::ios::binary);
        std::string head(4096, '\0');
        in.read(head.data(), static_cast<std::streamsize>(head.size()));
        head.resize(static_cast<std::size_t>(in.gcount()));
        return prime::malone::looksLikeMalone(head);
      }());
  if (!malone) return command;
  if (command == "export-pov") return prime::cli::malone::kExportPovCommand;
  return command == "trace" ? prime::cli::malone::kTraceCommand : prime::cli::malone::kProbeCommand;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<char*> args(argv, argv + argc);
  std::string routed;
  const std::string first = argc >= 2 ? argv[1] : "";
  if (first == "trace" || first == "probe" || first == "export-pov") {
    routed = commandFor(argv[1], argc, argv);
    args[1] = routed.data();
  }
  CLI::App app{"PRIME, revived: historical ray tracers (PRIME 1991, Malone 1995)"};
  app.require_subcommand(1);
  prime::cli::Action action;
  prime::cli::addModelCommand(app, action);
  prime::cli::addDumpCommand(app, action);
  prime::cli::addTraceCommand(app, action);
  prime::cli::addProbeCommand(app, action);
  prime::cli::addViewCommand(app, action);
  prime::cli::addExportCommand(app, action);
  prime::cli::addDiffCommand(app, action);
  prime::cli::addPaletteCommand(app, action);
  prime::cli::addExportPovCommand(app, action);
  prime::cli::addBenchCommand(app, action);
  prime::cli::addPlate1Command(app, action);
  prime::cli::addStressCommand(app, action);
  prime::cli::malone::addTraceCommand(app, action);
  prime::cli::malone::addProbeCommand(app, action);
  prime::cli::malone::addExportPovCommand(app, action);
  CLI11_PARSE(app, argc, args.data());
  try {
    return action ? action() : 0;
  } catch (const prime::io::InputError& e) {
    std::cerr << "prime: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "prime: error: " << e.what() << "\n";
    return 1;
  }
}
