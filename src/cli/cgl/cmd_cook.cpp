// prime cook OUT --reflectance FILE|33 NUMBERS: the Waterloo CGL package's
// `cook` utility (Sweeney 1985, section 9.9 and Appendix 1 section 9): a
// complete `cook` surface descriptor, its 66 Fresnel colour-vectors computed
// from the normal reflectance (src/cgl/cook.h), written to OUT. The package
// prompted on stdin; this port takes the values as options.
#include "legacy_io/cgl/reflectance.h"
#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"
#include "legacy_io/common/output_file.h"
#include "src/cgl/cook.h"
#include "src/cli/cgl/commands.h"
#include "src/cli/option_values.h"

namespace prime::cli::cgl {

namespace {

// 33 numbers: on the command line, or in a file (legacy_io/cgl/reflectance.h).
prime::cgl::Spectrum reflectanceOf(const std::vector<std::string>& args) {
  double v = 0;
  if (args.size() == 1 && !prime::cgl::isReflectanceNumber(args[0], v)) {
    io::InputFileOptions input;
    input.what = "a reflectance file";
    return prime::cgl::readReflectance(io::readInputText(args[0], input), args[0]);
  }
  const io::InputLocation where{"--reflectance"};
  std::vector<prime::cgl::ReflectanceNumber> numbers;
  for (const std::string& a : args) {
    if (!prime::cgl::isReflectanceNumber(a, v))
      throw io::InputError(where, "normal reflectance", "a real number", "'" + a + "'");
    numbers.push_back({v, where});
  }
  return prime::cgl::normalReflectance(numbers, where);
}

}  // namespace

void addCookCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "cook",
      "Write a Cook-Torrance surface descriptor with its 66 Fresnel colour-vectors (the Waterloo "
      "CGL package's cook)");
  auto out = std::make_shared<std::string>();
  auto refl = std::make_shared<std::vector<std::string>>();
  auto d = std::make_shared<prime::cgl::CookDescriptor>();
  cmd->add_option("OUT", *out, "The file to write the surface descriptor to")
      ->required()
      ->check(outputName());
  cmd->add_option("--reflectance", *refl,
                  "The normal reflectance R, 380-700 nm every 10 nm: a file of 33 numbers ('*' "
                  "lines are comments) or the 33 numbers; the Fresnel table is made from it, "
                  "the normal-colour-vector written is R/pi")
      ->required()
      ->expected(1, 33);
  cmd->add_option("--count", d->count, "The surface's number in its scene file")->check(above(0));
  cmd->add_option("--diffuse", d->diffuse, "k_d (usually 0.0-1.0)")->check(CLI::Range(0.0, 1.0e6));
  cmd->add_option("--specular", d->specular, "k_s (usually 0.0-1.0)")
      ->check(CLI::Range(0.0, 1.0e6));
  cmd->add_option("--m", d->m, "The rms facet slope m (usually 0.1-1.0)")
      ->check(CLI::Range(1.0e-6, 1.0e6));
  cmd->add_option("--reflect", d->reflect, "k_r (0.0-1.0)")->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--refract", d->refract, "k_t (0.0-1.0)")->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--index", d->index, "The refractive index")->check(CLI::Range(0.0, 1.0e6));
  cmd->add_option("--name", d->name, "The descriptor's comment: '* surface: NAME'");
  auto quiet = std::make_shared<bool>(false);
  cmd->add_flag("-q,--quiet", *quiet, "Print nothing on success");
  cmd->callback([=, &action] {
    action = [=] {
      prime::cgl::CookDescriptor desc = *d;
      desc.reflectance = reflectanceOf(*refl);
      const std::string text = prime::cgl::cookDescriptorText(desc);
      io::OutputFile f(*out);  // never over the reflectance file (an input), never half written
      f.write(text);
      f.commit();
      if (!*quiet)
        std::printf(
            "wrote %s: surface %d, Cook-Torrance, m %g, k_d %g, k_s %g, with its %d "
            "Fresnel colour-vectors\n",
            out->c_str(), desc.count, desc.m, desc.diffuse, desc.specular,
            prime::cgl::kFresnelAngles);
      return 0;
    };
  });
}

}  // namespace prime::cli::cgl
