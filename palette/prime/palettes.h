// The named palettes: each a 256-entry DAC table (6 bits per channel) with a
// name and a one-line description. docs/prime/palette.md lists them in full.
//
//   listing  InitPalette (lines 3894-3929, K17) through setrgbpalette: what the
//            8514/A showed for graphType 1, the only mode RayTrace.c uses
//   plate3   the Colour Plate 3 table of section 5.10 (X1): 16 red x 16 green
//            shades, no blue; goes with colorNumPlate3
//   vga      graphType 0 (InitGraph's DETECT branch, no InitPalette): the BGI's
//            default EGA/VGA colours; a 16-colour VGA keeps index & 15
//
// A user's own table is loaded from a text file (palette/prime/palette_file.h).
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "palette/prime/dac.h"

namespace prime {

struct Palette {
  std::string name;         // a built-in name, or the file the table came from
  std::string description;  // one line, for titles and listings
  DacTable dac;
};

// The 16 default colours of the EGA/VGA as the VGA BIOS loads them into the
// DAC (0..63): black, blue, green, cyan, red, magenta, brown, light grey, dark
// grey, light blue, light green, light cyan, light red, light magenta, yellow,
// white. Borland: "the BGI driver defines the first 16 palette entries of the
// IBM 8514 to the default colors of the EGA/VGA".
const std::array<Dac6, 16>& egaVgaDefaultColours();

DacTable listingDac();  // loadDac(initPalette())
DacTable plate3Dac();   // loadDac(plate3Palette())
DacTable vgaDac();      // entry i = egaVgaDefaultColours()[i & 15]

// "listing", "plate3", "vga", in that order.
const std::vector<std::string>& builtinPaletteNames();
// The built-in palette of that name ("8514" is another name for "listing");
// nullopt if there is none.
std::optional<Palette> findBuiltinPalette(std::string_view name);

// The display the 8514/A drove (--monitor; docs/prime/palette.md, "The
// monitor"). The adapter's DAC sends red, green and blue whatever is
// attached; a monochrome display (the IBM 8503) shows the green signal as
// its grey. The 8514/A and its Adapter Interface do no grey-scale summing
// (that is the VGA BIOS's, INT 10h AX=101Bh: 30 % red, 59 % green, 11 %
// blue), which Mono8503Summed shows for comparison.
enum class Monitor { Colour8514, Mono8503, Mono8503Summed };
std::string_view monitorName(Monitor m);  // "8514", "8503", "8503-summed"
std::optional<Monitor> monitorFromName(std::string_view name);
// The palette as the monitor shows it: unchanged on the 8514 colour
// display; on a monochrome one every entry grey (its green level, or the
// VGA BIOS's sum (77 R + 151 G + 28 B + 128) / 256 of the 6-bit values),
// named for the monitor.
Palette onMonitor(Palette palette, Monitor m);
// The palette a graph file's graphType implies: 0 -> "vga", anything else ->
// "listing" (RayTrace.c: 0 = DETECT, 1 = IBM8514HI). A Colour Plate 3 render
// also writes graphType 1: view it with --palette plate3.
std::string paletteNameForGraphType(int graphType);
// A built-in name, or else the path of a palette file (palette_file.h). An
// unknown name that is not an existing file is an io::InputError listing the
// built-in names.
Palette resolvePalette(const std::string& nameOrFile);

}  // namespace prime
