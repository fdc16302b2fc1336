#include "legacy_io/prime/model_builder.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "legacy_io/common/input_file.h"
#include "legacy_io/common/output_file.h"
#include "legacy_io/prime/model_c.h"
#include "legacy_io/prime/model_commit.h"
#include "legacy_io/prime/turbo_c.h"
#include "src/prime/math/listing_matrix.h"

namespace prime::io {

namespace fs = std::filesystem;

namespace {

// One modelling run: the in-memory databases and the state the listing kept
// in its open files and heap.
class Modeller {
 public:
  Modeller(const SceneDir& scene, const ModelOptions& options) : scene_(scene), options_(options) {}

  void run(const std::vector<ModelCall>& calls, const std::string& origin) {
    for (const auto& call : calls) {
      const std::string where = origin + ":" + std::to_string(call.line);
      if (call.name == "AddObj")
        addObj(call.args[0], where);
      else if (call.name == "AddToObjList")
        addToObjList(call.args[0], where);
      else if (call.name == "CopyObj")
        copyObj(call.args[0], call.args[1], call.args[2], where);
      else if (call.name == "AddMap")
        addMap(call.args[0], where);
    }
    warnAboutTheList(origin);
  }

  Model take() { return std::move(model_); }

 private:
  TextReader openText(const std::string& sub, const std::string& name, const std::string& origin) {
    const fs::path p = scene_.existingInput(sub, name, origin);
    return TextReader::open(p.string(), scene_.display(p));
  }

  // NewPrimNum: the next record number of PrimFile.
  std::int16_t newPrimNum(const std::string& origin) {
    const std::size_t n = model_.prims.prims.size();
    const std::size_t fileSize = n * kPrimSizePacked;
    if (options_.limitPrimFileTo16Bits && fileSize > 32767)
      throw InputError(
          {origin, std::nullopt, std::nullopt}, "primitive count",
          "at most 113 primitives and bounding volumes (numbers 0..112: NewPrimNum keeps "
          "ftell() in a 16-bit int, which wraps once PrimFile passes 32767 bytes, errata "
          "E40/K37; --no-16bit-limit numbers on)",
          "primitive number " + std::to_string(n));
    if (n > 32767)
      throw InputError({origin, std::nullopt, std::nullopt}, "primitive count",
                       "at most 32768 primitives (16-bit primitive numbers)",
                       std::to_string(n + 1));
    return static_cast<std::int16_t>(n);
  }

  std::int16_t writePrim(PrimRecord p, const std::string& origin) {
    const std::int16_t num = newPrimNum(origin);
    lastPrimType_ = p.type;
    model_.prims.prims.push_back(std::move(p));
    return num;
  }

  void invert(PrimRecord& p, const std::string& file) {
    // M12: say why. A matrix whose entries overflowed (scales or a
    // translation too large for a double) is not blamed on a zero scale.
    for (const auto& row : p.transform)
      for (const double v : row)
        if (!std::isfinite(v))
          throw InputError(
              {file, std::nullopt, std::nullopt}, "transformation", "a matrix of finite numbers",
              "an entry that overflowed to " + std::string(std::isnan(v) ? "NaN" : "infinity") +
                  " (a scale factor or a translation too large, or their product)");
    if (!inverse(p.transform, p.inverse))
      throw InputError({file, std::nullopt, std::nullopt}, "transformation", "an invertible matrix",
                       "a singular matrix (a zero scale factor, or scale factors so small that "
                       "their product underflows to zero)");
  }

  // AddPrim: prim/<opcode><n>.txt -> a new PrimFile record.
  std::int16_t addPrim(char opcode, std::int16_t n, const std::string& origin) {
    TextReader in = openText("prim", std::string(1, opcode) + std::to_string(n) + ".txt", origin);
    const PrimText text = parsePrimText(in);
    PrimRecord p;
    p.type = text.type;
    p.transform = identity4();
    transform(p.transform, text.place.s, text.place.t, text.place.pivot, text.place.r);
    invert(p, in.name());
    p.map = text.map;  // slots beyond the surface count: 0 (K34)
    p.priority = text.priority;
    return writePrim(std::move(p), in.name());
  }

  // AddBound: bound/<letter><n>.txt; maps and priority never set (zeros).
  std::int16_t addBound(char letter, std::int16_t n, const std::string& origin) {
    TextReader in = openText("bound", std::string(1, letter) + std::to_string(n) + ".txt", origin);
    const BoundText text = parseBoundText(in);
    PrimRecord p;
    p.type = text.type;
    p.transform = identity4();
    transform(p.transform, text.place.s, text.place.t, text.place.pivot, text.place.r);
    invert(p, in.name());
    return writePrim(std::move(p), in.name());
  }

