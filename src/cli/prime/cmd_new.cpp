// prime new DIR: a small commented starting scene in PRIME's text-input
// format (an orange sphere and a cube with a checker texture, two lights),
// the tutorial's (docs/prime/scene-authoring.md) values. `prime model DIR`
// then `prime trace DIR` render it. The listing's readers stop after the
// fields they read, so each file's comments follow its numbers.
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "legacy_io/common/error.h"
#include "legacy_io/common/output_file.h"
#include "src/cli/commands.h"

namespace prime::cli {

namespace fs = std::filesystem;

namespace {

// The cube's 4 x 4 checker of yellow (0.05 0.05 0) and red (0.05 0 0) texels
// (0.05 is "on": K12), as tools/prime/mapgen.py checker writes it.
std::string checkerMap() {
  std::string s = "2\n4 4\n";
  for (int plane = 0; plane < 3; ++plane)
    for (int v = 0; v < 4; ++v) {
      for (int u = 0; u < 4; ++u) {
        const bool yellow = (u + v) % 2 == 0;
        const char* t = plane == 0 ? "0.05" : plane == 1 && yellow ? "0.05" : "0";
        s += std::string(u ? " " : "") + t;
      }
      s += "\n";
    }
  return s +
         "# map 2: number, size (u v), then the red, green and blue planes, a row per v.\n"
         "# 0 is off and 0.05 the brightest texel (listing errata K11, K12).\n";
}

std::vector<std::pair<std::string, std::string>> sceneFiles() {
  return {
      {"Model.txt",
       "# A starting scene made by `prime new`: the modelling calls of the listing's Model.c,\n"
       "# one per line. Build the databases with `prime model DIR`, render with\n"
       "# `prime trace DIR --png out.png`, check values with `prime check DIR`.\n"
       "# Writing scenes: docs/prime/scene-authoring.md; every file: docs/prime/file-formats.md.\n"
       "# (A 1991 disk's Model.c is read when there is no Model.txt; with both, this file wins.)\n"
       "AddObj d1.txt       # object 1: obj/D1.txt (its CSG tree) and obj/H1.txt (its hue)\n"
       "AddToObjList 1\n"
       "AddObj d2.txt       # object 2: the cube\n"
       "AddToObjList 2\n"
       "AddMap Map1.txt     # every surface names a map: map 1 is plain\n"
       "AddMap Map2.txt     # map 2 is the cube's checker\n"},
      {"prim/S1.txt",
       "S\n150 150 150\n500 650 300\n0 0 0\n0 0 0\n1 1\n1\n"
       "# A sphere: the type letter at byte 0 (K36), then scale, translation, rotation in degrees\n"
       "# (about X, Y, Z), pivot, one outside/inside map pair per surface, and a priority.\n"
       "# The camera looks along +z from (500, 500, -1500) at the window x 0..1000, y 0..1000.\n"},
      {"prim/B1.txt",
       "B\n260 260 260\n250 280 350\n-20 30 0\n0.5 0.5 0.5\n2 2  2 2  2 2  2 2  2 2  2 2\n1\n"
       "# A cube of side 260 turned about its centre (the pivot is in unit coordinates: the\n"
       "# unit cube is [0, 1]^3), with map 2 on its six faces.\n"},
      {"obj/D1.txt",
       "1\nS 1\nNULL\n"
       "# The CSG tree: the number of entries, the entries (a leaf is a letter and a number,\n"
       "# two words: K35), then the bounding volume or NULL.\n"},
      {"obj/H1.txt",
       "0.0 1.0\n0.2 0.6 0.8\n0.999\n0 0\n1.0001\n"
       "# The hue: kDR kDT, fDR (r g b), tT, kRH kTH, indx. With kDR 0 and kDT 1 the object\n"
       "# shows 1 - fDR, here orange (0.8 0.4 0.2) (K10). kRH and kTH must be integers (K10),\n"
       "# tT just below 1 (K14), indx not exactly 1 (K13); `prime check` checks them.\n"},
      {"obj/D2.txt", "1\nB 1\nNULL\n# Object 2: one cube.\n"},
      {"obj/H2.txt", "0.0 1.0\n0.75 0.75 0.75\n0.999\n0 0\n1.0001\n# A grey cube (1 - fDR).\n"},
      {"map/Map1.txt", "1\n1 1\n0\n0\n0\n# map 1: one texel of zeros, a plain surface.\n"},
      {"map/Map2.txt", checkerMap()},
      {"light/light.txt",
       "0.3 0.3 0.3\n2\n500 1500 -1500 0.5 0.5 0.5\n2000 0 -500 0 0.2 0.4\n"
       "# The ambient light (r g b), the number of lights (at most 10: K40), then per light its\n"
       "# position and intensity. There are no shadows (K9). Read at render time.\n"},
  };
}

}  // namespace

void addNewCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "new", "Write a small commented starting scene (a sphere, a textured cube, two lights)");
  auto dir = std::make_shared<std::string>();
  auto quiet = std::make_shared<bool>(false);
  cmd->add_option("DIR", *dir, "Scene directory to create (must not exist, or be empty)")
      ->required();
  cmd->add_flag("-q,--quiet", *quiet, "Print nothing on success");
  cmd->callback([=, &action] {
    action = [=] {
      std::error_code ec;
      // An empty name would write the scene into the current directory.
      if (dir->empty())
        throw io::InputError({"prime new", std::nullopt, std::nullopt}, "DIR",
                             "the name of a new or empty directory", "an empty name");
      if (fs::exists(*dir, ec) && !(fs::is_directory(*dir, ec) && fs::is_empty(*dir, ec)))
        throw io::InputError({*dir, std::nullopt, std::nullopt}, "DIR",
                             "a new or empty directory (prime new overwrites nothing)",
                             "an existing non-empty " +
                                 std::string(fs::is_directory(*dir, ec) ? "directory" : "file"));
      // The scene is written whole beside DIR and renamed into place: a full
      // disk or a signal leaves nothing half-written to block a retry.
      const fs::path target = fs::path(*dir).lexically_normal();
      const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
      std::string pattern =
          (parent / (".prime-new." + std::to_string(::getpid()) + ".XXXXXX")).string();
      if (::mkdtemp(pattern.data()) == nullptr)
        throw io::InputError(
            {parent.string(), std::nullopt, std::nullopt},
            std::string("cannot create the new scene beside it: ") + std::strerror(errno));
      const fs::path temp = pattern;
      try {
        for (const char* sub : {"prim", "obj", "map", "light"}) {
          fs::create_directories(temp / sub, ec);
          if (ec)
            throw io::InputError({(target / sub).string(), std::nullopt, std::nullopt},
                                 "cannot create the directory: " + ec.message());
        }
        for (const auto& [name, text] : sceneFiles()) {
          io::OutputFile out((temp / name).string());
          out.write(text);
          out.commit();
        }
        // mkdtemp makes it 0700; a scene directory is an ordinary one.
        const mode_t mask = ::umask(0);
        ::umask(mask);
        fs::permissions(temp, static_cast<fs::perms>(0777 & ~mask));
        // rename(2) replaces an empty directory, and refuses one that is not.
        fs::rename(temp, target);
      } catch (const std::exception& e) {
        fs::remove_all(temp, ec);
        if (dynamic_cast<const io::InputError*>(&e)) throw;
        throw io::InputError({*dir, std::nullopt, std::nullopt},
                             std::string("cannot be written: ") + e.what());
      }
      if (!*quiet)
        std::cout << "wrote " << *dir << ": a sphere and a textured cube; next: prime model "
                  << *dir << " && prime trace " << *dir << " --png " << *dir << ".png\n";
      return 0;
    };
  });
}

}  // namespace prime::cli
