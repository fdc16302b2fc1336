// How every command takes and checks its options' values, written once:
//   - an option that takes several values takes exactly what it declares and
//     never the scene after it (takeDeclaredValues);
//   - checks whose messages say what was expected and what was found
//     (outputName, atLeast, above, sceneDirectory).
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace prime::cli {

// Run on the whole parser once every command is registered, and on the
// command line before it is parsed. CLI11 lets an option with several values
// take every word up to the next flag, so `--background 1 2 3 scene.cgl` read
// the scene as a fourth colour and `--textures DIR scene.cgl` as a second
// directory, and the message blamed something else. After this:
//   - an option of N values takes N;
//   - an option of M..N values (--light-radius, --reflectance) or of any
//     number (--scale-sizes, --textures, --class) takes a run of numbers, or
//     one word that is not a number (repeat the flag for more): the word after
//     them is the next argument (args is reordered so: the words CLI11 would
//     also have taken move before the option, keeping their order among the
//     positional arguments).
void takeDeclaredValues(CLI::App& app, std::vector<std::string>& args);

// Whether the whole word is a number, as strtod reads one ("-0.5", "1e3"):
// what tells an option's value from a flag or a file.
bool isNumber(const std::string& word);

// An output file's name: not empty (`--png ''` wrote nothing and said nothing).
CLI::Validator outputName();
// A number not below `least`: "must be at least 0, got -1" (CLI11's own said
// "not in range 0.000000 to 1797...", 309 digits).
CLI::Validator atLeast(double least);
// A number above `least` ("must be more than 0, got 0").
CLI::Validator above(double least);
// The extension of `path`'s file name in lower case (".png", or "").
std::string lowerExtension(const std::string& path);
// A PRIME scene directory, the default of the verbs every system shares: a
// file no system reads gets a message that says so, not CLI11's "Directory
// is actually a file". A command that is PRIME's only (`primeOnly`: its
// name) says so of any file; a zip is told to be unzipped.
CLI::Validator sceneDirectory(const std::string& primeOnly = "");

}  // namespace prime::cli
