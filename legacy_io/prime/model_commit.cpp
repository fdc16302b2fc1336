#include "legacy_io/prime/model_commit.h"

#include <nettle/sha2.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>

#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"
#include "legacy_io/common/output_file.h"

namespace prime::io {

namespace fs = std::filesystem;

namespace {

constexpr const char* kHeader = "prime-model 1";
// The largest database: a map of 32767 doubles and its header, or a PrimFile
// of 32768 records; the journal and stamp: one line per database.
constexpr std::uint64_t kMaxDatabase = 64ull << 20;

std::string sha256(const std::vector<std::uint8_t>& bytes) {
  // Nettle's SHA-256 (libnettle, Debian nettle-dev). It was OpenSSL's
  // libcrypto until its 19,000 relocations, made at every start of every
  // command, measured 2.5 ms of CPU per process (an empty program linked
  // with each, 101 interleaved runs: libcrypto +2.5 ms, libnettle +0.3 ms).
  sha256_ctx ctx;
  sha256_init(&ctx);
  sha256_update(&ctx, bytes.size(), bytes.data());
  std::uint8_t md[SHA256_DIGEST_SIZE];
  sha256_digest(&ctx, SHA256_DIGEST_SIZE, md);
  static const char* hex = "0123456789abcdef";
  std::string s;
  for (const std::uint8_t b : md) {
    s += hex[b >> 4];
    s += hex[b & 15];
  }
  return s;
}

// The fault-injection test hook (model_commit.h).
struct Fault {
  enum class Kind { None, Kill, Fail } kind = Kind::None;
  long step = 0;
};

Fault faultFromEnvironment() {
  Fault f;
  const char* v = std::getenv(kModelFaultVariable);
  if (v == nullptr) return f;
  const std::string s(v);
  if (s.rfind("kill:", 0) == 0) f.kind = Fault::Kind::Kill;
  if (s.rfind("fail:", 0) == 0) f.kind = Fault::Kind::Fail;
  if (f.kind != Fault::Kind::None) f.step = std::strtol(s.c_str() + 5, nullptr, 10);
  return f;
}

long stepsTaken = 0;

void faultPoint(const std::string& what) {
  const Fault fault = faultFromEnvironment();  // read each time: tests set it per run
  if (fault.kind == Fault::Kind::None || ++stepsTaken != fault.step) return;
  if (fault.kind == Fault::Kind::Kill) ::raise(SIGKILL);
  throw InputError({what, std::nullopt, std::nullopt}, "cannot be replaced: injected failure (" +
                                                           std::string(kModelFaultVariable) +
                                                           ", a test hook)");
}

struct Entry {
  std::string digest;
  std::uint64_t size = 0;
  std::string path;  // relative: prim/PrimFile, obj/O1, map/Map1_R.map
  std::string temp;  // the temporary's file name, beside the target
  int line = 0;
};

// A database path of the journal or stamp, checked like every scene name.
fs::path databasePath(const SceneDir& scene, const std::string& rel, const std::string& origin) {
  const auto slash = rel.find('/');
  const std::string sub = slash == std::string::npos ? "" : rel.substr(0, slash);
  const std::string name = slash == std::string::npos ? rel : rel.substr(slash + 1);
  if (sub != "prim" && sub != "obj" && sub != "map")
    throw InputError({origin, std::nullopt, std::nullopt}, "database path",
                     "prim/, obj/ or map/ and a file name", "\"" + rel + "\"");
  scene.file(sub, name, origin);  // the name checks
  // Where the scene has it (M40): a DOS copy's OBJ/O1 is written over as
  // OBJ/O1, into the directories it has, never beside them as obj/O1.
  return scene.find(sub, name);
}

std::vector<Entry> readEntries(const SceneDir& scene, const fs::path& file) {
  InputFileOptions o;
  o.what = "a prime model journal or stamp";
  o.display = scene.display(file);
  o.sceneContent = false;  // names temporaries by process id: not in the scene's digest
  o.maxBytes = kMaxDatabase;
  std::istringstream in(readInputText(file.string(), o));
  std::string line;
  std::vector<Entry> entries;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (n == 1) {
      if (line != kHeader)
        throw InputError({o.display, n, std::nullopt}, "header", std::string("\"") + kHeader + "\"",
                         quotedWord(line, 40));
      continue;
    }
    std::istringstream words(line);
    Entry e;
    e.line = n;
    if (!(words >> e.digest >> e.size >> e.path >> e.temp) || e.digest.size() != 64)
      throw InputError({o.display, n, std::nullopt}, "entry",
                       "SHA-256 (64 hex digits), size, database path, temporary",
                       quotedWord(line, 60));
    databasePath(scene, e.path, o.display + ":" + std::to_string(n));
    if (!isPlainFileName(e.temp))
      throw InputError({o.display, n, std::nullopt}, "temporary", "a plain file name",
                       quotedWord(e.temp, 60));
    entries.push_back(std::move(e));
  }
  if (n == 0) throw InputError({o.display, std::nullopt, std::nullopt}, "is empty");
  return entries;
}

bool hasDigest(const fs::path& p, const Entry& e) {
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(p, ec)) || !fs::is_regular_file(p, ec)) return false;
  if (fs::file_size(p, ec) != e.size || ec) return false;
  InputFileOptions o;
  o.maxBytes = kMaxDatabase;
  return sha256(readInputFile(p.string(), o)) == e.digest;
}

