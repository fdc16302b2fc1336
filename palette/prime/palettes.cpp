#include "palette/prime/palettes.h"

#include <algorithm>
#include <filesystem>

#include "legacy_io/common/error.h"
#include "palette/prime/palette_file.h"

namespace prime {

const std::array<Dac6, 16>& egaVgaDefaultColours() {
  // 0x2A = 42 (2/3 intensity), 0x15 = 21 (1/3), 0x3F = 63; brown is red 42,
  // green 21 (the EGA's special case of colour 6).
  static const std::array<Dac6, 16> colours{{
      {0, 0, 0},     // 0 black
      {0, 0, 42},    // 1 blue
      {0, 42, 0},    // 2 green
      {0, 42, 42},   // 3 cyan
      {42, 0, 0},    // 4 red
      {42, 0, 42},   // 5 magenta
      {42, 21, 0},   // 6 brown
      {42, 42, 42},  // 7 light grey
      {21, 21, 21},  // 8 dark grey
      {21, 21, 63},  // 9 light blue
      {21, 63, 21},  // 10 light green
      {21, 63, 63},  // 11 light cyan
      {63, 21, 21},  // 12 light red
      {63, 21, 63},  // 13 light magenta
      {63, 63, 21},  // 14 yellow
      {63, 63, 63},  // 15 white
  }};
  return colours;
}

DacTable listingDac() {
  return loadDac(initPalette());
}

DacTable plate3Dac() {
  return loadDac(plate3Palette());
}

DacTable vgaDac() {
  DacTable dac{};
  for (std::size_t i = 0; i < dac.size(); ++i) dac[i] = egaVgaDefaultColours()[i & 15];
  return dac;
}

const std::vector<std::string>& builtinPaletteNames() {
  static const std::vector<std::string> names{"listing", "plate3", "vga"};
  return names;
}

std::optional<Palette> findBuiltinPalette(std::string_view name) {
  if (name == "listing" || name == "8514")
    return Palette{"listing",
                   "InitPalette's 3-3-2 table with its overrides (K17), as the 8514/A DAC holds it",
                   listingDac()};
  if (name == "plate3")
    return Palette{"plate3", "Colour Plate 3: 16 red x 16 green shades, no blue (X1)", plate3Dac()};
  if (name == "vga")
    return Palette{"vga", "graphType 0: the BGI's 16 default EGA/VGA colours, index & 15",
                   vgaDac()};
  return std::nullopt;
}

std::string paletteNameForGraphType(int graphType) {
  return graphType == 0 ? "vga" : "listing";
}

Palette resolvePalette(const std::string& nameOrFile) {
  if (auto builtin = findBuiltinPalette(nameOrFile)) return *builtin;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(nameOrFile, ec)) {
    std::string names;
    for (const auto& n : builtinPaletteNames()) names += (names.empty() ? "" : ", ") + n;
    throw io::InputError({nameOrFile, std::nullopt, std::nullopt}, "palette",
                         "a built-in palette (" + names + ") or a palette file",
                         "no such palette or file");
  }
  return readPaletteFile(nameOrFile);
}

std::string_view monitorName(Monitor m) {
  switch (m) {
    case Monitor::Mono8503:
      return "8503";
    case Monitor::Mono8503Summed:
      return "8503-summed";
    case Monitor::Colour8514:
      break;
  }
  return "8514";
}

std::optional<Monitor> monitorFromName(std::string_view name) {
  for (Monitor m : {Monitor::Colour8514, Monitor::Mono8503, Monitor::Mono8503Summed})
    if (name == monitorName(m)) return m;
  return std::nullopt;
}

Palette onMonitor(Palette palette, Monitor m) {
  if (m == Monitor::Colour8514) return palette;
  for (Dac6& e : palette.dac) {
    const int grey =
        m == Monitor::Mono8503 ? e.g : std::min(63, (77 * e.r + 151 * e.g + 28 * e.b + 0x80) >> 8);
    e = {static_cast<std::uint8_t>(grey), static_cast<std::uint8_t>(grey),
         static_cast<std::uint8_t>(grey)};
  }
  const std::string shown = m == Monitor::Mono8503
                                ? " on the IBM 8503 monochrome display"
                                : " on the IBM 8503, greys summed as the VGA BIOS";
  palette.name += " (" + std::string(monitorName(m)) + ")";
  palette.description = (palette.description.empty() ? palette.name : palette.description) + shown;
  return palette;
}

}  // namespace prime
