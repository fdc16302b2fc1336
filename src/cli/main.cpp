// prime: the command-line front end. Every error a user can cause (bad scene
// data, missing files) is reported on stderr as "prime: <file:line: ...>" with
// exit status 1; usage errors exit 2; a render that Ctrl-C (SIGINT) or SIGTERM
// aborted exits 128 + the signal (130, 143), as a shell reports it.
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"
#include "legacy_io/common/run_inputs.h"
#include "src/cli/cgl/commands.h"
#include "src/cli/commands.h"
#include "src/cli/live_render.h"
#include "src/cli/option_values.h"
#include "src/cli/step.h"
#include "src/cli/system.h"

namespace {

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

// The option of `app` nearest to `word` ("--profil"), if near enough.
std::string nearestOption(const CLI::App& app, const std::string& word) {
  const std::size_t dashes = word.find_first_not_of('-');
  if (dashes == 0 || dashes == std::string::npos) return "";
  const std::string bare = word.substr(dashes, word.find('=') - dashes);
  std::string best;
  std::size_t bestDistance = bare.size() <= 3 ? 2 : 3;
  for (const CLI::Option* opt : app.get_options()) {
    for (const std::string& name : opt->get_lnames()) {
      const std::size_t d = distance(bare, name);
      if (d < bestDistance) bestDistance = d, best = "--" + name;
    }
  }
  return best;
}

// Arguments the command did not take, in the order given, as one sentence:
// CLI11's own lists them last first ("modern --profil").
std::string extrasMessage(const CLI::App& app) {
  const CLI::App* sub = &app;
  while (!sub->get_subcommands().empty()) sub = sub->get_subcommands().front();
  const std::vector<std::string> extra = sub->remaining();
  for (const std::string& w : extra)
    if (w.size() > 1 && w[0] == '-' && !prime::cli::isNumber(w)) {
      const std::string near = nearestOption(*sub, w);
      return "unknown option '" + w + "'" + (near.empty() ? "" : " - did you mean '" + near + "'?");
    }
  std::string words;
  for (const std::string& w : extra) words += (words.empty() ? "'" : " '") + w + "'";
  return std::string(extra.size() == 1 ? "an argument" : "arguments") +
         " the command does not take: " + words;
}

// Every command, in the order `prime --help` lists them, with the names each
// registration adds. Building all of them (CLI11 objects for some 30
// commands and their options) cost about 3 ms of CPU per run of `prime`
// (docs/cgl/benchmarks.md, "What every command pays"), more than many small
// renders' set-up: a run that names one of them registers that one alone.
struct Command {
  std::vector<std::string> names;
  void (*add)(CLI::App&, prime::cli::Action&);
  // A verb every system shares: registered with the system the command line
  // names (prime::cli::systemFor), instead of `add`.
  void (*verb)(CLI::App&, prime::cli::Action&, const prime::cli::System&) = nullptr;
};

const std::vector<Command>& commands() {
  namespace cli = prime::cli;
  // One command a line, in `prime --help` order.
  // clang-format off
  static const std::vector<Command> kCommands = {
      {{"model"}, cli::addModelCommand},
      {{"dump"}, cli::addDumpCommand},
      {{"trace"}, nullptr, cli::addTraceVerb},
      {{"probe"}, nullptr, cli::addProbeVerb},
      {{"view"}, nullptr, cli::addViewVerb},
      {{"export"}, nullptr, cli::addExportVerb},
      {{"diff"}, cli::addDiffCommand},
      {{"palette"}, cli::addPaletteCommand},
      {{"errata"}, cli::addErrataCommand},
      {{"export-pov"}, nullptr, cli::addExportPovVerb},
      {{"bench"}, nullptr, cli::addBenchVerb},
      {{"plate1"}, cli::addPlate1Command},
      {{"stress"}, cli::addStressCommand},
      {{"quantize"}, cli::addQuantizeCommand},
      {{"film"}, cli::addFilmCommand},
      {{"check"}, cli::addCheckCommand},
      {{"new"}, cli::addNewCommand},
      {{"compare"}, cli::addCompareCommand},
      {{"walk"}, nullptr, cli::addWalkVerb},
      {{"path"}, nullptr, cli::addPathVerb},
      {{"stitch"}, cli::addStitchCommand},
      {{"cgl-splines"}, cli::cgl::addSplinesCommand},
      {{"cook"}, cli::cgl::addCookCommand},
      {{"tovector"}, cli::cgl::addTovectorCommand},
  };
  // clang-format on
  return kCommands;
}

// Registers every command, checking the table: each registration must add
// exactly the names listed (a command added without its row, or renamed,
// fails `prime --help`, which the build runs for the man page).
void addCommand(CLI::App& app, prime::cli::Action& action, const Command& c,
                const std::vector<std::string>& args) {
  if (c.verb == nullptr) {
    c.add(app, action);
    return;
  }
  // The words after the verb, when the command line names it.
  std::vector<std::string> rest;
  if (args.size() >= 2 && args[1] == c.names.front()) rest.assign(args.begin() + 2, args.end());
  c.verb(app, action, prime::cli::systemFor(c.names.front(), rest));
}

void addEveryCommand(CLI::App& app, prime::cli::Action& action,
                     const std::vector<std::string>& args) {
  for (const Command& c : commands()) {
    const auto all = [](CLI::App*) { return true; };
    const std::size_t before = app.get_subcommands(all).size();
    addCommand(app, action, c, args);
    const std::vector<CLI::App*> subs = app.get_subcommands(all);
    std::vector<std::string> added;
    for (std::size_t k = before; k < subs.size(); ++k) added.push_back(subs[k]->get_name());
    if (added != c.names)
      throw std::logic_error("src/cli/main.cpp: the command table does not list the commands " +
                             (added.empty() ? std::string("(none)") : added.front()) +
                             " registers");
  }
}

// The row to register alone, or nullptr for all: when args[1] is a command's
// name and no later argument is (so no word can be read as another command).
const Command* onlyCommandNeeded(const std::vector<char*>& args) {
  const Command* found = nullptr;
  for (const Command& c : commands())
    for (const std::string& name : c.names) {
      for (std::size_t k = 2; k < args.size(); ++k)
        if (name == args[k]) return nullptr;
      if (name == args[1]) found = &c;
    }
  return found;
}

// The command line's parser: with `only`, that row's commands alone, else
// every command.
std::unique_ptr<CLI::App> makeApp(const Command* only, prime::cli::Action& action,
                                  const std::vector<std::string>& args) {
  auto app = std::make_unique<CLI::App>(
      "PRIME, revived: historical ray tracers (PRIME 1991, Malone 1995, Waterloo CGL 1985)");
  app->require_subcommand(1);
  if (only != nullptr)
    addCommand(*app, action, *only, args);
  else
    addEveryCommand(*app, action, args);
  app->set_version_flag("--version", std::string("prime ") + PRIME_VERSION +
                                         " (PRIME 1991, Malone 1995, Waterloo CGL 1985)");
  return app;
}
}  // namespace

