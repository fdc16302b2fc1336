// prime probe SCENE.mal --pixel X Y: why is this pixel that colour? The ray
// tree of one pixel of a Malone scene: every hit, light, shadow ray,
// reflected and transmitted ray, with the colour each returns.
#include <cstdio>
#include <iostream>

#include "legacy_io/malone/ppm.h"
#include "src/cli/malone/commands.h"
#include "src/cli/malone/options.h"

namespace prime::cli::malone {

void addProbeCommand(CLI::App& app, Action& action) {
  auto* cmd =
      app.add_subcommand(kProbeCommand, "The ray tree of one pixel of a Malone (1995) scene file");
  cmd->group("");  // reached through `prime probe FILE` (src/cli/main.cpp)
  auto o = std::make_shared<MaloneOptions>();
  auto pixel = std::make_shared<std::vector<int>>();
  addMaloneOptions(cmd, *o);
  cmd->add_option("--pixel", *pixel, "The pixel X Y (X from the left, Y from the top)")
      ->expected(2)
      ->required();
  cmd->callback([=, &action] {
    action = [=] {
      const prime::malone::Scene scene = loadMalone(*o);
      const int x = (*pixel)[0], y = (*pixel)[1];
      if (x < 0 || y < 0 || x >= scene.viewer.xRes || y >= scene.viewer.yRes) {
        std::cerr << "prime: probe: --pixel " << x << " " << y << " is outside the "
                  << scene.viewer.xRes << " x " << scene.viewer.yRes << " picture\n";
        return 2;
      }
      const prime::malone::Tracer tracer(scene, o->trace);
      prime::malone::TraceStats stats;
      std::string log;
      const Rgb c = tracer.pixel(x, y, stats, &log);
      std::cout << o->file << ": Malone (1995)\n" << log;
      std::printf("pixel (%d, %d) = (%.6g, %.6g, %.6g) -> bytes %d %d %d; %llu rays\n", x, y, c[0],
                  c[1], c[2], prime::malone::toByte(c[0]), prime::malone::toByte(c[1]),
                  prime::malone::toByte(c[2]), static_cast<unsigned long long>(stats.rays()));
      return 0;
    };
  });
}

}  // namespace prime::cli::malone
