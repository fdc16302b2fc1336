#include "legacy_io/common/run_inputs.h"

#include <sys/stat.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <utility>

#include "legacy_io/common/digest.h"
#include "legacy_io/common/error.h"

namespace prime::io {

namespace {

struct Registry {
  std::mutex mutex;
  int scopes = 0;
  std::map<std::pair<unsigned long long, unsigned long long>, std::string> inputs;
  // The XXH3 of each input read whole, by device and inode.
  std::map<std::pair<unsigned long long, unsigned long long>, std::uint64_t> content;
};

Registry& registry() {
  static Registry r;
  return r;
}

}  // namespace

RunInputs::RunInputs() {
  std::lock_guard lock(registry().mutex);
  ++registry().scopes;
}

RunInputs::~RunInputs() {
  std::lock_guard lock(registry().mutex);
  if (--registry().scopes == 0) {
    registry().inputs.clear();
    registry().content.clear();
  }
}

void noteInput(unsigned long long device, unsigned long long inode, const std::string& display) {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  if (r.scopes > 0) r.inputs.emplace(std::make_pair(device, inode), display);
}

void noteInputContent(unsigned long long device, unsigned long long inode,
                      const std::string& display, const void* bytes, std::size_t size) {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  if (r.scopes == 0) return;
  r.inputs.emplace(std::make_pair(device, inode), display);
  r.content[std::make_pair(device, inode)] = xxh3(bytes, size);
}

std::uint64_t inputsDigest(const std::vector<std::string>& excluding) {
  std::vector<std::pair<unsigned long long, unsigned long long>> skip;
  for (const std::string& path : excluding) {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) skip.emplace_back(st.st_dev, st.st_ino);
  }
  Registry& r = registry();
  std::vector<std::uint64_t> hashes;
  {
    std::lock_guard lock(r.mutex);
    if (r.scopes == 0) return 0;
    for (const auto& [file, hash] : r.content)
      if (std::find(skip.begin(), skip.end(), file) == skip.end()) hashes.push_back(hash);
  }
  std::sort(hashes.begin(), hashes.end());
  return xxh3(hashes.data(), hashes.size() * sizeof(std::uint64_t));
}

void forgetInputsContent() {
  Registry& r = registry();
  std::lock_guard lock(r.mutex);
  r.content.clear();
}

void protectInput(const std::string& path, const std::string& display) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode))
    noteInput(st.st_dev, st.st_ino, display.empty() ? path : display);
}

void refuseIfInput(const std::string& output) {
  struct stat st {};
  if (::stat(output.c_str(), &st) != 0) return;  // not there (yet): not an input
  Registry& r = registry();
  std::string input;
  {
    std::lock_guard lock(r.mutex);
    if (r.scopes == 0) return;
    auto found = r.inputs.find({st.st_dev, st.st_ino});
    if (found == r.inputs.end()) return;
    input = found->second;
  }
  throw InputError({output, std::nullopt, std::nullopt},
                   "refusing to write: this output is the input " + input +
                       " of this run (the same file), which writing it would destroy; "
                       "choose another output path");
}

}  // namespace prime::io
