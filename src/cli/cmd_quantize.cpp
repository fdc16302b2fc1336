// prime quantize IN.png OUT.png --method M [--dither D] [--report]: any
// system's true-colour picture in 256 colours a 6-bit DAC (the IBM 8514/A's)
// can load, by the quantizers of thesis 4.4, with their error against the
// true-colour picture (CIEDE2000 and PSNR). `listing` is PRIME's fixed
// palette (the 1991 baseline) and `libimagequant` the reference a user would
// pick (for comparison only). docs/prime/quantization.md.
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <stdexcept>

#include "legacy_io/common/error.h"
#include "legacy_io/common/output_file.h"
#include "legacy_io/common/run_inputs.h"
#include "palette/png_image.h"
#include "palette/quantize/colour_difference.h"
#include "src/cli/commands.h"
#include "src/cli/option_values.h"
#include "src/cli/quantize_options.h"

namespace prime::cli {

void addQuantizeCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "quantize",
      "Map a true-colour PNG to 256 colours of a 6-bit DAC (thesis 4.4), with its error");
  auto in = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto method = std::make_shared<std::string>("median-cut");
  auto dither = std::make_shared<std::string>("none");
  auto colours = std::make_shared<int>(256);
  auto report = std::make_shared<bool>(false);
  auto repeat = std::make_shared<int>(1);
  auto quiet = std::make_shared<bool>(false);
  cmd->add_option("IN", *in, "True-colour PNG (any system's --png / --true-color-png)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("OUT", *out, "PNG to write: the quantized picture as the DAC shows it")
      ->required()
      ->check(outputName());
  cmd->add_option("--method", *method,
                  "popularity, median-cut (default), octree; listing (PRIME's fixed palette, "
                  "the 1991 baseline) or libimagequant (the reference, for comparison only)")
      ->check(CLI::IsMember({"popularity", "median-cut", "octree", "listing", "libimagequant"}));
  cmd->add_option("--dither", *dither, "none (default), ordered (Bayer 8x8), floyd-steinberg")
      ->check(CLI::IsMember({"none", "ordered", "floyd-steinberg"}));
  cmd->add_option("--colours", *colours, "Palette entries, 2..256 (256)")
      ->check(CLI::Range(2, 256));
  cmd->add_flag("--report", *report,
                "Print the error against IN (mean and max CIEDE2000, PSNR) and the CPU time");
  cmd->add_option("--repeat", *repeat,
                  "Quantize this many times and report the median CPU time (timing)")
      ->check(CLI::Range(1, 100));
  cmd->add_flag("-q,--quiet", *quiet, "Print nothing but the report");
  cmd->callback([=, &action] {
    action = [=] {
      const quantize::Dither d = *quantize::ditherFromName(*dither);
      // Usage errors (exit 2, as CLI11's).
      if (*method == "listing" && d != quantize::Dither::None) {
        std::cerr << "prime: --dither: the listing's fixed palette is never dithered (prime "
                     "quantize --help)\n";
        return 2;
      }
      if (*method == "libimagequant" && d == quantize::Dither::Ordered) {
        std::cerr << "prime: --dither: libimagequant has no ordered dithering (prime quantize "
                     "--help)\n";
        return 2;
      }
      // IN is an input of the run before OUT is checked: `quantize IN IN`,
      // `./IN` or a hard link to it are refused, not overwritten.
      io::protectInput(*in);
      io::checkOutputPath(*out);
      Image8 image;
      try {
        image = readPng(*in);
      } catch (const io::InputError&) {
        throw;  // a FIFO, a directory, too large: already named and said
      } catch (const std::runtime_error& e) {
        throw io::InputError({*in, std::nullopt, std::nullopt},
                             std::string("not a PNG that can be read: ") + e.what());
      }
      std::vector<double> seconds;
      quantize::Result r;
      for (int i = 0; i < *repeat; ++i) {
        const std::clock_t t0 = std::clock();  // process CPU time, every thread
        r = quantizeBy(image, *method, d, *colours);
        seconds.push_back(static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC);
      }
      std::nth_element(seconds.begin(),
                       seconds.begin() + static_cast<std::ptrdiff_t>(seconds.size() / 2),
                       seconds.end());
      const Image8 shown = quantize::present(r, image.width, image.height);
      writePng(*out, shown);
      if (!*quiet)
        std::printf("wrote %s: %d x %d, %zu palette entries (%s, dither %s)\n", out->c_str(),
                    image.width, image.height, r.palette.levels.size(), method->c_str(),
                    dither->c_str());
      if (*report) {
        const quantize::ImageError e = quantize::compareImages(image, shown);
        std::printf(
            "%s %s: mean dE00 %.3f, max dE00 %.2f, PSNR %.2f dB, CPU %.4f s (median of %d)\n",
            method->c_str(), dither->c_str(), e.meanDeltaE, e.maxDeltaE, e.psnr,
            seconds[seconds.size() / 2], *repeat);
      }
      return 0;
    };
  });
}

}  // namespace prime::cli
