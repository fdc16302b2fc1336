// How every command takes and checks its options' values (option_values.h).
#include "src/cli/option_values.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace prime::cli {

namespace {

// CLI11 gives an option of any number of values this many.
constexpr int kUnbounded = 1 << 20;

// The subcommand args[1] names, if it is one.
CLI::App* chosenCommand(CLI::App& app, const std::vector<std::string>& args) {
  if (args.size() < 2) return nullptr;
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    if (sub->check_name(args[1])) return sub;
  return nullptr;
}

// M..N values, or a list of any number (--scale-sizes 1 10, --textures DIR).
bool isRange(const CLI::Option* o) {
  const int most = o->get_items_expected_max();
  return !o->get_positional() && o->get_items_expected_min() < most && most > 1;
}

}  // namespace

bool isNumber(const std::string& word) {
  if (word.empty()) return false;
  char* end = nullptr;
  std::strtod(word.c_str(), &end);
  return end == word.c_str() + word.size();
}

void takeDeclaredValues(CLI::App& app, std::vector<std::string>& args) {
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    for (CLI::Option* o : sub->get_options()) {
      if (o->get_positional() || o->get_items_expected_max() <= 1) continue;
      if (o->get_items_expected_min() == o->get_items_expected_max()) o->allow_extra_args(false);
    }
  // M..N values: a run of numbers, or one word that is not a number.
  CLI::App* cmd = chosenCommand(app, args);
  if (cmd == nullptr) return;
  for (std::size_t i = 2; i < args.size(); ++i) {
    if (args[i] == "--") break;
    if (args[i].size() < 2 || args[i][0] != '-' || isNumber(args[i])) continue;
    const CLI::Option* o = cmd->get_option_no_throw(args[i]);
    if (o == nullptr || !isRange(o)) continue;
    std::size_t end = i + 1;  // one past the option's values
    const auto most = static_cast<std::size_t>(std::min(o->get_items_expected_max(), kUnbounded));
    if (end < args.size() && isNumber(args[end])) {
      while (end < args.size() && end - i - 1 < most && isNumber(args[end])) ++end;
    } else if (end < args.size() && !args[end].empty() && args[end][0] != '-') {
      ++end;
    }
    // The words CLI11 would also have taken: before the option.
    std::size_t after = end;
    while (after < args.size() && (args[after].empty() || args[after][0] != '-')) ++after;
    if (after == end) continue;
    std::vector<std::string> moved(args.begin() + static_cast<std::ptrdiff_t>(end),
                                   args.begin() + static_cast<std::ptrdiff_t>(after));
    args.erase(args.begin() + static_cast<std::ptrdiff_t>(end),
               args.begin() + static_cast<std::ptrdiff_t>(after));
    args.insert(args.begin() + static_cast<std::ptrdiff_t>(i), moved.begin(), moved.end());
    i = after - 1;  // the option and its values now end where the moved words did
  }
}

CLI::Validator outputName() {
  return CLI::Validator(
      [](std::string& name) -> std::string {
        return name.empty() ? "an empty file name: name the file to write" : std::string();
      },
      "FILE");
}

namespace {
CLI::Validator numberFrom(double least, bool strict) {
  std::ostringstream text;
  text << least;
  const std::string shown = text.str();
  return CLI::Validator(
      [least, strict, shown](std::string& value) -> std::string {
        double v = 0;
        std::istringstream in(value);
        if (!(in >> v) || !in.eof() || std::isnan(v))
          return "expected a number, got '" + value + "'";
        if (strict ? v <= least : v < least)
          return std::string(strict ? "must be more than " : "must be at least ") + shown +
                 ", got " + value;
        return std::string();
      },
      std::string(strict ? "NUMBER > " : "NUMBER >= ") + shown);
}
}  // namespace

CLI::Validator atLeast(double least) {
  return numberFrom(least, false);
}

CLI::Validator above(double least) {
  return numberFrom(least, true);
}

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

CLI::Validator sceneDirectory(const std::string& primeOnly) {
  return CLI::Validator(
      [primeOnly](std::string& path) -> std::string {
        namespace fs = std::filesystem;
        std::error_code ec;
        const fs::file_status st = fs::status(path, ec);
        if (fs::is_directory(st)) return std::string();
        if (!fs::exists(st))
          return "'" + path +
                 "' does not exist (a PRIME scene is a directory, a Malone or CGL "
                 "scene a file)";
        if (lowerExtension(path) == ".zip")
          return "'" + path +
                 "' is a zip: unzip it and give its scene directory (only the web page reads a "
                 "zip)";
        if (!primeOnly.empty())
          return "'" + path + "' is a file, and prime " + primeOnly +
                 " takes a PRIME scene directory: it is PRIME's command (Malone's and CGL's "
                 "scenes are files; prime --help says which commands read them)";
        return "'" + path +
               "' is a file that no system reads as its scene: a PRIME scene is a directory, a "
               "Malone scene a file of numbers (Malone, section 1.10), a CGL scene a "
               "scene-description file (Sweeney, Appendix 1); --format malone or --format cgl "
               "says where it departs from one";
      },
      "DIR");
}

}  // namespace prime::cli
