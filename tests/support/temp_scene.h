// A scene directory written into a fresh temporary directory by a test, file
// by file, so each test shows exactly the inputs it uses.
#pragma once
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace prime::test {

class TempScene {
 public:
  TempScene() {
    std::random_device rd;
    root_ = std::filesystem::temp_directory_path() /
            ("prime-test-" + std::to_string(rd()) + "-" + std::to_string(rd()));
    for (const char* sub : {"prim", "bound", "obj/Copy", "map", "light"})
      std::filesystem::create_directories(root_ / sub);
  }
  ~TempScene() {
    std::error_code ec;
    std::filesystem::remove_all(root_, ec);
  }
  TempScene(const TempScene&) = delete;
  TempScene& operator=(const TempScene&) = delete;

  void write(const std::string& rel, const std::string& text) const {
    std::filesystem::create_directories((root_ / rel).parent_path());
    std::ofstream(root_ / rel, std::ios::binary) << text;
  }
  void writeBytes(const std::string& rel, const std::vector<std::uint8_t>& bytes) const {
    std::ofstream out(root_ / rel, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
  }
  std::vector<std::uint8_t> read(const std::string& rel) const {
    std::ifstream in(root_ / rel, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  bool exists(const std::string& rel) const { return std::filesystem::exists(root_ / rel); }
  std::filesystem::path path(const std::string& rel = "") const {
    return rel.empty() ? root_ : root_ / rel;
  }

 private:
  std::filesystem::path root_;
};

#ifdef PRIME_TEST_DATA
// Fills the scene with the sphere test scene's text inputs
// (tests/prime/data/sphere) and returns its path.
inline std::filesystem::path sphere(const TempScene& s) {
  std::filesystem::copy(
      std::filesystem::path(PRIME_TEST_DATA) / "sphere", s.path(),
      std::filesystem::copy_options::recursive | std::filesystem::copy_options::overwrite_existing);
  return s.path();
}
#endif

}  // namespace prime::test