void removeDeadTemporaries(const SceneDir& scene) {
  for (const char* sub : {".", "prim", "obj", "map"}) {
    std::error_code ec;
    const fs::path dir = scene.find(".", sub);  // PRIM/ of a DOS copy too (M40)
    if (fs::is_directory(dir, ec)) removeStaleTemporariesIn(dir.string());
  }
}

[[noreturn]] void renameFailed(const fs::path& from, const std::string& shown, int error) {
  throw InputError(
      {shown, std::nullopt, std::nullopt},
      "cannot be replaced (from " + from.filename().string() + "): " + std::strerror(error));
}

}  // namespace

std::unique_ptr<DirLock> lockForModel(const SceneDir& scene, bool wait) {
  auto lock = std::make_unique<DirLock>((scene.root() / kModelLock).string(), "prime model");
  if (lock->tryLock(DirLock::Mode::Exclusive)) return lock;
  if (!wait) lock->busy(scene.display(scene.root()), "try again when it is done, or add --wait");
  std::cerr << "prime: waiting: " << lock->holderText() << " " << scene.display(scene.root())
            << "\n";
  lock->lock(DirLock::Mode::Exclusive);
  return lock;
}

bool holdsPrimeScene(const SceneDir& scene) {
  std::error_code ec;
  for (const char* name :
       {"Model.txt", "Model.c", kModelStamp, kModelJournal, kModelLock, "prim", "obj"})
    if (fs::exists(scene.find(".", name), ec)) return true;
  return false;
}

std::unique_ptr<DirLock> openModelForReading(const SceneDir& scene) {
  // A directory with nothing of a PRIME scene in it (another system's scene,
  // an empty directory) gets no lock file: the reader's error follows, and
  // the directory is left as it was.
  std::error_code ec;
  if (!holdsPrimeScene(scene)) {
    verifyModel(scene);
    return nullptr;
  }
  std::unique_ptr<DirLock> lock;
  try {
    lock = std::make_unique<DirLock>((scene.root() / kModelLock).string(), "prime model");
  } catch (const InputError&) {
    verifyModel(scene);  // a read-only scene: nothing can be finished, only checked
    return nullptr;
  }
  if (!lock->tryLock(DirLock::Mode::Shared)) {
    std::cerr << "prime: waiting: " << lock->holderText() << " " << scene.display(scene.root())
              << "\n";
    lock->lock(DirLock::Mode::Shared);
  }
  if (fs::exists(scene.root() / kModelJournal, ec)) {
    // An interrupted run: finish it, alone (flock converts the lock).
    lock->lock(DirLock::Mode::Exclusive);
    settleModel(scene);
    lock->lock(DirLock::Mode::Shared);
  }
  verifyModel(scene);
  return lock;
}

