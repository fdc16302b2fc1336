#include "palette/prime/dac.h"

namespace prime {

DacTable loadDac(const PaletteTable& calls) {
  DacTable dac{};
  for (std::size_t i = 0; i < dac.size(); ++i)
    dac[i] = {setrgbToDac6(calls[i].r), setrgbToDac6(calls[i].g), setrgbToDac6(calls[i].b)};
  return dac;
}

std::string_view dacTo8Name(DacTo8 how) {
  switch (how) {
    case DacTo8::Replicate:
      return "replicate";
    case DacTo8::Truncate:
      return "truncate";
    case DacTo8::Round:
      break;
  }
  return "round";
}

std::string_view dacTo8Rule(DacTo8 how) {
  switch (how) {
    case DacTo8::Replicate:
      return "replicate: v8 = v6 * 4 + v6 / 16 (bit replication); v6 = v8 / 4";
    case DacTo8::Truncate:
      return "truncate: v8 = v6 * 255 / 63; v6 = (v8 * 63 + 254) / 255";
    case DacTo8::Round:
      break;
  }
  return "round: v8 = (v6 * 255 + 31) / 63, the nearest 8-bit level to v6 / 63; "
         "v6 = (v8 * 63 + 127) / 255";
}

std::optional<DacTo8> dacTo8FromName(std::string_view name) {
  for (DacTo8 how : {DacTo8::Round, DacTo8::Replicate, DacTo8::Truncate})
    if (name == dacTo8Name(how)) return how;
  return std::nullopt;
}

Rgb8Table present(const DacTable& dac, DacTo8 how) {
  Rgb8Table out{};
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = {dacTo8(dac[i].r, how), dacTo8(dac[i].g, how), dacTo8(dac[i].b, how)};
  return out;
}

}  // namespace prime
