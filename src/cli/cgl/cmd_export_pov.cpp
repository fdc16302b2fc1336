// prime export-pov SCENE.cgl OUT.pov: a Waterloo CGL scene as POV-Ray 3.7
// scene language (src/cgl/pov_export.h), its texture maps as PNG files beside
// OUT.pov. The shared verb (src/cli/verbs.cpp) runs it when the scene reads as a
// CGL scene-description file (or with --format cgl).
#include <filesystem>
#include <iostream>

#include "legacy_io/common/output_file.h"
#include "palette/png_image.h"
#include "src/cgl/pov_export.h"
#include "src/cli/cgl/commands.h"
#include "src/cli/cgl/options.h"
#include "src/cli/option_values.h"

namespace prime::cli::cgl {

void addExportPovOptions(CLI::App* cmd, Action& action) {
  auto o = std::make_shared<CglOptions>();
  auto out = std::make_shared<std::string>();
  auto quiet = std::make_shared<bool>(false);
  addCglOptions(cmd, *o, false);
  cmd->add_option("OUT", *out,
                  "POV-Ray scene file to write (e.g. scene.pov); texture maps are written beside "
                  "it as <OUT stem>-texture<k>.png")
      ->required()
      ->check(outputName());
  cmd->add_option("--aalevel", o->aalevel,
                  "Anti-aliasing level the picture is compared at (default: the file's): 0 puts "
                  "POV-Ray's pixel centres on CGL's pixel corners and writes -A")
      ->check(CLI::IsMember({0, 1, 2, 4, 8}));
  cmd->add_flag("-q,--quiet", *quiet, "Print nothing on success");
  cmd->callback([=, &action] {
    action = [=] {
      const prime::cgl::SceneFile file = readCgl(*o, *quiet);
      const prime::cgl::Scene scene = buildCgl(*o, file);
      const std::filesystem::path target(*out);
      prime::cgl::PovExportOptions options;
      options.program = file.program;
      options.phosphors = renderSettings(*o, file).phosphors;
      options.textureStem = target.stem().string();
      const auto exported = prime::cgl::exportPov(scene, options);
      const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : ".";
      // All or none: a full disk at the scene file leaves no texture behind.
      io::OutputSet files;
      for (const auto& img : exported.images) {
        Image8 png;
        png.width = png.height = prime::cgl::Frame::kSize;
        png.rgb.reserve(img.frame.words.size() * 3);
        for (std::uint32_t w : img.frame.words) {
          png.rgb.push_back(static_cast<std::uint8_t>(prime::cgl::redOf(w)));
          png.rgb.push_back(static_cast<std::uint8_t>(prime::cgl::greenOf(w)));
          png.rgb.push_back(static_cast<std::uint8_t>(prime::cgl::blueOf(w)));
        }
        writePng(files.add((dir / img.file).string()), png);
      }
      files.add(target.string()).write(exported.pov);
      files.commit();
      if (!*quiet) {
        std::cout << "wrote " << *out << " (" << exported.objects << " objects, " << exported.lights
                  << " light sources";
        if (exported.boxesOmitted > 0)
          std::cout << "; " << exported.boxesOmitted
                    << " super boxes left to POV-Ray's own bounding";
        std::cout << ")";
        for (const auto& img : exported.images) std::cout << " and " << (dir / img.file).string();
        std::cout << "\nrender: povray +I" << target.filename().string() << " " << exported.povArgs
                  << " File_Gamma=1.0 (from " << dir.string() << ")\n";
      }
      return 0;
    };
  });
}

}  // namespace prime::cli::cgl