  // CopyPrim: inverse * S * R * T * transform of the source, from prim/A<n>.txt.
  std::int16_t copyPrim(const PrimRecord& src, std::int16_t copyFile, const std::string& origin) {
    TextReader in = openText("prim", "A" + std::to_string(copyFile) + ".txt", origin);
    const Placement place = parsePlacement(in);
    PrimRecord p;
    p.type = options_.copyTypeFromSource ? src.type : lastPrimType_;  // K33
    p.transform = src.inverse;
    scale(p.transform, place.s);
    rotate(p.transform, place.r[X], place.r[Y], place.r[Z]);
    translate(p.transform, place.t);
    matrixMul(p.transform, src.transform);
    invert(p, in.name());
    p.map = src.map;
    p.priority = src.priority;
    return writePrim(std::move(p), in.name());
  }

  const PrimRecord& prim(int num, const std::string& origin) {
    if (num < 0 || num >= static_cast<int>(model_.prims.prims.size()))
      throw InputError({origin, std::nullopt, std::nullopt}, "primitive number",
                       "0.." + std::to_string(model_.prims.prims.size()) + " (exclusive)",
                       std::to_string(num));
    return model_.prims.prims[num];
  }

  static ObjRecord record(char op, std::int16_t l, std::int16_t r) {
    ObjRecord o;
    o.opCode = {op, 0, 0, 0};  // bytes after the NUL: never written by the listing; zeros
    o.l = l;
    o.r = r;
    return o;
  }

  // "d1.txt" -> "1": AddObj patches the first character of the name (to H, D
  // and O) and takes the object number from the characters up to the '.'.
  static std::string objectStem(const std::string& name, const std::string& origin) {
    const auto dot = name.find('.');
    bool ok = dot != std::string::npos && dot >= 2;
    for (std::size_t i = 1; ok && i < dot; ++i)
      ok = std::isdigit(static_cast<unsigned char>(name[i]));
    if (!ok)
      throw InputError({origin, std::nullopt, std::nullopt}, "AddObj file name",
                       "a letter, the object number and an extension, like \"d1.txt\"",
                       "\"" + name + "\"");
    return name.substr(1, dot - 1);
  }

  void addObj(const std::string& name, const std::string& origin) {
    if (!isPlainFileName(name)) scene_.file("obj", name, origin);  // throws the path error
    const std::string stem = objectStem(name, origin);
    const std::string rest = name.substr(1);

    ObjFile obj;
    {
      TextReader in = openText("obj", "H" + rest, origin);
      obj.header.hue = parseHueText(in);
    }
    TextReader in = openText("obj", "D" + rest, origin);
    const ObjText text = parseObjText(in);

    for (const auto& e : text.entries) {
      const std::string where = in.name() + ":" + std::to_string(e.line);
      if (isLeafOpcode(e.op))
        obj.entries.push_back(record('P', addPrim(e.op, e.l, where), 0));
      else
        obj.entries.push_back(record(e.op, e.l, e.r));
    }

    // Replace each 'O' entry by the root of the named object and append the
    // rest of it, re-numbered; its primitives are copied through CopyPrim.
    for (std::size_t i = 0; i < obj.entries.size(); ++i) {
      if (obj.entries[i].op() != 'O') continue;
      const int line = text.entries[i].line;
      const std::string where = in.name() + ":" + std::to_string(line);
      const std::string srcName = "O" + std::to_string(obj.entries[i].l);
      auto found = model_.objects.find(srcName);
      if (found == model_.objects.end())
        throw InputError({in.name(), line, std::nullopt}, "O entry source object",
                         "an object built earlier in Model.txt (obj/" + srcName + ")",
                         "object " + std::to_string(obj.entries[i].l) + ", which does not exist");
      const ObjFile src = found->second;
      // Checked before copying: each O entry can append up to 32766 entries,
      // and 32767 O entries would otherwise build gigabytes before the check
      // at the end.
      if (obj.entries.size() + src.entries.size() - 1 > 32767)
        throw InputError({in.name(), line, std::nullopt}, "numEntries",
                         "at most 32767 entries after copying objects",
                         std::to_string(obj.entries.size() + src.entries.size() - 1) +
                             " once this O entry copies the " + std::to_string(src.entries.size()) +
                             " entries of object " + srcName.substr(1));
      const std::int16_t copyFile = obj.entries[i].r;
      const auto offset = static_cast<std::int16_t>(obj.entries.size() - 1);
      ObjRecord root = src.entries.at(0);
      if (root.op() == 'P')
        model_.warnings.push_back(where + ": O entry copies object " + srcName.substr(1) +
                                  ", whose root is a primitive; as in the listing its primitive "
                                  "number is offset like a child index (K33) and the copy is "
                                  "broken");
      root.l = static_cast<std::int16_t>(root.l + offset);
      root.r = static_cast<std::int16_t>(root.r + offset);
      obj.entries[i] = root;
      for (std::size_t j = 1; j < src.entries.size(); ++j) {
        ObjRecord e = src.entries[j];
        switch (e.op()) {
          case '+':
          case '-':
          case '&':
            e.l = static_cast<std::int16_t>(e.l + offset);
            e.r = static_cast<std::int16_t>(e.r + offset);
            break;
          case 'P':
            e.l = copyPrim(prim(e.l, where), copyFile, where);
            break;
          default:
            throw InputError({where, std::nullopt, std::nullopt}, "entry of object " + srcName,
                             "an operator or primitive", std::string("opcode '") + e.op() + "'");
        }
        obj.entries.push_back(e);
      }
    }
    if (obj.entries.size() > 32767)
      throw InputError({in.name(), std::nullopt, std::nullopt}, "numEntries",
                       "at most 32767 entries after copying objects",
                       std::to_string(obj.entries.size()));
    obj.header.numEntries = static_cast<std::int16_t>(obj.entries.size());
    obj.header.boundVol = -1;
    if (text.bound)
      obj.header.boundVol = addBound(text.bound->first, text.bound->second,
                                     in.name() + ":" + std::to_string(text.boundLine));
    model_.objects["O" + stem] = std::move(obj);
  }

