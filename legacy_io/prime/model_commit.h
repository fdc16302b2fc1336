// The databases of one `prime model` run switch together (M19), and two runs
// on one scene never write at once (M20).
//
// PRIME's databases must stay at their documented paths (prim/PrimFile,
// obj/O<n>, obj/List, map/Map<n>_?.map), beside the text inputs they are
// built from, so the switch cannot be one rename of a fresh directory.
// Instead, a redo journal:
//   1. every database is written to a temporary beside its target;
//   2. DIR/prime-model.journal is written (itself a temporary renamed into
//      place: it exists whole or not at all): one line per database, with
//      its SHA-256, size, path and temporary; this is the commit point;
//   3. each temporary is renamed over its target;
//   4. the journal is renamed to DIR/prime-model.stamp.
// A run killed before 2 leaves the old databases and temporaries whose
// process is gone (removed by the next run); killed after 2, the next run, or
// the next trace/probe/export-pov, finishes the renames from the journal
// (settleModel): the scene then holds exactly the new databases. Before
// using the databases, trace, probe and export-pov check every one against
// the stamp (verifyModel), so a scene changed behind prime's back, or a
// mixture made by older versions or by hand, is refused, not rendered.
// A scene without a stamp (built by the original or an older prime) is
// read as before.
#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "legacy_io/prime/dir_lock.h"
#include "legacy_io/prime/scene_dir.h"

namespace prime::io {

inline constexpr const char* kModelStamp = "prime-model.stamp";
inline constexpr const char* kModelJournal = "prime-model.journal";
inline constexpr const char* kModelLock = "prime-model.lock";

struct DatabaseFile {
  std::string path;  // relative to the scene: "prim/PrimFile", "obj/O1", "map/Map1_R.map"
  std::vector<std::uint8_t> bytes;
};

// Takes the scene's lock exclusively for `prime model` (M20): without
// `wait`, throws "busy: another prime model (pid N) is writing DIR" if
// another run holds it.
std::unique_ptr<DirLock> lockForModel(const SceneDir& scene, bool wait);
// Whether `scene` holds anything of a PRIME scene: Model.txt, a 1991
// Model.c, prim/, obj/, or prime model's stamp, journal or lock (any case,
// M40). Another system's scene or an empty directory holds none of them.
bool holdsPrimeScene(const SceneDir& scene);
// Takes the lock shared for a reader (waiting for a `prime model` run to
// finish), finishes an interrupted run's journal, and checks the databases
// against the stamp; throws InputError. Returns the held lock (release it
// when the databases are read), or null if the scene directory is not
// writable or holds nothing of a PRIME scene (no Model.txt, prim/, obj/,
// stamp, journal or lock: then nothing is created in it and the databases
// are only checked).
std::unique_ptr<DirLock> openModelForReading(const SceneDir& scene);

// Writes `files` as one switch (steps 1-4 above). The caller holds the
// exclusive lock. Finishes or discards an interrupted earlier run first.
void commitDatabases(const SceneDir& scene, const std::vector<DatabaseFile>& files);
// Finishes an interrupted run's journal and removes dead runs' temporaries
// (the caller holds the exclusive lock). Returns true if a journal was
// finished. A journal that cannot be finished throws, unless `discard`
// (`prime model` itself, which is about to write every database again).
bool settleModel(const SceneDir& scene, bool discard = false);
// Throws InputError unless every database the stamp names has the stamp's
// size and SHA-256, and no journal is pending.
void verifyModel(const SceneDir& scene);

// Test hook (never set by users): PRIME_TEST_MODEL_FAULT="kill:N" makes the
// process kill itself with SIGKILL at the N-th step of a model switch (1 =
// the first temporary written; every temporary, the journal, each rename and
// the stamp are steps), "fail:N" makes step N fail as a failed rename would.
// Documented in docs/prime/deviations.md (M19).
inline constexpr const char* kModelFaultVariable = "PRIME_TEST_MODEL_FAULT";

}  // namespace prime::io
