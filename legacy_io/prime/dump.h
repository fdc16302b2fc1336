// `prime dump`: a readable listing of any PRIME database or graph file, record
// by record, for people inspecting old files.
#pragma once
#include <optional>
#include <string>

namespace prime::io {

enum class DatabaseKind { PrimFile, ObjFile, ObjList, MapFile, GraphFile };

// From the file name as the listing names them: PrimFile, List, O<n>,
// Map<n>_R.map (or _G, _B), graph_scr. Empty when the name says nothing.
std::optional<DatabaseKind> kindFromFileName(const std::string& path);
std::optional<DatabaseKind> kindFromName(const std::string& word);  // prim|obj|list|map|graph

// Reads `path` as `kind` and returns the listing. `maxPixels` limits how many
// graph-file rows are printed in full (a summary and histogram always are).
std::string dumpDatabase(const std::string& path, DatabaseKind kind, int maxRows = 8);

}  // namespace prime::io
