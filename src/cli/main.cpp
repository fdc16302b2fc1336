// prime: the command-line front end. Every error a user can cause (bad scene
// data, missing files) is reported on stderr as "prime: <file:line: ...>" with
// exit status 1; usage errors exit 2; a render that Ctrl-C (SIGINT) or SIGTERM
// aborted exits 128 + the signal (130, 143), as a shell reports it.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "legacy_io/cgl/scene_file.h"
#include "legacy_io/common/error.h"
#include "legacy_io/common/run_inputs.h"
#include "legacy_io/malone/input.h"
#include "src/cli/cgl/commands.h"
#include "src/cli/commands.h"
#include "src/cli/live_render.h"
#include "src/cli/malone/commands.h"

namespace {

std::string fileHead(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}

std::string lowerExtension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// `prime trace`, `probe`, `bench` and `export-pov` serve every system: the
// scene says which. --format names it; otherwise a directory is a PRIME
// scene and a file is read for what it is: a CGL scene-description file
// (keywords, `*` comments) or a stream of numbers (Malone's). `prime export`
// and `prime view` take a CGL picture when the file ends in .rle or .raw (or
// --format rle|raw), else a PRIME graph file. Returns the subcommand that
// handles it.
std::string commandFor(const std::string& command, int argc, char** argv) {
  std::string format, scene;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--format" && i + 1 < argc) {
      format = argv[++i];
    } else if (a.rfind("--format=", 0) == 0) {
      format = a.substr(9);
    } else if (!a.empty() && a[0] != '-') {
      // The first word that names a file or directory (a 1985 call statement
      // puts numbers before it: `trace -yh 511 scene`), else the first word.
      if (scene.empty() || (!std::filesystem::exists(scene) && std::filesystem::exists(a)))
        scene = a;
    }
  }
  namespace cgl = prime::cli::cgl;
  if (command == "export" || command == "view") {
    const std::string ext = lowerExtension(scene);
    const bool picture =
        format == "rle" || format == "raw" || (format.empty() && (ext == ".rle" || ext == ".raw"));
    if (!picture) return command;
    return command == "export" ? cgl::kExportCommand : cgl::kViewCommand;
  }
  const bool file = format.empty() && !scene.empty() && std::filesystem::is_regular_file(scene);
  const std::string head = file ? fileHead(scene) : std::string();
  if (format == "cgl" || (file && prime::cgl::looksLikeCgl(head))) {
    if (command == "trace") return cgl::kTraceCommand;
    if (command == "probe") return cgl::kProbeCommand;
    if (command == "export-pov") return cgl::kExportPovCommand;
    return cgl::kBenchCommand;
  }
  if (format == "malone" || (file && prime::malone::looksLikeMalone(head))) {
    if (command == "trace") return prime::cli::malone::kTraceCommand;
    if (command == "probe") return prime::cli::malone::kProbeCommand;
    if (command == "export-pov") return prime::cli::malone::kExportPovCommand;
    return prime::cli::malone::kBenchCommand;
  }
  return command;
}

// CLI11's range checks let NaN through (every comparison with NaN is false)
// and accept "inf": no command of prime takes a number that is not finite.
// Returns the message for the first option or argument of the parsed command
// line whose value reads as a number that is not finite ("" when none). A
// value that names an existing file is a file, not a number.
std::string nonFiniteNumber(const CLI::App& app) {
  for (const CLI::Option* opt : app.get_options()) {
    for (const std::string& value : opt->results()) {
      const char* begin = value.c_str();
      char* end = nullptr;
      const double v = std::strtod(begin, &end);
      if (end == begin || *end != '\0' || std::isfinite(v)) continue;
      if (std::filesystem::exists(value)) continue;
      const std::string name = opt->get_name(false, true);
      return name + ": expected a finite number, found '" + value + "'";
    }
  }
  for (const CLI::App* sub : app.get_subcommands()) {
    const std::string m = nonFiniteNumber(*sub);
    if (!m.empty()) return m;
  }
  return "";
}

// Edit distance, for "did you mean".
std::size_t distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// The visible subcommand nearest to `word`, if it is near enough.
std::string nearestCommand(const CLI::App& app, const std::string& word) {
  std::string best;
  std::size_t bestDistance = 3;
  for (const CLI::App* sub :
       app.get_subcommands([](const CLI::App* a) { return !a->get_group().empty(); })) {
    const std::size_t d = distance(word, sub->get_name());
    if (d < bestDistance) {
      bestDistance = d;
      best = sub->get_name();
    }
  }
  return best;
}

}  // namespace

