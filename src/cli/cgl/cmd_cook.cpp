// prime cook OUT --reflectance FILE|33 NUMBERS: the Waterloo CGL package's
// `cook` utility (Sweeney 1985, section 9.9 and Appendix 1 section 9): a
// complete `cook` surface descriptor, its 66 Fresnel colour-vectors computed
// from the normal reflectance (src/cgl/cook.h), written to OUT. The package
// prompted on stdin; this port takes the values as options.
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"
#include "legacy_io/common/output_file.h"
#include "legacy_io/common/text_reader.h"
#include "src/cgl/cook.h"
#include "src/cli/cgl/commands.h"
#include "src/cli/option_values.h"

namespace prime::cli::cgl {

namespace {

bool isNumber(const std::string& s, double& v) {
  std::istringstream in(s);
  in >> v;
  return !in.fail() && in.eof();
}

// 33 numbers: on the command line, or in a file (blank lines and lines whose
// first non-blank character is '*' are comments, as in a scene file).
prime::cgl::Spectrum reflectanceOf(const std::vector<std::string>& args) {
  std::vector<double> values;
  std::string where = "--reflectance";
  double v = 0;
  if (args.size() == 1 && !isNumber(args[0], v)) {
    where = args[0];
    io::InputFileOptions input;
    input.what = "a reflectance file";
    std::istringstream in(io::normalizeLineBreaks(io::readInputText(args[0], input)));
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
      ++lineNo;
      const auto first = line.find_first_not_of(" \t\r");
      if (first == std::string::npos || line[first] == '*') continue;
      std::istringstream words(line);
      std::string w;
      while (words >> w) {
        if (!isNumber(w, v))
          throw io::InputError({args[0], lineNo}, "normal reflectance", "a real number",
                               "'" + w + "'");
        values.push_back(v);
      }
    }
  } else {
    for (const std::string& a : args) {
      if (!isNumber(a, v))
        throw io::InputError(io::InputLocation{where}, "normal reflectance", "a real number",
                             "'" + a + "'");
      values.push_back(v);
    }
  }
  if (values.size() != static_cast<std::size_t>(prime::cgl::kSpectrumSamples))
    throw io::InputError(io::InputLocation{where}, "normal reflectance",
                         "33 numbers (380 to 700 nm every 10 nm)",
                         std::to_string(values.size()) + " numbers");
  prime::cgl::Spectrum r{};
  for (std::size_t k = 0; k < r.size(); ++k) {
    if (!(values[k] >= 0.0 && values[k] < 1.0))
      throw io::InputError(io::InputLocation{where},
                           "normal reflectance at " + std::to_string(380 + 10 * k) + " nm",
                           "0 <= R < 1", std::to_string(values[k]));
    r[k] = values[k];
  }
  return r;
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
  cmd->add_option("--diffuse", d->diffuse, "k_d (0.0-1.0)")->check(CLI::Range(0.0, 1.0e6));
  cmd->add_option("--specular", d->specular, "k_s (0.0-1.0)")->check(CLI::Range(0.0, 1.0e6));
  cmd->add_option("--m", d->m, "The rms facet slope m (0.1-1.0)")->check(CLI::Range(1.0e-6, 1.0e6));
  cmd->add_option("--reflect", d->reflect, "k_r (0.0-1.0)")->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--refract", d->refract, "k_t (0.0-1.0)")->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--index", d->index, "The refractive index")->check(CLI::Range(0.0, 1.0e6));
  cmd->add_option("--name", d->name, "The descriptor's comment: '* surface: NAME'");
  cmd->callback([=, &action] {
    action = [=] {
      prime::cgl::CookDescriptor desc = *d;
      desc.reflectance = reflectanceOf(*refl);
      const std::string text = prime::cgl::cookDescriptorText(desc);
      io::OutputFile f(*out);  // never over the reflectance file (an input), never half written
      f.write(text);
      f.commit();
      return 0;
    };
  });
}

}  // namespace prime::cli::cgl