  void addToObjList(const std::string& arg, const std::string& origin) {
    TextReader in(arg, origin);
    const std::int16_t n = in.int16("AddToObjList object number");
    if (!in.atEnd()) in.fail("AddToObjList object number", "an integer", "\"" + arg + "\"");
    if (!model_.objects.count("O" + std::to_string(n)))
      throw InputError({origin, std::nullopt, std::nullopt}, "AddToObjList object number",
                       "an object built earlier in Model.txt",
                       std::to_string(n) + " (no obj/O" + std::to_string(n) + ")");
    model_.list.objects.push_back(n);
  }

  // Every ray tests every entry of the object list (the listing's Trace has
  // no other structure): an object listed twice costs twice and changes no
  // pixel, and a list of thousands (30,000 entries from a short Model.txt)
  // makes every ray that many tests. Said, not refused: the listing allows it.
  void warnAboutTheList(const std::string& origin) {
    const auto& list = model_.list.objects;
    std::map<std::int16_t, int> times;
    for (const std::int16_t n : list) ++times[n];
    std::size_t repeats = 0;
    std::int16_t most = 0;
    for (const auto& [n, k] : times) {
      repeats += static_cast<std::size_t>(k - 1);
      if (k > times[most]) most = n;
    }
    if (repeats > 0)
      model_.warnings.push_back(
          origin + ": the object list holds " + std::to_string(list.size()) + " entries, " +
          std::to_string(repeats) + " of them objects already in it (object " +
          std::to_string(most) + " " + std::to_string(times[most]) +
          " times): every ray tests each entry, so a repeat changes no pixel and adds its tests");
    else if (list.size() > kManyListEntries)
      model_.warnings.push_back(origin + ": the object list holds " + std::to_string(list.size()) +
                                " objects: every ray tests each of them (the listing has no "
                                "other structure); expect a slow render");
  }
  static constexpr std::size_t kManyListEntries = 1000;

