#include "legacy_io/cgl/reflectance.h"

#include <sstream>

#include "legacy_io/common/input_file.h"
#include "legacy_io/common/text_reader.h"

namespace prime::cgl {

bool isReflectanceNumber(const std::string& word, double& value) {
  std::istringstream in(word);
  in >> value;
  return !in.fail() && in.eof();
}

Spectrum normalReflectance(const std::vector<ReflectanceNumber>& numbers,
                           const io::InputLocation& end) {
  const std::size_t want = static_cast<std::size_t>(kSpectrumSamples);
  if (numbers.size() != want)
    throw io::InputError(numbers.size() > want ? numbers[want].where : end, "normal reflectance",
                         "33 numbers (380 to 700 nm every 10 nm)",
                         std::to_string(numbers.size()) + " numbers");
  Spectrum r{};
  for (std::size_t k = 0; k < r.size(); ++k) {
    const double v = numbers[k].value;
    if (!(v >= 0.0 && v < 1.0))
      throw io::InputError(numbers[k].where,
                           "normal reflectance at " + std::to_string(380 + 10 * k) + " nm",
                           "0 <= R < 1", std::to_string(v));
    r[k] = v;
  }
  return r;
}

Spectrum readReflectance(const std::string& text, const std::string& display) {
  std::string all = io::normalizeLineBreaks(text);
  io::endAtDosEof(all);
  std::istringstream in(all);
  std::vector<ReflectanceNumber> numbers;
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '*') continue;
    std::istringstream words(line);
    std::string w;
    while (words >> w) {
      double v = 0;
      if (!isReflectanceNumber(w, v))
        throw io::InputError({display, lineNo}, "normal reflectance", "a real number",
                             io::quotedWord(w, 40));
      if (numbers.size() == static_cast<std::size_t>(kSpectrumSamples))
        throw io::InputError({display, lineNo}, "normal reflectance",
                             "33 numbers (380 to 700 nm every 10 nm)",
                             "a 34th, " + io::quotedWord(w, 40));
      numbers.push_back({v, {display, lineNo}});
    }
  }
  return normalReflectance(numbers, {display, lineNo < 1 ? 1 : lineNo});
}

}  // namespace prime::cgl
