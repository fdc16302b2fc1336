// A 1991 scene disk's Model.c, read as `prime model` reads Model.txt: the
// listing's Model.c (O'Reilly 1991, appendix: module Model) makes the scene
// in its main(), one call per object, list entry, copy and map:
//
//   void main(void)
//   {
//     Message("Initialising Files");
//     InitFiles();
//     OpenFiles();
//     AddObj("d1.txt");
//     AddToObjList(1);
//     CopyObj("d1.txt", "d2.txt", "c1.txt");
//     AddMap("Map1.txt");
//     CloseFiles();
//     if (!MemoryEmpty())
//     {
//       FreeAll();
//       Error("main(): Number of Mallocs != Number of Frees");
//     }
//   }
//
// Those four calls, with string and integer literals, are the scene, in
// order (M42). main()'s own housekeeping (Message, InitFiles, OpenFiles,
// CloseFiles, and the MemoryEmpty/FreeAll/Error check) is read and passed
// over; anything else in main() (a variable, a loop, another call, a call
// with something other than a literal) is refused with the file, the line
// and what was found. Comments (/* */ and //), preprocessor lines and
// everything outside main() are skipped. When a scene has both Model.txt and
// Model.c, Model.txt is read (it is what `prime new` writes and the port's
// own format); `prime model` says Model.c was left alone.
#pragma once
#include <string>
#include <vector>

#include "legacy_io/prime/text_inputs.h"

namespace prime::io {

std::vector<ModelCall> parseModelC(const std::string& text, const std::string& display);

}  // namespace prime::io