// The help that lists the options of the command line `words`: a verb every
// system shares lists those of the system its scene names, so the scene
// goes in ("prime trace glass.cgl --help").
static std::string helpCommand(const std::vector<std::string>& words) {
  if (words.size() < 2 || words[1].empty() || words[1][0] == '-') return "prime --help";
  bool shared = false;
  for (const Command& c : commands())
    shared = shared || (c.verb != nullptr &&
                        std::find(c.names.begin(), c.names.end(), words[1]) != c.names.end());
  std::string scene;
  if (shared)
    for (std::size_t i = 2; i < words.size() && scene.empty(); ++i)
      if (!words[i].empty() && words[i][0] != '-' && std::filesystem::exists(words[i]))
        scene = " " + words[i];
  return "prime " + words[1] + scene + " --help";
}

// "while rendering FILE" (the step the failure ended), else "running `prime
// trace FILE ...`": a message that names what was being done, and to which file.
static std::string doing(const std::vector<std::string>& words) {
  if (const std::string step = prime::cli::Step::current(); !step.empty()) return "while " + step;
  std::string line = "prime";
  for (std::size_t i = 1; i < words.size(); ++i) line += " " + words[i];
  return "running `" + line + "`";
}

// The whole command line; with `parseOnly`, everything but the chosen
// command's action (the CLI fuzz target, tests/prime/fuzz/cli_fuzz.cpp,
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
  // A system's own way of writing a command line (CGL's 1985 call
  // statement after `prime trace`): its flags rewritten to the port's.
  std::vector<std::string> words(args.begin(), args.end());
  if (words.size() >= 2 && (words[1] == "trace" || words[1] == "probe" || words[1] == "bench")) {
    const prime::cli::System& system =
        prime::cli::systemFor(words[1], std::vector<std::string>(words.begin() + 2, words.end()));
    if (system.callStatement != nullptr) {
      try {
        system.callStatement(words, 2);
      } catch (const CLI::ParseError& e) {  // a flag of the call statement without its value
        std::cerr << "prime: " << e.what() << " (prime " << words[1] << " --help)\n";
        return 2;
      }
    }
  }
  prime::cli::Action action;
  // Only the command named is registered when that is enough (commands()).
  const Command* only = args.size() >= 2 ? onlyCommandNeeded(args) : nullptr;
  std::unique_ptr<CLI::App> made;
  // The parser, its options taking the values they declare (option_values.h).
  const auto parse = [&](const Command* command) {
    made = makeApp(command, action, words);
    prime::cli::takeDeclaredValues(*made, words);
    args.clear();
    for (std::string& a : words) args.push_back(a.data());
    made->parse(static_cast<int>(args.size()), args.data());
  };
  try {
    try {
      parse(only);
    } catch (const CLI::Error&) {
      if (only == nullptr) throw;
      // Help, --version and usage errors come from the whole command line,
      // as they always did (their messages name other commands).
      action = nullptr;
      parse(nullptr);
    }
  } catch (const CLI::Success& e) {  // --help, --version
    return made->exit(e);
  } catch (const CLI::ParseError& e) {
    // Usage errors: one line with the prime: prefix, exit status 2.
    // The command as the user typed it (not the system's subcommand it went to).
    const std::string first = argc > 1 ? argv[1] : "";
    if (!first.empty() && first[0] != '-' && made->get_subcommands().empty()) {
      const std::string near = nearestCommand(*made, first);
      std::cerr << "prime: unknown command '" << first << "'"
                << (near.empty() ? "" : " - did you mean '" + near + "'?")
                << " (prime --help lists the commands)\n";
      return 2;
    }
    const std::string what =
        dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr ? extrasMessage(*made) : e.what();
    std::cerr << "prime: " << what << " (" << helpCommand(words) << ")\n";
    return 2;
  } catch (const prime::io::InputError& e) {  // a check a command made while parsing
    std::cerr << "prime: " << e.what() << "\n";
    return 1;
  } catch (const std::logic_error& e) {  // the command table (addEveryCommand)
    std::cerr << "prime: internal error: " << e.what() << "\n";
    return 1;
  }
  if (const std::string bad = nonFiniteNumber(*made); !bad.empty()) {
    std::cerr << "prime: " << bad << " (" << helpCommand(words) << ")\n";
    return 2;
  }
  if (parseOnly) return 0;
  try {
    // Every input the command reads is recorded: no output may replace one.
    const prime::io::RunInputs inputs;
    const int status = action ? action() : 0;
    // What went to standard output reached it (a full disk, a closed pipe
    // end: `prime palette listing > my.pal` must not say it succeeded).
    std::cout.flush();
    errno = 0;
    if (std::fflush(stdout) != 0 || std::ferror(stdout) != 0 || !std::cout) {
      // (The write that failed may have been long before: its errno is gone.)
      std::cerr << "prime: cannot write standard output"
                << (errno != 0 ? std::string(": ") + std::strerror(errno)
                               : std::string(" (a full disk, or a closed pipe?)"))
                << "; what it holds is not complete\n";
      return status != 0 ? status : 1;
    }
    // Ctrl-C (or SIGTERM) that aborted a render: 130 (143), as the shell
    // reports a process the signal ended, not the 1 of Esc (ExitOnEsc).
    const int sig = prime::cli::interruptingSignal();
    return status != 0 && sig != 0 ? 128 + sig : status;
  } catch (const prime::io::InputError& e) {
    const std::string note = prime::io::dosEofNote(e);
    std::cerr << "prime: " << e.what() << (note.empty() ? "" : " (" + note + ")") << "\n";
    return 1;
  } catch (const CLI::ParseError& e) {  // an option's value found wrong only in the action
    std::cerr << "prime: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "prime: out of memory " << doing(words) << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "prime: error " << doing(words) << ": " << e.what() << "\n";
    return 1;
  }
}

#ifndef PRIME_NO_MAIN
int main(int argc, char** argv) {
#ifdef __EMSCRIPTEN__
  // Emscripten 3.1.6 starts a program with the file mode mask 0777, so every
  // file it made had no permissions at all; a process started from a shell
  // has 022 (docs/web.md).
  ::umask(022);
#endif
  return primeMain(argc, argv, false);
}
#endif
