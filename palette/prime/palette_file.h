// A user's own 256-entry palette, as a small text file (docs/prime/palette.md):
//
//   # anything after '#' is a comment; blank lines are ignored
//   prime-palette 1            first line: the format and its version
//   name sunset                optional: shown in the window title
//   values setrgbpalette       how to read the numbers: 0..255 as passed to
//                              setrgbpalette (the DAC keeps the top 6 bits), or
//                              `values dac` for 0..63 DAC values as they are
//   base listing               optional: a built-in palette for the entries
//                              the file does not list
//   0 0 0 0                    INDEX RED GREEN BLUE, one entry a line, any
//   1 80 178 60                order; each index 0..255 at most once, and all
//   ...                        256 of them unless there is a `base`
//
// Every mistake is an io::InputError naming the file, the line, the field,
// what was expected and what was found; nothing in a file can crash the parser.
#pragma once
#include <string>
#include <string_view>

#include "palette/prime/palettes.h"

namespace prime {

// `fileName` is used in messages and as the default name.
Palette parsePaletteText(std::string_view text, const std::string& fileName);
// Reads and parses a file (at most 1 MiB).
Palette readPaletteFile(const std::string& path);
// The palette in the file format (`values dac`), each entry followed by a
// comment with the colour it shows as (`how`); parsePaletteText reads it back.
std::string formatPaletteText(const Palette& palette, DacTo8 how = kDefaultDacTo8);

}  // namespace prime
