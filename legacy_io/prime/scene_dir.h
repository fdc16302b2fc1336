// A scene directory: the port's stand-in for the listing's d:\c\thesis\ tree
// (errata E07): prim/, bound/, obj/, obj/Copy/, map/, light/, graph_scr.
// Every file name that comes from scene data goes through here, and here only
// plain names are accepted: no "..", no absolute paths, no separators, no
// symbolic links, so no scene file can make prime read or write elsewhere.
//
// Reading finds each name without regard to case (decision M40): a scene copied
// from a DOS disk has PRIM/PRIMFILE, OBJ/LIST, MAP/MAP1_R.MAP, LIGHT/LIGHT.TXT,
// and a case-sensitive file system must still find them. Two entries of one
// directory that differ only by case are refused, naming both. Writing keeps
// the canonical names (prim/PrimFile, ...).
#pragma once
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace prime::io {

class SceneDir {
 public:
  explicit SceneDir(std::filesystem::path root);

  // Path of `name` inside subdirectory `sub` ("prim", "obj/Copy", ...).
  // `origin` names where the name came from, for the error message
  // (e.g. "scene/Model.txt:3"). Throws InputError for an unsafe name.
  std::filesystem::path file(const std::string& sub, const std::string& name,
                             const std::string& origin) const;
  // The same, additionally refusing a path that exists as a symbolic link,
  // found without regard to case (M40): the path as it is on disk.
  std::filesystem::path existingInput(const std::string& sub, const std::string& name,
                                      const std::string& origin) const;
  // The path of sub/name as it is on disk, each part matched without regard
  // to case (M40); the canonical path when a part does not exist. Throws
  // InputError when two entries of a directory differ only by case.
  std::filesystem::path find(const std::string& sub, const std::string& name) const;
  // How a path inside the scene is shown in messages: "<scene>/prim/S1.txt".
  std::string display(const std::filesystem::path& p) const;
  const std::filesystem::path& root() const { return root_; }
  // Every regular file a scene is made of: Model.txt, Model.c and the files of prim/,
  // bound/, obj/, obj/Copy/, map/ and light/ (text inputs and databases), the
  // files no output of a run may replace (run_inputs.h). Not graph_scr.
  std::vector<std::filesystem::path> inputFiles() const;

 private:
  // A directory's entries by lower-case name, read once (and again on a miss).
  struct Listing {
    std::mutex mutex;
    std::map<std::string, std::map<std::string, std::vector<std::string>>> byDir;
  };
  std::filesystem::path resolve(const std::filesystem::path& dir, const std::string& part) const;
  std::filesystem::path root_;
  std::shared_ptr<Listing> listing_ = std::make_shared<Listing>();
};

// A path a user typed, as it is on disk (M40): each part that does not exist
// as written is matched in its directory without regard to case
// (`prime dump D/PRIM/PRIMFILE` finds D/PRIM/PrimFile and a DOS disk's
// D/PRIM/PRIMFILE alike); the path as written when nothing matches.
std::filesystem::path findIgnoringCase(const std::filesystem::path& typed);

// Longest file name SceneDir::file accepts (NAME_MAX on Linux).
inline constexpr std::size_t kMaxFileName = 255;

// True for a plain file name: non-empty, no '/', '\\', ':' or NUL, not "." or "..".
bool isPlainFileName(const std::string& name);

}  // namespace prime::io
