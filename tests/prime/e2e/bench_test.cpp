// prime bench --quick as a user runs it: the CSV's columns, a reference row
// with zero error, the Markdown and the plot; and a tiny scale study.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "palette/png_image.h"
#include "tests/support/temp_scene.h"

namespace {

namespace fs = std::filesystem;

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  bool quoted = false;
  for (char c : line) {
    if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted) {
      out.push_back(cell);
      cell.clear();
    } else
      cell += c;
  }
  out.push_back(cell);
  return out;
}

std::vector<std::vector<std::string>> readCsv(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) rows.push_back(splitCsv(line));
  return rows;
}

int column(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return static_cast<int>(i);
  ADD_FAILURE() << "no column " << name;
  return 0;
}

TEST(PrimeBench, QuickRunOnTheSphereWritesCsvMarkdownAndPlot) {
  prime::test::TempScene out;
  const fs::path scene = fs::path(PRIME_TEST_DATA) / "sphere";
  const bool hadDatabases = fs::exists(scene / "prim" / "PrimFile");
  const std::string cmd = std::string(PRIME_EXE) + " bench --quick -q " + scene.string() +
                          " --out " + out.path("res").string();
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  // The scene is modelled in a copy, never in place.
  EXPECT_EQ(fs::exists(scene / "prim" / "PrimFile"), hadDatabases);
  EXPECT_FALSE(fs::exists(scene / "graph_scr"));

  const auto rows = readCsv(out.path("res/bench.csv"));
  ASSERT_GE(rows.size(), 3u);
  const std::vector<std::string> expected = {"scene",
                                             "setting",
                                             "reference",
                                             "max_depth",
                                             "min_weight",
                                             "sampling",
                                             "threads",
                                             "runs",
                                             "columns",
                                             "rows",
                                             "wall_median_s",
                                             "wall_min_s",
                                             "wall_max_s",
                                             "cpu_median_s",
                                             "cpu_min_s",
                                             "cpu_max_s",
                                             "rays",
                                             "primary_rays",
                                             "reflected_rays",
                                             "transmitted_rays",
                                             "bound_tests",
                                             "object_tests",
                                             "primitive_tests",
                                             "rmse",
                                             "max_error",
                                             "index_diff_share",
                                             "pareto",
                                             "paired_speedup"};
  EXPECT_EQ(rows[0], expected);
  for (std::size_t i = 1; i < rows.size(); ++i)
    EXPECT_EQ(rows[i].size(), expected.size()) << "row " << i;

  const auto& h = rows[0];
  // The first row is the reference: 4 x 4 rays per pixel, depth 12, zero error.
  const auto& ref = rows[1];
  EXPECT_EQ(ref[column(h, "scene")], "sphere");
  EXPECT_EQ(ref[column(h, "reference")], "1");
  EXPECT_EQ(ref[column(h, "max_depth")], "12");
  EXPECT_EQ(ref[column(h, "sampling")], "grid4");
  EXPECT_EQ(std::stod(ref[column(h, "rmse")]), 0.0);
  EXPECT_EQ(std::stod(ref[column(h, "max_error")]), 0.0);
  EXPECT_EQ(std::stod(ref[column(h, "index_diff_share")]), 0.0);
  const int columns = std::stoi(ref[column(h, "columns")]),
            pixelRows = std::stoi(ref[column(h, "rows")]);
  EXPECT_EQ(columns, 45);  // --quick: a 128 x 96 screen, the listing's viewport
  EXPECT_EQ(pixelRows, 97);
  EXPECT_EQ(std::stoull(ref[column(h, "primary_rays")]), 16ull * columns * pixelRows);

  int pareto = 0, listing = 0;
  for (std::size_t i = 2; i < rows.size(); ++i) {
    const auto& r = rows[i];
    EXPECT_EQ(r[column(h, "reference")], "0");
    const double rmse = std::stod(r[column(h, "rmse")]), mx = std::stod(r[column(h, "max_error")]);
    EXPECT_GE(rmse, 0.0);
    EXPECT_LE(rmse, mx + 1e-12);
    EXPECT_LE(mx, 1.0);
    EXPECT_GT(std::stod(r[column(h, "cpu_median_s")]), 0.0);
    pareto += r[column(h, "pareto")] == "1";
    if (r[column(h, "sampling")] == "single" && r[column(h, "max_depth")] == "5" &&
        r[column(h, "min_weight")] == "0" && r[column(h, "threads")] == "1") {
      ++listing;
      // One ray per pixel: every primary ray is the listing's.
      EXPECT_EQ(std::stoull(r[column(h, "primary_rays")]), 1ull * columns * pixelRows);
      // The lone sphere's single-sample picture differs from the 4 x 4 one on its silhouette only.
      EXPECT_GT(std::stod(r[column(h, "index_diff_share")]), 0.0);
      EXPECT_LT(std::stod(r[column(h, "index_diff_share")]), 0.2);
    }
  }
  EXPECT_GE(pareto, 1);
  EXPECT_EQ(listing, 1);
  // The 2-thread row carries the paired speed-up; the others leave it empty.
  int paired = 0;
  for (std::size_t i = 1; i < rows.size(); ++i)
    if (rows[i][column(h, "threads")] == "2" && rows[i][column(h, "reference")] == "0") {
      ++paired;
      EXPECT_GT(std::stod(rows[i][column(h, "paired_speedup")]), 0.0);
    } else {
      EXPECT_EQ(rows[i][column(h, "paired_speedup")], "");
    }
  EXPECT_EQ(paired, 1);

  std::ifstream md(out.path("res/bench.md"));
  std::stringstream text;
  text << md.rdbuf();
  EXPECT_THAT(text.str(), ::testing::HasSubstr("### sphere (45 x 97 pixels)"));
  EXPECT_THAT(text.str(), ::testing::HasSubstr("prime bench"));
  const prime::Image8 plot = prime::readPng(out.path("res/time_error.png").string());
  EXPECT_GT(plot.width, 100);
  EXPECT_GT(plot.height, 100);
}

TEST(PrimeBench, TinyScaleStudy) {
  prime::test::TempScene out;
  const std::string cmd = std::string(PRIME_EXE) +
                          " bench --only-scale --quick -q --scale-sizes 1 10 --out " +
                          out.path("res").string();
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const auto rows = readCsv(out.path("res/scale.csv"));
  ASSERT_EQ(rows.size(), 5u);  // header, 1 and 10 objects with the skips on and off
  const auto& h = rows[0];
  EXPECT_EQ(rows[1][column(h, "objects")], "1");
  EXPECT_EQ(rows[1][column(h, "skips")], "on");
  EXPECT_EQ(rows[2][column(h, "skips")], "off");
  EXPECT_EQ(rows[4][column(h, "objects")], "10");
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_GT(std::stol(rows[i][column(h, "peak_rss_kb")]), 0);
    EXPECT_GT(std::stod(rows[i][column(h, "rays")]), 0.0);
  }
  // The skips only remove work: never more primitive tests with them on.
  EXPECT_LE(std::stod(rows[3][column(h, "primitive_tests")]),
            std::stod(rows[4][column(h, "primitive_tests")]));
  EXPECT_TRUE(fs::exists(out.path("res/scale_time.png")));
  EXPECT_TRUE(fs::exists(out.path("res/scale_memory.png")));
}

}  // namespace
