#include "src/cli/render_record.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "legacy_io/common/digest.h"
#include "legacy_io/common/error.h"
#include "legacy_io/common/output_file.h"
#include "legacy_io/common/text_reader.h"
#include "src/cli/camera_flags.h"

namespace prime::cli {

namespace {

std::string band(int first, int last, int of) {
  return std::to_string(first) + "-" + std::to_string(last) + " of " + std::to_string(of);
}

}  // namespace

void writeRecord(const std::string& picture, RenderRecord r) {
  const std::optional<io::FileDigest> d = io::fileXxh3(picture);
  if (!d)
    throw io::InputError({picture, std::nullopt, std::nullopt}, "cannot read it back to record it");
  r.file = std::filesystem::path(picture).filename().string();
  r.bytes = d->bytes;
  r.hash = d->hash;
  std::string text =
      "# prime render record: what made " + r.file + " (docs/user-guide.md, \"Films and bands\")\n";
  text += "file " + r.file + "\n";
  text += "bytes " + std::to_string(r.bytes) + "\n";
  text += "xxh3 " + io::hex16(r.hash) + "\n";
  text += "render " + r.render + "\n";
  text += "system " + r.system + "\n";
  text += "output " + r.output + "\n";
  if (r.frame) text += "frame " + std::to_string(*r.frame) + "\n";
  text += "rows " + band(r.firstRow, r.lastRow, r.rows) + "\n";
  text += "file-rows " + band(r.fileFirstRow, r.fileLastRow, r.fileRows) + "\n";
  io::OutputFile out(recordPath(picture));
  out.write(text);
  out.commit();
}

std::optional<RenderRecord> readRecord(const std::string& picture) {
  const std::string path = recordPath(picture);
  // Read as an output of an earlier run, not as an input of this one (which
  // no output of this run could then replace).
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::string text(1 << 16, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  text = io::normalizeLineBreaks(text);
  RenderRecord r;
  bool seen[4] = {false, false, false, false};  // bytes, xxh3, render, rows
  std::istringstream lines(text);
  std::string line;
  int lineNo = 0;
  while (std::getline(lines, line)) {
    ++lineNo;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::string key;
    if (!(words >> key)) continue;
    const io::InputLocation where{path, lineNo, std::nullopt};
    auto bad = [&](const std::string& expected) {
      throw io::InputError(where, key, expected, io::quotedWord(line, 80));
    };
    auto bandOf = [&](int& first, int& last, int& of) {
      std::string range, word;
      if (!(words >> range >> word >> of) || word != "of") bad("FIRST-LAST of ROWS");
      const auto dash = range.find('-', 1);
      const auto a = exactInt(range.substr(0, dash));
      const auto b = dash == std::string::npos ? std::nullopt : exactInt(range.substr(dash + 1));
      if (!a || !b) bad("FIRST-LAST of ROWS");
      first = *a;
      last = *b;
    };
    if (key == "file") {
      std::getline(words >> std::ws, r.file);
    } else if (key == "bytes") {
      if (!(words >> r.bytes)) bad("a number of bytes");
      seen[0] = true;
    } else if (key == "xxh3") {
      std::string h;
      if (!(words >> h) || h.size() != 16 ||
          h.find_first_not_of("0123456789abcdef") != std::string::npos)
        bad("16 hex digits");
      r.hash = std::stoull(h, nullptr, 16);
      seen[1] = true;
    } else if (key == "render") {
      if (!(words >> r.render) || r.render.size() != 16) bad("16 hex digits");
      seen[2] = true;
    } else if (key == "system") {
      words >> r.system;
    } else if (key == "output") {
      words >> r.output;
    } else if (key == "frame") {
      int f = 0;
      if (!(words >> f)) bad("a frame number");
      r.frame = f;
    } else if (key == "rows") {
      bandOf(r.firstRow, r.lastRow, r.rows);
      seen[3] = true;
    } else if (key == "file-rows") {
      bandOf(r.fileFirstRow, r.fileLastRow, r.fileRows);
    } else {
      bad("one of file, bytes, xxh3, render, system, output, frame, rows, file-rows");
    }
  }
  const char* names[4] = {"bytes", "xxh3", "render", "rows"};
  for (int i = 0; i < 4; ++i)
    if (!seen[i])
      throw io::InputError({path, std::nullopt, std::nullopt}, names[i],
                           "a line '" + std::string(names[i]) + " ...'", "none");
  return r;
}

bool recordMatches(const std::string& picture, const std::string& render) {
  std::optional<RenderRecord> r;
  try {
    r = readRecord(picture);
  } catch (const io::InputError&) {
    return false;  // a damaged record: the frame is rendered again
  }
  if (!r || r->render != render) return false;
  const std::optional<io::FileDigest> d = io::fileXxh3(picture);
  return d && d->bytes == r->bytes && d->hash == r->hash;
}

}  // namespace prime::cli
