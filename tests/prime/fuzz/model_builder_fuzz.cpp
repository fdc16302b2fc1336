// `prime model` on a whole scene directory: buildModel(SceneDir) reads
// Model.txt and every text input it names (fuzz_support.h: the input is split
// into the scene's files at "%%prime:<path>" lines). What it builds is then
// written with writeModel and read back with loadScene, so the databases the
// modeller writes are fuzzed through the loader as well. Bytes before the
// first marker choose the options: 'T' --copy-type-from-source,
// 'L' --no-16bit-limit.
#include <string_view>

#include "legacy_io/prime/model_builder.h"
#include "src/prime/scene/scene_loader.h"
#include "tests/prime/fuzz/fuzz_support.h"

using namespace prime;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static fuzz::ScratchScene scratch;
  const std::string_view in(reinterpret_cast<const char*>(data), size);
  const std::string_view prefix = in.substr(0, in.find(fuzz::kFileMarker));
  io::ModelOptions options;
  options.copyTypeFromSource = prefix.find('T') != std::string_view::npos;
  options.limitPrimFileTo16Bits = prefix.find('L') == std::string_view::npos;

  scratch.fill(fuzz::splitScene(data, size));
  const io::SceneDir dir(scratch.root());
  try {
    const io::Model model = io::buildModel(dir, options);
    fuzz::check(model.prims.prims.size() <= (options.limitPrimFileTo16Bits ? 113u : 32768u),
                "primitive limit not kept");
    for (const auto& [name, obj] : model.objects)
      fuzz::check(!obj.entries.empty() && obj.entries.size() <= 32767 &&
                      static_cast<std::size_t>(obj.header.numEntries) == obj.entries.size(),
                  "object " + name + " has a bad entry count");
    io::writeModel(dir, model);
    (void)loadScene(dir);
  } catch (const io::InputError& e) {
    fuzz::check(std::string(e.what()).find(": ") != std::string::npos, "message without a place");
  }
  return 0;
}
