// `prime model`: what Model.c's main() and AddObj / AddPrim / CopyPrim /
// AddBound / CopyObj / TransferObj / AddToObjList / AddMap did, producing the
// same databases: same primitive numbering, same records, same matrices from
// the same sequence of floating-point operations.
//
// The listing hard-coded its calls in main(); a scene directory holds them in
// Model.txt, one per line, in the order main() made them (errata E32).
//
// The whole model is built in memory first; only when every input has been
// read and checked are the databases written, all of them as one switch
// (model_commit.h, M19) under the scene's lock (M20), so a failed or killed
// run leaves the previous databases intact, or the new ones complete.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "legacy_io/prime/dir_lock.h"
#include "legacy_io/prime/map_file.h"
#include "legacy_io/prime/obj_file.h"
#include "legacy_io/prime/obj_list.h"
#include "legacy_io/prime/prim_file.h"
#include "legacy_io/prime/scene_dir.h"
#include "legacy_io/prime/text_inputs.h"

namespace prime::io {

struct ModelOptions {
  // CopyPrim never sets the copy's type (K33): the copy keeps whatever the
  // recycled heap block held, which we model as the type of the Prim record
  // built last (AddPrim, AddBound, CopyPrim or CopyObj's TransferObj: each
  // Mallocs and Frees one Prim-sized block). true: take the source's type.
  bool copyTypeFromSource = false;
  // NewPrimNum keeps ftell() in a 16-bit int (E40, K37): past 32767 bytes the
  // original failed. false lifts that limit (not the 1991 behaviour).
  bool limitPrimFileTo16Bits = true;
  // A Model.txt that builds no object (empty, all comments) is refused (M22): it would replace the
  // databases with an empty scene.
  bool allowEmpty = false;
};

struct Model {
  PrimFile prims;
  std::map<std::string, ObjFile> objects;  // by file name in obj/: "O1", ...
  ObjList list;
  std::map<std::string, MapFile> maps;  // by file name in map/: "Map1_R.map", ...
  std::vector<std::string> warnings;    // listing quirks the scene runs into
};

// Runs the calls of `calls` against the text inputs of `scene`; `origin`
// names the file the calls came from in messages ("" : the scene's
// Model.txt).
Model buildModel(const SceneDir& scene, const std::vector<ModelCall>& calls,
                 const ModelOptions& options = {}, const std::string& origin = "");
// The file the scene's calls are read from (M42): Model.txt (as the scene
// spells it, M40), else a 1991 disk's Model.c (model_c.h); Model.txt when
// both exist. Throws InputError naming both when neither does.
std::filesystem::path modelSource(const SceneDir& scene);
// Reads the scene's calls (modelSource) and builds from them.
Model buildModel(const SceneDir& scene, const ModelOptions& options = {});
// Writes every database of `model` into `scene` as one switch (M19). `held`:
// the scene's lock, taken by the caller with lockForModel; null: taken here
// (and "busy" if another run holds it).
void writeModel(const SceneDir& scene, const Model& model, const DirLock* held = nullptr);

}  // namespace prime::io
