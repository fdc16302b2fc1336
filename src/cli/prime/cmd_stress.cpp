// prime stress: the numerical stress suite (src/prime/stress, docs/prime/numerics.md).
#include <fstream>
#include <iostream>

#include "legacy_io/common/output_file.h"
#include "src/cli/commands.h"
#include "src/cli/option_values.h"
#include "src/prime/stress/stress.h"

namespace prime::cli {

void addStressCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "stress",
      "Numerical stress suite: adversarial rays against a long double / __float128 reference");
  auto profile = std::make_shared<std::string>("both");
  auto o = std::make_shared<stress::StressOptions>();
  auto csv = std::make_shared<std::string>();
  auto markdown = std::make_shared<bool>(false);
  auto images = std::make_shared<std::string>();
  auto divisor = std::make_shared<int>(4);
  auto noQuad = std::make_shared<bool>(false);
  auto list = std::make_shared<bool>(false);
  cmd->add_option("--profile", *profile, "1991, modern or both")
      ->check(CLI::IsMember({"1991", "modern", "both"}));
  cmd->add_option("--rays", o->raysPerClass, "Rays per class and profile")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000000));
  cmd->add_option("--class", o->classes, "Only these classes (repeatable)");
  cmd->add_option("--seed", o->seed, "Seed of the generator")->capture_default_str();
  cmd->add_option("--threads", o->threads, "Worker threads")
      ->capture_default_str()
      ->check(CLI::Range(0, 4096));
  cmd->add_option("--tolerance", o->toleranceUlps, "C of the conditioning tolerance C*u*(...)")
      ->capture_default_str()
      ->check(above(0));
  cmd->add_flag("--no-quad", *noQuad, "Skip the __float128 reference (long double only)");
  cmd->add_option("--csv", *csv, "Also write the figures as CSV to FILE");
  cmd->add_flag("--markdown", *markdown, "Print Markdown tables");
  cmd->add_option(
      "--images", *images,
      "Whole-image stability instead: every scene under DIR with Model.txt, transformed");
  cmd->add_option("--screen-divisor", *divisor, "Image stability: screen size divided by N")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  cmd->add_flag("--list", *list, "List the classes and exit");
  cmd->callback([=, &action] {
    action = [=]() -> int {
      if (*list) {
        for (const auto& c : stress::stressClasses())
          std::cout << c.name << ": " << c.description << "\n";
        return 0;
      }
      for (const auto& name : o->classes) {
        bool known = false;
        for (const auto& c : stress::stressClasses()) known = known || c.name == name;
        if (!known) {
          std::cerr << "prime stress: unknown class '" << name << "' (see --list)\n";
          return 2;
        }
      }
      auto log = [](const std::string& s) { std::cerr << s << "\n"; };
      if (!images->empty()) {
        stress::StabilityOptions so;
        so.scenesDir = *images;
        so.screenDivisor = *divisor;
        so.threads = o->threads;
        so.run1991 = *profile != "modern";
        so.runModern = *profile != "1991";
        so.log = log;
        std::cout << stress::formatStability(stress::runStability(so), *markdown);
        return 0;
      }
      stress::StressOptions opts = *o;
      opts.run1991 = *profile != "modern";
      opts.runModern = *profile != "1991";
      opts.quad = !*noQuad;
      opts.log = log;
      const auto results = stress::runStress(opts);
      std::cout << stress::formatTable(results, *markdown);
      if (!csv->empty()) {
        io::checkOutputPath(*csv);  // not an input of the run, its directory exists
        std::ofstream f(*csv);
        f << stress::formatCsv(results);
        if (!f) {
          std::cerr << "prime stress: cannot write " << *csv << "\n";
          return 2;
        }
      }
      return 0;
    };
  });
}

}  // namespace prime::cli
