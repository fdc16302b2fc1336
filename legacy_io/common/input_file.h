// Every input file of every system is read here, whole, in one way:
//   - a missing file, a directory, and anything that is not a regular file
//     (a FIFO would block the reader forever, a device such as /dev/zero
//     would never end, a socket cannot be read) are refused by type, with
//     the file named and what it is;
//   - a file larger than the largest its format can have is refused before
//     it is read (the caller passes its format's cap), so no input makes the
//     program run out of memory;
//   - the file is opened without blocking and its type checked on the open
//     descriptor, so a path swapped for a FIFO between a check and the open
//     cannot block either.
// Errors are InputError naming the file as the user gave it.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace prime::io {

class InputError;

// The cap of readFileBytes and TextReader::open when a reader names none.
inline constexpr std::uint64_t kDefaultInputCap = 256ull << 20;

struct InputFileOptions {
  std::uint64_t maxBytes = kDefaultInputCap;
  std::string what = "an input file";  // for messages: "a CGL scene file", "a PRIME graph file"
  std::string display;                 // the name in messages ("" = the path)
  // Whether the bytes are the scene's, for inputsDigest (run_inputs.h): false
  // for a program's own bookkeeping beside a scene (prime model's journal
  // and stamp, which name temporaries by process id), so that the digest of
  // a render is the same on every machine that built the same databases.
  bool sceneContent = true;
};

std::vector<std::uint8_t> readInputFile(const std::string& path,
                                        const InputFileOptions& options = {});
// A text input, by the rule every text input of every system is read by
// (M41): a ^Z (0x1A, the end of file DOS's COPY and the editors of the time
// wrote, which Turbo C's text mode stops at) ends the text; nothing after it
// is read. (A leading UTF-8 byte order mark stays, for the reader to skip
// with kUtf8Bom: byte offsets in messages count from the file's first byte.)
std::string readInputText(const std::string& path, const InputFileOptions& options = {});

// When `e` found the end of a text that a ^Z ended before bytes other than
// ^Z padding (a binary COPY A+B put one in the middle): a sentence that
// says so, for the message; else "".
std::string dosEofNote(const InputError& e);

// The same rule for text that did not come from a file (standard input, a
// fuzzer): `text` cut at its first ^Z.
void endAtDosEof(std::string& text);
inline constexpr char kDosEof = '\x1A';
inline constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
// The length of a leading byte order mark of `text` (3 or 0).
inline std::size_t bomLength(std::string_view text) {
  return text.substr(0, 3) == kUtf8Bom ? 3 : 0;
}

}  // namespace prime::io
