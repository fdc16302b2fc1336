// prime export PICTURE.rle OUT and prime view PICTURE.rle: the CGL package's
// pictures (RLE or raw frames, Appendix 3's `encode` option) as PNG, as the
// other CGL picture format, through PRIME's 8514/A, or in a window (the
// package's `rl` utility showed an RLE file on the frame buffer).
#include <filesystem>
#include <iostream>

#include "legacy_io/cgl/frame.h"
#include "palette/png_image.h"
#include "palette/window/live_rgb_frame.h"
#include "src/cli/cgl/commands.h"
#include "src/cli/cgl/picture.h"
#include "src/cli/live_render.h"
#include "src/cli/option_values.h"
#include "src/cli/view_8514.h"

namespace prime::cli::cgl {

namespace {

using prime::cgl::Frame;

std::string lowerExtension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// The picture's format: --format, else the extension (.raw is raw, anything
// else RLE: the package's default build wrote RLE).
Frame readPicture(const std::string& path, const std::string& format) {
  const bool raw = format == "raw" || (format.empty() && lowerExtension(path) == ".raw");
  return raw ? prime::cgl::readRawFile(path) : prime::cgl::readRleFile(path);
}

}  // namespace

bool isPicture(const std::string& path, const std::string& format) {
  if (format == "rle" || format == "raw") return true;
  const std::string ext = lowerExtension(path);
  return format.empty() && (ext == ".rle" || ext == ".raw");
}

void addExportOptions(CLI::App* cmd, Action& action) {
  {
    auto file = std::make_shared<std::string>();
    auto out = std::make_shared<std::string>();
    auto format = std::make_shared<std::string>();
    auto as8514 = std::make_shared<bool>(false);
    auto quiet = std::make_shared<bool>(false);
    cmd->add_option("PICTURE", *file, "CGL picture: RLE (.rle) or raw frame (.raw)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("OUT", *out, "Output: .png, .rle or .raw")->required()->check(outputName());
    cmd->add_option("--format", *format, "The picture's format (default: from its extension)")
        ->check(CLI::IsMember({"rle", "raw"}));
    cmd->add_flag("--8514", *as8514,
                  "PNG as PRIME's IBM 8514/A (1991) would have shown it (ColorNum's palette)");
    cmd->add_flag("-q,--quiet", *quiet, "Print nothing on success");
    cmd->callback([=, &action] {
      action = [=] {
        const Frame frame = readPicture(*file, *format);
        const std::string ext = lowerExtension(*out);
        std::string what;
        if (ext == ".rle") {
          prime::cgl::writeRleFile(*out, frame);
          what = "RLE";
        } else if (ext == ".raw") {
          prime::cgl::writeRawFile(*out, frame);
          what = "raw frame";
        } else if (*as8514) {
          write8514Png(*out, prime::cgl::toRgbImage(frame));
          what = "PNG on the 8514/A palette";
        } else {
          writePng(*out, frameImage(frame));
          what = "PNG";
        }
        if (!*quiet)
          std::cout << "wrote " << *out << ": " << Frame::kSize << " x " << Frame::kSize << " "
                    << what << "\n";
        return 0;
      };
    });
  }
}

void addViewOptions(CLI::App* cmd, Action& action) {
  {
    auto file = std::make_shared<std::string>();
    auto format = std::make_shared<std::string>();
    auto live = std::make_shared<LiveOptions>();
    cmd->add_option("PICTURE", *file, "CGL picture: RLE (.rle) or raw frame (.raw)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--format", *format, "The picture's format (default: from its extension)")
        ->check(CLI::IsMember({"rle", "raw"}));
    addLiveWindowOptions(cmd, live, false);
    cmd->callback([=, &action] {
      action = [=] {
        const Frame picture = readPicture(*file, *format);
        display::LiveRgbFrame frame(Frame::kSize, Frame::kSize);
        LiveOptions options = *live;
        options.caption = *file;
        options.commandName = "view";
        LiveRender window(frame, options);
        if (!window.windowed()) {
          std::cerr << "prime: nothing to show without a window; `prime export " << *file
                    << " OUT.png` writes the picture\n";
          return 0;
        }
        std::vector<std::uint32_t> row(Frame::kSize);
        for (int y = 0; y < Frame::kSize; ++y) {
          for (int x = 0; x < Frame::kSize; ++x) {
            const std::uint32_t w = picture.words[static_cast<std::size_t>(y) * Frame::kSize + x];
            row[static_cast<std::size_t>(x)] =
                static_cast<std::uint32_t>(prime::cgl::redOf(w)) << 16 |
                static_cast<std::uint32_t>(prime::cgl::greenOf(w)) << 8 |
                static_cast<std::uint32_t>(prime::cgl::blueOf(w));
          }
          frame.setRow(y, row);
        }
        window.run([] {});
        window.waitForEsc("Esc to close");
        return 0;
      };
    });
  }
}

}  // namespace prime::cli::cgl