bool settleModel(const SceneDir& scene, bool discard) {
  const fs::path journal = scene.root() / kModelJournal;
  std::error_code ec;
  bool finished = false;
  if (fs::exists(fs::symlink_status(journal, ec))) {
    try {
      const std::vector<Entry> entries = readEntries(scene, journal);
      for (const Entry& e : entries) {
        const fs::path target = databasePath(scene, e.path, scene.display(journal));
        const fs::path temp = target.parent_path() / e.temp;
        if (fs::exists(fs::symlink_status(temp, ec))) {
          faultPoint(scene.display(target));
          if (::rename(temp.c_str(), target.c_str()) != 0)
            renameFailed(temp, scene.display(target), errno);
        } else if (!hasDigest(target, e)) {
          throw InputError({scene.display(target), std::nullopt, std::nullopt},
                           "cannot finish the interrupted prime model run recorded in " +
                               scene.display(journal) +
                               ": neither its temporary nor the database it wrote is there; run "
                               "prime model " +
                               scene.display(scene.root()) + " again");
        }
      }
      faultPoint(scene.display(journal));
      if (::rename(journal.c_str(), (scene.root() / kModelStamp).c_str()) != 0)
        renameFailed(journal, scene.display(scene.root() / kModelStamp), errno);
      finished = true;
    } catch (const InputError&) {
      if (!discard) throw;
      // `prime model` writes every database again: the journal and the stamp go.
      fs::remove(journal, ec);
      fs::remove(scene.root() / kModelStamp, ec);
    }
  }
  removeDeadTemporaries(scene);
  return finished;
}

void verifyModel(const SceneDir& scene) {
  const fs::path journal = scene.root() / kModelJournal, stamp = scene.root() / kModelStamp;
  const std::string dir = scene.display(scene.root());
  std::error_code ec;
  if (fs::exists(fs::symlink_status(journal, ec)))
    throw InputError({scene.display(journal), std::nullopt, std::nullopt},
                     "an interrupted prime model run could not be finished here; run prime model " +
                         dir + " again");
  if (!fs::exists(fs::symlink_status(stamp, ec))) return;  // built before stamps: as before
  for (const Entry& e : readEntries(scene, stamp)) {
    const fs::path p = databasePath(scene, e.path, scene.display(stamp));
    if (!hasDigest(p, e))
      throw InputError({scene.display(p), std::nullopt, std::nullopt},
                       "the databases are a mixture of two `prime model` runs (or were changed "
                       "after it): this file is not the one " +
                           scene.display(stamp) + " records; run prime model " + dir + " again");
  }
}

void commitDatabases(const SceneDir& scene, const std::vector<DatabaseFile>& files) {
  settleModel(scene, /*discard=*/true);
  stepsTaken = 0;
  // 1. Every database to a temporary beside its target.
  std::vector<std::unique_ptr<OutputFile>> outs;
  std::ostringstream journal;
  journal << kHeader << "\n";
  for (const auto& f : files) {
    const fs::path path = databasePath(scene, f.path, "prime model");
    fs::create_directories(path.parent_path());
    if (fs::is_symlink(fs::symlink_status(path)))
      throw InputError({scene.display(path), std::nullopt, std::nullopt},
                       "is a symbolic link; refusing to write through it");
    outs.push_back(std::make_unique<OutputFile>(path.string()));
    outs.back()->write(f.bytes);
    outs.back()->finish();
    faultPoint(scene.display(path));
    journal << sha256(f.bytes) << " " << f.bytes.size() << " " << f.path << " "
            << fs::path(outs.back()->temporary()).filename().string() << "\n";
  }
  // 2. The journal: the commit point. From here the temporaries belong to
  // it (a signal must not remove them), so they are released first; a run
  // killed between the two leaves temporaries of a dead process, which the
  // next run removes.
  std::vector<std::string> temps;
  for (auto& out : outs) temps.push_back(out->release());
  try {
    OutputFile j((scene.root() / kModelJournal).string());
    j.write(journal.str());
    faultPoint(scene.display(scene.root() / kModelJournal));
    j.commit();
  } catch (...) {
    for (const auto& t : temps) ::unlink(t.c_str());  // no commit point: the old databases stay
    throw;
  }
  // 3 and 4: the renames and the stamp, as a later recovery would do them.
  settleModel(scene);
}

}  // namespace prime::io
