// prime check DIR: the values of a scene's text inputs that the 1991 listing
// turns into NaN, a division by zero or an invisible object (scene_check.h),
// and anything `prime model` would refuse. Exit 0 clean, 1 with problems.
#include <filesystem>
#include <iostream>

#include "legacy_io/common/error.h"
#include "legacy_io/prime/model_builder.h"
#include "legacy_io/prime/model_commit.h"
#include "src/cli/commands.h"
#include "src/cli/option_values.h"
#include "src/cli/prime/scene_check.h"

namespace prime::cli {

void addCheckCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "check",
      "Check a scene's text inputs for values the 1991 listing turns into NaN, a division by "
      "zero or an invisible object (non-integer kRH/kTH, indx 1, tT >= 1, colours on the fixed "
      "palette entries)");
  auto dir = std::make_shared<std::string>();
  auto quiet = std::make_shared<bool>(false);
  cmd->add_option("DIR", *dir, "Scene directory")->required()->check(sceneDirectory("check"));
  cmd->add_flag("-q,--quiet", *quiet, "Print nothing when the scene is clean");
  cmd->callback([=, &action] {
    action = [=] {
      const io::SceneDir scene(*dir);
      // A directory with nothing of a PRIME scene in it is not a clean scene.
      if (!io::holdsPrimeScene(scene))
        throw io::InputError({*dir, std::nullopt, std::nullopt}, "DIR",
                             "a PRIME scene directory (Model.txt or a 1991 Model.c, prim/, obj/; "
                             "prime new DIR writes one)",
                             "none of them");
      std::vector<SceneProblem> problems;
      // What `prime model` would refuse (the first error), and its warnings;
      // the calls of Model.txt, or of a 1991 Model.c (M42).
      if (std::filesystem::exists(scene.find(".", "Model.txt")) ||
          std::filesystem::exists(scene.find(".", "Model.c"))) {
        try {
          for (const auto& w : io::buildModel(scene).warnings) problems.push_back({w});
        } catch (const io::InputError& e) {
          problems.push_back({e.what()});
        }
      }
      for (auto& p : checkHues(scene)) problems.push_back(std::move(p));
      for (const auto& p : problems) std::cout << p.message << "\n";
      if (!problems.empty()) {
        std::cout << *dir << ": " << problems.size() << " problem(s)\n";
        return 1;
      }
      if (!*quiet) std::cout << *dir << ": no problems found\n";
      return 0;
    };
  });
}

}  // namespace prime::cli
