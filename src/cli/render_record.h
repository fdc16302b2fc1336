// The render record beside each picture a film's frame or a band's piece
// writes (docs/user-guide.md, "Films and bands"): FILE.render, plain text,
//
//   # prime render record: what made frame0007.ppm (docs/user-guide.md, "Films and bands")
//   file frame0007.ppm
//   bytes 589839
//   xxh3 0123456789abcdef
//   render 89abcdef01234567
//   system malone
//   output --ppm
//   frame 7
//   rows 0-383 of 384
//   file-rows 0-383 of 384
//
// `render` is one hash of the system, every setting that changes pixels and
// the bytes of the scene's files (not of the outputs, the thread count or
// the band); two records with the same `render` are pieces of one picture.
// `rows` is the band of the picture, `file-rows` the rows of this file it
// covers (PRIME's screen PNG places the picture lower on its screen). A
// frame whose every output has a record that matches its file's bytes and
// the run's `render` is done: a rerun skips it. Written last, after every
// output of the frame or piece, each through io::OutputFile.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace prime::cli {

struct RenderRecord {
  std::string file;  // the picture's name, without its directory
  std::uint64_t bytes = 0, hash = 0;
  std::string render;  // 16 hex digits
  std::string system, output;
  std::optional<int> frame;
  int firstRow = 0, lastRow = 0, rows = 0;               // the band, of the picture's rows
  int fileFirstRow = 0, fileLastRow = -1, fileRows = 0;  // the rows of this file it covers
};

inline std::string recordPath(const std::string& picture) {
  return picture + ".render";
}
// Writes `picture`'s record, its bytes and hash read from the file.
void writeRecord(const std::string& picture, RenderRecord record);
// The record beside `picture`; nullopt when there is none. Throws
// io::InputError naming the record's file, line and field when it is not one.
std::optional<RenderRecord> readRecord(const std::string& picture);
// Whether `picture` is done: its record exists, names `render`, and the
// file's bytes are the ones recorded.
bool recordMatches(const std::string& picture, const std::string& render);

}  // namespace prime::cli
