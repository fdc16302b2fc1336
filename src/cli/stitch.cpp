// `prime stitch OUT PIECE...`: the pieces `prime trace --rows` rendered,
// joined into the whole picture, byte for byte what one process renders.
// Each piece's render record (src/cli/render_record.h) says which rows it
// holds and of which render; stitch refuses gaps, overlaps, pieces of
// different renders and pieces changed since they were written.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "legacy_io/common/digest.h"
#include "legacy_io/common/error.h"
#include "legacy_io/common/output_file.h"
#include "palette/png_image.h"
#include "src/cli/commands.h"
#include "src/cli/option_values.h"
#include "src/cli/render_record.h"
#include "src/cli/system.h"

namespace prime::cli {

namespace {

// Every system's PNGs (--png, --true-color-png, --png-8514): rows of
// palette indices (an 8514/A screen) or of RGB; the stitched file is written
// as the pieces were, with their palette, pHYs and text (one render's pieces
// say the same: --rows is not among the settings they name).
RowPicture readPngRows(const std::string& path) {
  const PngFile png = readPngFile(path);
  const int w = png.indexed ? png.palette.width : png.rgb.width;
  const int h = png.indexed ? png.palette.height : png.rgb.height;
  RowPicture p;
  p.head = {static_cast<std::uint8_t>(w >> 24),    static_cast<std::uint8_t>(w >> 16),
            static_cast<std::uint8_t>(w >> 8),     static_cast<std::uint8_t>(w),
            static_cast<std::uint8_t>(h >> 24),    static_cast<std::uint8_t>(h >> 16),
            static_cast<std::uint8_t>(h >> 8),     static_cast<std::uint8_t>(h),
            static_cast<std::uint8_t>(png.indexed)};
  p.rowBytes = static_cast<std::size_t>(w) * (png.indexed ? 1 : 3);
  p.rows = h;
  p.pixels = png.indexed ? png.palette.indices : png.rgb.rgb;
  return p;
}
void writePngRows(const std::string& path, const RowPicture& p, const std::string& piece) {
  PngFile like = readPngFile(piece);  // its palette and text
  if (like.indexed) {
    IndexedImage8& img = like.palette;
    img.width = static_cast<int>(p.rowBytes);
    img.height = p.rows;
    img.indices = p.pixels;
    writeIndexedPng(path, img, like.meta);
  } else {
    Image8 img;
    img.width = static_cast<int>(p.rowBytes / 3);
    img.height = p.rows;
    img.rgb = p.pixels;
    writePng(path, img, like.meta);
  }
}
constexpr PieceKind kPng{readPngRows, writePngRows};

struct Piece {
  std::string path;
  RenderRecord record;
};

std::string rowsText(int first, int last) {
  return first == last ? "row " + std::to_string(first)
                       : "rows " + std::to_string(first) + "-" + std::to_string(last);
}

int stitch(const std::string& out, const std::vector<std::string>& paths) {
  // The same piece named twice (or by two names) is said to be, not taken
  // for two bands that overlap.
  for (std::size_t i = 0; i < paths.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) {
      std::error_code ec;
      if (paths[i] == paths[j] || std::filesystem::equivalent(paths[i], paths[j], ec))
        throw io::InputError({paths[i], std::nullopt, std::nullopt},
                             "is given twice (also as " + paths[j] + "): name each piece once");
    }
  std::vector<Piece> pieces;
  for (const std::string& path : paths) {
    std::optional<RenderRecord> r = readRecord(path);
    if (!r)
      throw io::InputError({path, std::nullopt, std::nullopt},
                           "has no render record (" + recordPath(path) +
                               "): not a piece that prime trace --rows wrote");
    const std::optional<io::FileDigest> d = io::fileXxh3(path);
    if (!d || d->bytes != r->bytes || d->hash != r->hash)
      throw io::InputError({path, std::nullopt, std::nullopt},
                           "is not the piece its render record describes (its bytes changed "
                           "since it was written): render it again");
    pieces.push_back({path, *r});
  }
  const RenderRecord& first = pieces.front().record;
  for (const Piece& p : pieces) {
    const RenderRecord& r = p.record;
    auto differ = [&](const std::string& what, const std::string& a, const std::string& b) {
      throw io::InputError({p.path, std::nullopt, std::nullopt},
                           "is not a piece of the same render as " + pieces.front().path + ": " +
                               what + " " + b + " here, " + a + " there");
    };
    if (r.render != first.render)
      differ("render (settings, scene or program)", first.render, r.render);
    if (r.output != first.output) differ("output", first.output, r.output);
    if (r.rows != first.rows || r.fileRows != first.fileRows)
      differ("picture rows", std::to_string(first.rows), std::to_string(r.rows));
  }
  // The bands must tile the picture's rows.
  std::sort(pieces.begin(), pieces.end(),
            [](const Piece& a, const Piece& b) { return a.record.firstRow < b.record.firstRow; });
  int next = 0;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const RenderRecord& r = pieces[i].record;
    if (r.firstRow > next)
      throw io::InputError({pieces[i].path, std::nullopt, std::nullopt},
                           "leaves a gap: " + rowsText(next, r.firstRow - 1) +
                               " of the picture are in no piece given");
    if (r.firstRow < next)
      throw io::InputError({pieces[i].path, std::nullopt, std::nullopt},
                           "overlaps " + pieces[i - 1].path + ": both hold " +
                               rowsText(r.firstRow, std::min(next - 1, r.lastRow)));
    next = r.lastRow + 1;
  }
  if (next < first.rows)
    throw io::InputError({pieces.back().path, std::nullopt, std::nullopt},
                         "is the last piece, but " + rowsText(next, first.rows - 1) + " of the " +
                             std::to_string(first.rows) + " are in no piece given");
  // The kind: the system's own picture file, or a PNG.
  const PieceKind* kind = nullptr;
  if (first.output == "--png" || first.output == "--true-color-png" ||
      first.output == "--png-8514") {
    kind = &kPng;
  } else if (const System* sys = findSystem(first.system); sys && sys->pieceKind) {
    kind = sys->pieceKind(first.output);
  }
  if (kind == nullptr)
    throw io::InputError({pieces.front().path, std::nullopt, std::nullopt},
                         "output " + first.output + " of " + first.system +
                             " is not a kind of picture stitch joins");
  io::checkOutputPath(out);
  RowPicture whole;
  std::vector<RowPicture> rows;
  for (const Piece& p : pieces) {
    rows.push_back(kind->read(p.path));
    const RowPicture& r = rows.back();
    if (r.head != rows.front().head || r.rowBytes != rows.front().rowBytes ||
        r.rows != rows.front().rows || r.rows != first.fileRows)
      throw io::InputError({p.path, std::nullopt, std::nullopt},
                           "is not the same size of picture as " + pieces.front().path);
  }
  whole = rows.front();
  for (int y = 0; y < whole.rows; ++y) {
    const std::size_t at = static_cast<std::size_t>(y) * whole.rowBytes;
    bool placed = false;
    for (std::size_t i = 0; i < pieces.size() && !placed; ++i)
      if (y >= pieces[i].record.fileFirstRow && y <= pieces[i].record.fileLastRow) {
        std::memcpy(whole.pixels.data() + at, rows[i].pixels.data() + at, whole.rowBytes);
        placed = true;
      }
    if (placed) continue;
    // A row outside the picture (the screen around it): every piece has it.
    for (std::size_t i = 1; i < pieces.size(); ++i)
      if (std::memcmp(rows[i].pixels.data() + at, whole.pixels.data() + at, whole.rowBytes) != 0)
        throw io::InputError({pieces[i].path, std::nullopt, std::nullopt},
                             "differs from " + pieces.front().path + " at row " +
                                 std::to_string(y) +
                                 ", which is outside every band: not pieces of one render");
  }
  kind->write(out, whole, pieces.front().path);
  std::printf("stitched %zu pieces of %s (%d rows of the render)\nwrote %s\n", pieces.size(),
              first.output.c_str(), first.rows, out.c_str());
  return 0;
}

}  // namespace

void addStitchCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "stitch",
      "Join the pieces prime trace --rows rendered into the whole picture, byte for byte what "
      "one process renders (a graph file and its companion, a PPM, an RLE or a PNG)");
  auto out = std::make_shared<std::string>();
  auto pieces = std::make_shared<std::vector<std::string>>();
  cmd->add_option("OUT", *out, "The whole picture to write")->required()->check(outputName());
  cmd->add_option("PIECE", *pieces, "The pieces, in any order (each with its .render record)")
      ->required();
  cmd->callback(
      [out, pieces, &action] { action = [out, pieces] { return stitch(*out, *pieces); }; });
}

}  // namespace prime::cli