  // CopyObj: copy obj/<src> byte for byte to obj/<dest>, then TransferObj:
  // every primitive (and the bound) gets Transform() applied to its own matrix
  // and is written as a new PrimFile record.
  void copyObj(const std::string& srcName, const std::string& destName, const std::string& copyTxt,
               const std::string& origin) {
    scene_.file("obj", srcName, origin);
    scene_.file("obj", destName, origin);
    // The destination becomes the file obj/<destName>: it must not be one of
    // the other files of obj/, which writing it would replace (List, a text
    // input) or cannot replace (the Copy/ folder).
    const bool textInput = destName.ends_with(".txt") || destName.ends_with(".TXT");
    if (destName == "List" || destName == "Copy" || textInput)
      throw InputError(
          {origin, std::nullopt, std::nullopt}, "CopyObj destination object",
          "a name for a new object file in obj/ like O4 (not List, Copy or a .txt input)",
          "\"" + destName + "\"");
    auto found = model_.objects.find(srcName);
    if (found == model_.objects.end())
      throw InputError({origin, std::nullopt, std::nullopt}, "CopyObj source object",
                       "an object built earlier in Model.txt", "\"" + srcName + "\"");
    ObjFile dest = found->second;
    TextReader in = openText("obj/Copy", copyTxt, origin);
    const Placement place = parsePlacement(in);
    auto transfer = [&](int num) {
      PrimRecord p = prim(num, origin);
      transform(p.transform, place.s, place.t, place.pivot, place.r);
      invert(p, in.name());
      return writePrim(std::move(p), in.name());
    };
    for (auto& e : dest.entries)
      if (e.op() == 'P') e.l = transfer(e.l);
    if (dest.header.boundVol != -1) dest.header.boundVol = transfer(dest.header.boundVol);
    if (destName.size() < 2 || destName[0] != 'O' ||
        destName.find_first_not_of("0123456789", 1) != std::string::npos)
      model_.warnings.push_back(origin + ": CopyObj destination \"" + destName +
                                "\" is not of the form O<number>; RayTrace can only open objects "
                                "named that way");
    model_.objects[destName] = std::move(dest);
  }

  void addMap(const std::string& name, const std::string& origin) {
    TextReader in = openText("map", name, origin);
    const MapText text = parseMapText(in);
    for (int c = 0; c < 3; ++c) {
      MapFile f;
      f.header = text.header;
      f.texels = text.planes[c];
      model_.maps[mapFileName(text.mapNum, c)] = std::move(f);
    }
  }

  const SceneDir& scene_;
  ModelOptions options_;
  Model model_;
  char lastPrimType_ = 0;
};

}  // namespace

Model buildModel(const SceneDir& scene, const std::vector<ModelCall>& calls,
                 const ModelOptions& options, const std::string& from) {
  Modeller m(scene, options);
  const std::string origin = from.empty() ? scene.display(scene.root() / "Model.txt") : from;
  m.run(calls, origin);
  Model model = m.take();
  if (model.objects.empty() && !options.allowEmpty)  // M22
    throw InputError({origin, std::nullopt, std::nullopt}, "objects",
                     "at least one AddObj or CopyObj (a Model.txt with no objects would replace "
                     "the databases with an empty scene; prime model --allow-empty builds one "
                     "anyway)",
                     calls.empty()
                         ? "no calls at all (an empty file, or only comments)"
                         : std::to_string(calls.size()) + " call(s), none making an object");
  return model;
}

fs::path modelSource(const SceneDir& scene) {
  std::error_code ec;
  const fs::path text = scene.find(".", "Model.txt");
  if (fs::exists(fs::symlink_status(text, ec)))
    return scene.existingInput(".", "Model.txt", "prime model");
  const fs::path c = scene.find(".", "Model.c");
  if (fs::exists(fs::symlink_status(c, ec)))
    return scene.existingInput(".", "Model.c", "prime model");
  throw InputError({scene.display(text), std::nullopt, std::nullopt},
                   "file does not exist, nor does a 1991 disk's Model.c (" +
                       scene.display(scene.root() / "Model.c") +
                       "): one of them names the scene's objects and maps");
}

Model buildModel(const SceneDir& scene, const ModelOptions& options) {
  const fs::path p = modelSource(scene);
  std::string name = p.filename().string();
  for (char& ch : name) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  const bool c = name == "model.c";  // however the scene spells it
  io::InputFileOptions input;
  input.what = c ? "a Model.c" : "a Model.txt";
  input.display = scene.display(p);
  const std::string text = io::readInputText(p.string(), input);
  return buildModel(
      scene, c ? parseModelC(text, scene.display(p)) : parseModelText(text, scene.display(p)),
      options, scene.display(p));
}

void writeModel(const SceneDir& scene, const Model& model, const DirLock* held) {
  std::unique_ptr<DirLock> lock;
  if (held == nullptr) lock = lockForModel(scene, /*wait=*/false);
  // Encode everything first; then switch them all at once.
  std::vector<DatabaseFile> files;
  files.push_back({"prim/PrimFile", toBytes(model.prims)});
  files.push_back({"obj/List", toBytes(model.list)});
  for (const auto& [name, obj] : model.objects) files.push_back({"obj/" + name, toBytes(obj)});
  for (const auto& [name, map] : model.maps) files.push_back({"map/" + name, toBytes(map)});
  commitDatabases(scene, files);
}

}  // namespace prime::io