// The whole command line; with `parseOnly`, everything but the chosen
// command's action (the CLI fuzz target, tests/fuzz/prime/cli_fuzz.cpp,
// calls it so, in-process).
int primeMain(int argc, char** argv, bool parseOnly) {
  std::vector<char*> args(argv, argv + argc);
  // `prime help CMD` is `prime CMD --help`.
  std::string helpFlag = "--help";
  if (argc >= 3 && std::string(argv[1]) == "help") {
    args.erase(args.begin() + 1);
    args.push_back(helpFlag.data());
    argv = args.data();
    argc = static_cast<int>(args.size());
  } else if (argc == 2 && std::string(argv[1]) == "help") {
    args[1] = helpFlag.data();
  }
  std::string routed;
  std::vector<std::string> translated;  // a CGL call statement's flags, rewritten
  if (argc >= 2 && (std::string(argv[1]) == "trace" || std::string(argv[1]) == "probe" ||
                    std::string(argv[1]) == "bench" || std::string(argv[1]) == "export-pov" ||
                    std::string(argv[1]) == "export" || std::string(argv[1]) == "view")) {
    routed = commandFor(argv[1], argc, argv);
    args[1] = routed.data();
    if (routed == prime::cli::cgl::kTraceCommand || routed == prime::cli::cgl::kProbeCommand ||
        routed == prime::cli::cgl::kBenchCommand) {
      translated.assign(args.begin(), args.end());
      prime::cli::cgl::translateCallStatement(translated, 2);
      args.clear();
      for (std::string& a : translated) args.push_back(a.data());
    }
  }
  CLI::App app{
      "PRIME, revived: historical ray tracers (PRIME 1991, Malone 1995, Waterloo CGL 1985)"};
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
  prime::cli::addQuantizeCommand(app, action);
  prime::cli::addCheckCommand(app, action);
  prime::cli::addNewCommand(app, action);
  prime::cli::addCompareCommand(app, action);
  prime::cli::addWalkCommand(app, action);
  prime::cli::malone::addTraceCommand(app, action);
  prime::cli::malone::addProbeCommand(app, action);
  prime::cli::malone::addBenchCommand(app, action);
  prime::cli::malone::addExportPovCommand(app, action);
  prime::cli::cgl::addTraceCommand(app, action);
  prime::cli::cgl::addProbeCommand(app, action);
  prime::cli::cgl::addBenchCommand(app, action);
  prime::cli::cgl::addExportPovCommand(app, action);
  prime::cli::cgl::addPictureCommands(app, action);
  prime::cli::cgl::addSplinesCommand(app, action);
  prime::cli::cgl::addCookCommand(app, action);
  prime::cli::cgl::addTovectorCommand(app, action);
  app.set_version_flag("--version", std::string("prime ") + PRIME_VERSION +
                                        " (PRIME 1991, Malone 1995, Waterloo CGL 1985)");
  try {
    app.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Usage errors: one line with the prime: prefix, exit status 2.
    // The command as the user typed it (not the system's subcommand it went to).
    const std::string first = argc > 1 ? argv[1] : "";
    if (!first.empty() && first[0] != '-' && app.get_subcommands().empty()) {
      const std::string near = nearestCommand(app, first);
      std::cerr << "prime: unknown command '" << first << "'"
                << (near.empty() ? "" : " - did you mean '" + near + "'?")
                << " (prime --help lists the commands)\n";
      return 2;
    }
    std::cerr << "prime: " << e.what() << " (prime " << (first.empty() ? "" : first + " ")
              << "--help)\n";
    return 2;
  }
  if (const std::string bad = nonFiniteNumber(app); !bad.empty()) {
    const std::string first = argc > 1 ? argv[1] : "";
    std::cerr << "prime: " << bad << " (prime " << (first.empty() ? "" : first + " ")
              << "--help)\n";
    return 2;
  }
  if (parseOnly) return 0;
  try {
    // Every input the command reads is recorded: no output may replace one.
    const prime::io::RunInputs inputs;
    const int status = action ? action() : 0;
    // Ctrl-C (or SIGTERM) that aborted a render: 130 (143), as the shell
    // reports a process the signal ended, not the 1 of Esc (ExitOnEsc).
    const int sig = prime::cli::interruptingSignal();
    return status != 0 && sig != 0 ? 128 + sig : status;
  } catch (const prime::io::InputError& e) {
    std::cerr << "prime: " << e.what() << "\n";
    return 1;
  } catch (const CLI::ParseError& e) {  // an option's value found wrong only in the action
    std::cerr << "prime: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "prime: error: " << e.what() << "\n";
    return 1;
  }
}

#ifndef PRIME_NO_MAIN
int main(int argc, char** argv) {
  return primeMain(argc, argv, false);
}
#endif
