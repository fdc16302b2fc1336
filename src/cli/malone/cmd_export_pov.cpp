// prime export-pov SCENE.mal OUT.pov: a Malone scene as POV-Ray 3.7 scene
// language (src/malone/pov_export.h). The shared verb (src/cli/verbs.cpp)
// runs it when the scene reads as Malone's numbers (or with --format malone).
#include <filesystem>
#include <iostream>

#include "legacy_io/malone/input.h"
#include "src/cli/malone/commands.h"
#include "src/cli/option_values.h"
#include "src/malone/pov_export.h"

namespace prime::cli::malone {

void addExportPovOptions(CLI::App* cmd, Action& action) {
  auto file = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto comments = std::make_shared<bool>(false);
  auto quiet = std::make_shared<bool>(false);
  auto options = std::make_shared<prime::malone::PovExportOptions>();
  cmd->add_option("SCENE", *file, "Malone scene file (a stream of numbers)")->required();
  cmd->add_option("OUT", *out, "POV-Ray scene file to write (e.g. scene.pov)")
      ->required()
      ->check(outputName());
  cmd->add_flag("--comments", *comments,
                "Extension, not the original: '#' starts a comment to the end of the line");
  cmd->add_option("--max-depth", options->maxDepth,
                  "Deepest ray traced, as prime trace's (default 7): max_trace_level")
      ->check(CLI::Range(1, 64));
  cmd->add_option("--min-weight", options->minWeight,
                  "MIN_WEIGHT, as prime trace's (default 0.01/256): adc_bailout")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_flag("-q,--quiet", *quiet, "Print nothing on success");
  cmd->callback([=, &action] {
    action = [=] {
      prime::malone::ReadOptions read;
      read.comments = *comments;
      const auto scene =
          prime::malone::buildScene(prime::malone::readSceneFile(*file, read), *file);
      const auto exported = prime::malone::exportPov(scene, *options);
      const std::filesystem::path target(*out);
      prime::malone::writePovFile(exported.pov, target);
      if (!*quiet)
        std::cout << "wrote " << *out << " (" << exported.objects << " objects, " << exported.lights
                  << " light sources)\nrender: povray +I" << target.filename().string() << " +W"
                  << exported.width << " +H" << exported.height << " -A File_Gamma=1.0 (from "
                  << (target.has_parent_path() ? target.parent_path().string() : std::string("."))
                  << ")\n";
      return 0;
    };
  });
}

}  // namespace prime::cli::malone
