#include "legacy_io/prime/scene_dir.h"

#include <algorithm>
#include <cctype>
#include <vector>

#include "legacy_io/common/error.h"

namespace prime::io {

namespace fs = std::filesystem;

SceneDir::SceneDir(fs::path root) : root_(std::move(root)) {}

bool isPlainFileName(const std::string& name) {
  if (name.empty() || name == "." || name == "..") return false;
  for (char c : name)
    if (c == '/' || c == '\\' || c == ':' || c == '\0') return false;
  return true;
}

std::string SceneDir::display(const fs::path& p) const {
  // Lexical only: a symbolic link is shown by its own name, not its target.
  const fs::path rel = p.lexically_relative(root_);
  return (rel.empty() || *rel.begin() == ".." ? p : root_ / rel)
      .lexically_normal()
      .generic_string();
}

fs::path SceneDir::file(const std::string& sub, const std::string& name,
                        const std::string& origin) const {
  if (!isPlainFileName(name))
    throw InputError({origin, std::nullopt, std::nullopt}, "file name",
                     "a plain file name inside the scene's " + sub +
                         "/ directory (no '..', no '/' or '\\', no drive letter)",
                     "\"" + name + "\"");
  // Longer names make every file system call fail (ENAMETOOLONG), which
  // std::filesystem reports as an exception of its own, not as bad input.
  if (name.size() > kMaxFileName)
    throw InputError(
        {origin, std::nullopt, std::nullopt}, "file name",
        "at most " + std::to_string(kMaxFileName) + " bytes (the file system's NAME_MAX)",
        std::to_string(name.size()) + " bytes (\"" + name.substr(0, 40) + "...\")");
  return root_ / sub / name;
}

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

// M40: `part` inside `dir`, matched without regard to (ASCII) case. The
// directory is listed once and again only when a name is not in the listing
// (a file written since), so a scene of n objects costs n lookups, not n scans.
fs::path SceneDir::resolve(const fs::path& dir, const std::string& part) const {
  if (part == "." || part.empty()) return dir;
  const std::string key = lower(part);
  std::lock_guard lock(listing_->mutex);
  const std::string dirKey = dir.string();
  auto scan = [&] {
    auto& entries = listing_->byDir[dirKey];
    entries.clear();
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
      entries[lower(it->path().filename().string())].push_back(it->path().filename().string());
    return &entries;
  };
  auto found = listing_->byDir.find(dirKey);
  const auto* entries = found == listing_->byDir.end() ? scan() : &found->second;
  if (entries->find(key) == entries->end()) entries = scan();
  const auto hit = entries->find(key);
  if (hit == entries->end()) return dir / part;  // canonical: does not exist
  std::vector<std::string> names = hit->second;
  if (names.size() > 1) {
    std::sort(names.begin(), names.end());
    throw InputError({display(dir), std::nullopt, std::nullopt},
                     "two entries differ only by case, " + names[0] + " and " + names[1] +
                         "; PRIME looks its files up without regard to case (decision M40): "
                         "remove or rename one");
  }
  return dir / names.front();
}

fs::path SceneDir::find(const std::string& sub, const std::string& name) const {
  fs::path dir = root_;
  for (const auto& part : fs::path(sub)) dir = resolve(dir, part.string());
  return resolve(dir, name);
}

fs::path SceneDir::existingInput(const std::string& sub, const std::string& name,
                                 const std::string& origin) const {
  file(sub, name, origin);  // the name checks
  const fs::path p = find(sub, name);
  std::vector<fs::path> chain;
  fs::path dir = root_;
  for (const auto& part : fs::path(sub))
    if (part != ".") chain.push_back(dir = resolve(dir, part.string()));
  chain.push_back(p);
  for (const fs::path& q : chain) {
    if (fs::is_symlink(fs::symlink_status(q)))
      throw InputError({display(q), std::nullopt, std::nullopt},
                       "is a symbolic link; scene files must be real files inside the scene "
                       "directory (named by " +
                           origin + ")");
  }
  if (!fs::exists(p))
    throw InputError({display(p), std::nullopt, std::nullopt},
                     "file does not exist (named by " + origin + ")");
  return p;
}

fs::path findIgnoringCase(const fs::path& typed) {
  std::error_code ec;
  if (fs::exists(fs::symlink_status(typed, ec))) return typed;
  fs::path at = typed.root_path();
  for (const auto& part : typed.relative_path()) {
    const fs::path next = at / part;
    if (part == "." || part == ".." || fs::exists(fs::symlink_status(next, ec))) {
      at = next;
      continue;
    }
    const fs::path found = SceneDir(at.empty() ? fs::path(".") : at).find(".", part.string());
    if (!fs::exists(fs::symlink_status(found, ec))) return typed;
    at /= found.filename();
  }
  return at;
}

std::vector<fs::path> SceneDir::inputFiles() const {
  std::vector<fs::path> files;
  std::error_code ec;
  // The names as the scene has them (M40: MODEL.TXT, OBJ/COPY of a DOS copy).
  for (const char* name : {"Model.txt", "Model.c"})
    if (const fs::path m = find(".", name); fs::is_regular_file(m, ec)) files.push_back(m);
  for (const auto& [parent, sub] : {std::pair{".", "prim"},
                                    {".", "bound"},
                                    {".", "obj"},
                                    {"obj", "Copy"},
                                    {".", "map"},
                                    {".", "light"}}) {
    const fs::path d = find(parent, sub);
    if (fs::is_symlink(fs::symlink_status(d, ec)) || !fs::is_directory(d, ec)) continue;
    for (fs::directory_iterator it(d, ec), end; !ec && it != end; it.increment(ec))
      if (it->is_regular_file(ec)) files.push_back(it->path());
  }
  return files;
}

}  // namespace prime::io
