// prime model DIR: build the scene's databases from its text inputs: the
// calls of Model.txt, or of a 1991 disk's Model.c (M42).
#include <filesystem>
#include <iostream>

#include "legacy_io/prime/model_builder.h"
#include "legacy_io/prime/model_commit.h"
#include "src/cli/commands.h"
#include "src/cli/option_values.h"
#include "src/cli/prime/scene_check.h"
#include "src/prime/scene/scene_loader.h"

namespace prime::cli {

namespace fs = std::filesystem;

void addModelCommand(CLI::App& app, Action& action) {
  auto* cmd =
      app.add_subcommand("model", "Build a scene's databases from its text inputs, as Model.c did");
  auto dir = std::make_shared<std::string>();
  auto options = std::make_shared<io::ModelOptions>();
  auto quiet = std::make_shared<bool>(false);
  auto wait = std::make_shared<bool>(false);
  auto verify = std::make_shared<bool>(false);
  cmd->add_option("DIR", *dir,
                  "Scene directory (holds Model.txt or a 1991 Model.c, prim/, obj/, map/ ...)")
      ->required()
      ->check(sceneDirectory("model"));
  cmd->add_flag("--copy-type-from-source", options->copyTypeFromSource,
                "Give primitives copied by an O entry their source's type (not the listing: K33)");
  cmd->add_flag(
      "--no-16bit-limit", [options](std::int64_t) { options->limitPrimFileTo16Bits = false; },
      "Allow more than 113 primitives (the listing's 16-bit ftell stops there: E40)");
  cmd->add_flag("--allow-empty", options->allowEmpty,
                "Build databases even if Model.txt lists no object (refused otherwise: M22)");
  cmd->add_flag("--wait", *wait,
                "If another prime model is writing DIR, wait for it (default: say busy, M20)");
  cmd->add_flag("--verify", *verify,
                "Build nothing: finish an interrupted run and check the databases against "
                "DIR/prime-model.stamp (M19)");
  cmd->add_flag("-q,--quiet", *quiet,
                "No summary (warnings about the scene still go to standard error)");
  cmd->callback([=, &action] {
    action = [=] {
      const io::SceneDir scene(*dir);
      const auto lock = io::lockForModel(scene, *wait);
      if (*verify) {
        const bool finished = io::settleModel(scene);
        io::verifyModel(scene);
        if (!*quiet)
          std::cout << "verified " << *dir << ": "
                    << (finished ? "finished an interrupted prime model run; " : "")
                    << "the databases are the ones the last run wrote\n";
        return 0;
      }
      const io::Model model = io::buildModel(scene, *options);
      io::writeModel(scene, model, lock.get());
      // M42: Model.txt wins over a 1991 disk's Model.c; said, not silent.
      if (std::error_code ec; fs::exists(scene.find(".", "Model.txt"), ec) &&
                              fs::exists(scene.find(".", "Model.c"), ec))
        std::cerr << "prime: " << scene.display(scene.find(".", "Model.c"))
                  << " left alone: the calls were read from "
                  << scene.display(scene.find(".", "Model.txt"))
                  << " (Model.txt wins when a scene has both)\n";
      for (const auto& w : model.warnings) std::cerr << "prime: warning: " << w << "\n";
      // The values the listing turns into NaN or invisible objects (prime check).
      for (const auto& p : checkHues(scene)) std::cerr << "prime: warning: " << p.message << "\n";
      // M34: shared subtrees whose expansion is large, said when the scene
      // is built, not only when it is traced. A scene the renderer would
      // refuse is reported by trace, with its own message.
      try {
        for (const auto& w : sharedSubtreeWarnings(loadScene(scene)))
          std::cerr << "prime: warning: " << w << "\n";
      } catch (const io::InputError&) {
      }
      if (!*quiet)
        std::cout << "modelled " << *dir << ": " << model.objects.size() << " object file(s), "
                  << model.list.objects.size() << " in the object list, "
                  << model.prims.prims.size() << " primitive record(s), " << model.maps.size() / 3
                  << " texture map(s)\n";
      return 0;
    };
  });
}

}  // namespace prime::cli
