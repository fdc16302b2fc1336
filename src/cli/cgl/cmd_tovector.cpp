// prime tovector R G B: the Waterloo CGL package's `tovector` utility
// (Sweeney 1985, Appendix 1 section 9): the colour-vector of an RGB triple
// (section 10: only the 450, 550 and 600 nm samples set) on the standard
// output, as a scene file writes one, and the RGB that colour-vector converts
// back to (ToRGB, section 9.1) on the standard error as a check.
#include <cstdio>

#include "src/cgl/colour.h"
#include "src/cli/cgl/commands.h"

namespace prime::cli::cgl {

void addTovectorCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "tovector", "The colour-vector of an RGB triple (the Waterloo CGL package's tovector)");
  auto rgb = std::make_shared<std::vector<int>>();
  auto phosphors = std::make_shared<std::string>("electrohome");
  cmd->add_option("RGB", *rgb, "Red, green and blue, 0..255")
      ->required()
      ->expected(3)
      ->check(CLI::Range(0, 255));
  cmd->add_option("--phosphors", *phosphors,
                  "RGB to XYZ: the Electrohome ECM 1301 monitor (default) or NTSC")
      ->check(CLI::IsMember({"electrohome", "ntsc"}));
  cmd->callback([=, &action] {
    action = [=] {
      const prime::cgl::Phosphors p =
          *phosphors == "ntsc" ? prime::cgl::Phosphors::Ntsc : prime::cgl::Phosphors::Electrohome;
      const prime::cgl::Rgb8 in{(*rgb)[0], (*rgb)[1], (*rgb)[2]};
      const prime::cgl::Spectrum c = prime::cgl::rgbToSpectrum(in, p);
      std::fputs(prime::cgl::colourVectorText(c).c_str(), stdout);
      const prime::cgl::Rgb8 back = prime::cgl::toRgb(c, p);
      std::fprintf(stderr, "%d %d %d\n", back.r, back.g, back.b);
      return 0;
    };
  });
}

}  // namespace prime::cli::cgl
