#include "palette/quantize/quantize.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace prime::quantize {

std::string_view methodName(Method m) {
  switch (m) {
    case Method::Popularity:
      return "popularity";
    case Method::MedianCut:
      return "median-cut";
    case Method::Octree:
      return "octree";
  }
  return "?";
}

std::optional<Method> methodFromName(std::string_view name) {
  for (Method m : {Method::Popularity, Method::MedianCut, Method::Octree})
    if (methodName(m) == name) return m;
  return std::nullopt;
}

std::string_view ditherName(Dither d) {
  switch (d) {
    case Dither::None:
      return "none";
    case Dither::Ordered:
      return "ordered";
    case Dither::FloydSteinberg:
      return "floyd-steinberg";
  }
  return "?";
}

std::optional<Dither> ditherFromName(std::string_view name) {
  for (Dither d : {Dither::None, Dither::Ordered, Dither::FloydSteinberg})
    if (ditherName(d) == name) return d;
  return std::nullopt;
}

Colour8 Palette::shown(std::size_t i) const {
  const int max = maxLevel();
  Colour8 c{};
  for (int k = 0; k < 3; ++k)
    c[k] = static_cast<std::uint8_t>((levels[i][k] * 255 + max / 2) / max);
  return c;
}

std::uint8_t Palette::levelOf(double v8) const {
  const double v = std::clamp(v8, 0.0, 255.0) * maxLevel() / 255.0;
  return static_cast<std::uint8_t>(std::lround(v));
}

namespace {

void checkSettings(const Image8& image, int colours, int dacBits) {
  if (colours < 1 || colours > 256)
    throw std::invalid_argument("quantize: colours must be 1..256, not " + std::to_string(colours));
  if (dacBits < 1 || dacBits > 8)
    throw std::invalid_argument("quantize: DAC bits must be 1..8, not " + std::to_string(dacBits));
  if (image.width < 0 || image.height < 0 ||
      image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3)
    throw std::invalid_argument("quantize: the image's pixels do not match its size");
}

// The picture's colours gathered by DAC cell (T57): the cell of a pixel is the
// nearest DAC level of each channel; each cell keeps its pixel count and the
// sums of its pixels' 8-bit values, so a representative is the mean of the
// pixels it stands for.
struct Cell {
  std::uint32_t key = 0;  // r level << 16 | g level << 8 | b level
  std::uint64_t count = 0;
  std::uint64_t sum[3] = {0, 0, 0};
  double mean(int c) const { return static_cast<double>(sum[c]) / static_cast<double>(count); }
};

std::vector<Cell> histogram(const Image8& image, const Palette& p) {
  const int bits = p.dacBits;
  std::array<std::uint32_t, 256> level{};
  for (int v = 0; v < 256; ++v) level[static_cast<std::size_t>(v)] = p.levelOf(v);
  const std::size_t n = image.rgb.size() / 3;
  const auto keyOf = [&](std::size_t i) {
    const std::uint8_t* px = &image.rgb[3 * i];
    return level[px[0]] << 16 | level[px[1]] << 8 | level[px[2]];
  };
  std::vector<Cell> used;
  if (bits <= 6) {  // a dense table of 2^(3 bits) cells (the DAC's 262,144)
    std::vector<Cell> cells(std::size_t{1} << (3 * bits));
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t key = keyOf(i);
      Cell& c = cells[(key >> 16) << (2 * bits) | ((key >> 8) & 0xFF) << bits | (key & 0xFF)];
      c.key = key;
      ++c.count;
      for (int k = 0; k < 3; ++k) c.sum[k] += image.rgb[3 * i + k];
    }
    for (const Cell& c : cells)
      if (c.count > 0) used.push_back(c);
  } else {  // finer DACs: sort the pixels by cell
    std::vector<std::pair<std::uint32_t, std::uint32_t>> keys(n);
    for (std::size_t i = 0; i < n; ++i) keys[i] = {keyOf(i), static_cast<std::uint32_t>(i)};
    std::sort(keys.begin(), keys.end());
    for (const auto& [key, i] : keys) {
      if (used.empty() || used.back().key != key) used.push_back(Cell{key, 0, {0, 0, 0}});
      ++used.back().count;
      for (int k = 0; k < 3; ++k) used.back().sum[k] += image.rgb[3 * std::size_t{i} + k];
    }
  }
  return used;  // in key order
}

Levels levelsOfMean(const Palette& p, const std::uint64_t sum[3], std::uint64_t count) {
  Levels l{};
  for (int k = 0; k < 3; ++k)
    l[k] = p.levelOf(static_cast<double>(sum[k]) / static_cast<double>(count));
  return l;
}

// 4.4.2: the `colours` most popular cells, most popular first (ties: lower
// key first), each as the mean of its pixels (T51).
void popularity(const Image8& image, Palette& p, int colours) {
  std::vector<Cell> cells = histogram(image, p);
  std::stable_sort(cells.begin(), cells.end(),
                   [](const Cell& a, const Cell& b) { return a.count > b.count; });
  cells.resize(std::min(cells.size(), static_cast<std::size_t>(colours)));
  for (const Cell& c : cells) p.levels.push_back(levelsOfMean(p, c.sum, c.count));
}

// 4.4.3, Heckbert's median cut over the cells (T52).
struct Box {
  std::size_t begin = 0, end = 0;
  std::uint64_t count = 0;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
};

Box makeBox(const std::vector<Cell>& cells, std::size_t begin, std::size_t end) {
  Box b{begin, end, 0, {255, 255, 255}, {0, 0, 0}};
  for (std::size_t i = begin; i < end; ++i) {
    b.count += cells[i].count;
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = std::min(b.lo[k], cells[i].mean(k));
      b.hi[k] = std::max(b.hi[k], cells[i].mean(k));
    }
  }
  return b;
}

void medianCut(const Image8& image, Palette& p, int colours) {
  std::vector<Cell> cells = histogram(image, p);
  if (cells.empty()) return;
  std::vector<Box> boxes{makeBox(cells, 0, cells.size())};
  bool first = true;
  while (boxes.size() < static_cast<std::size_t>(colours)) {
    // The box standing for the most pixels that can still be split.
    std::size_t pick = boxes.size();
    for (std::size_t i = 0; i < boxes.size(); ++i)
      if (boxes[i].end - boxes[i].begin >= 2 &&
          (pick == boxes.size() || boxes[i].count > boxes[pick].count))
        pick = i;
    if (pick == boxes.size()) break;  // every box holds one cell
    const Box box = boxes[pick];
    // The thesis: the first cut is across red; then each box's longest side.
    int axis = 0;
    if (!(first && box.hi[0] > box.lo[0]))
      for (int k = 1; k < 3; ++k)
        if (box.hi[k] - box.lo[k] > box.hi[axis] - box.lo[axis]) axis = k;
    first = false;
    const auto begin = cells.begin() + static_cast<std::ptrdiff_t>(box.begin);
    const auto end = cells.begin() + static_cast<std::ptrdiff_t>(box.end);
    std::sort(begin, end, [axis](const Cell& a, const Cell& b) {
      const double x = a.mean(axis), y = b.mean(axis);
      return x != y ? x < y : a.key < b.key;
    });
    // The median: the first cell at which half of the box's pixels are reached;
    // it closes the lower box (and never leaves the upper one empty).
    std::uint64_t below = 0;
    std::size_t cut = box.begin;
    while (cut < box.end - 1) {
      below += cells[cut].count;
      ++cut;
      if (2 * below >= box.count) break;
    }
    boxes[pick] = makeBox(cells, box.begin, cut);
    boxes.push_back(makeBox(cells, cut, box.end));
  }
  for (const Box& b : boxes) {
    std::uint64_t sum[3] = {0, 0, 0};
    for (std::size_t i = b.begin; i < b.end; ++i)
      for (int k = 0; k < 3; ++k) sum[k] += cells[i].sum[k];
    p.levels.push_back(levelsOfMean(p, sum, b.count));
  }
}

// 4.4.4, Gervautz and Purgathofer's octree, built and reduced in one pass
// over the pixels in raster order (T53).
class Octree {
 public:
  explicit Octree(int colours) : colours_(colours) { root_ = newNode(0); }

  void add(const std::uint8_t* px) {
    std::int32_t n = root_;
    for (;;) {
      Node& node = nodes_[static_cast<std::size_t>(n)];
      ++node.count;
      if (node.leaf) {
        for (int k = 0; k < 3; ++k) node.sum[k] += px[k];
        break;
      }
      const int shift = 7 - node.level;
      const int child =
          ((px[0] >> shift) & 1) << 2 | ((px[1] >> shift) & 1) << 1 | ((px[2] >> shift) & 1);
      std::int32_t c = node.child[child];
      if (c < 0) {
        const int level = node.level + 1;
        c = newNode(level);  // may reallocate nodes_: `node` is not used after this
        nodes_[static_cast<std::size_t>(n)].child[child] = c;
      }
      n = c;
    }
    while (leaves_ > colours_) reduce();
  }

  void palette(Palette& p) const { collect(root_, p); }

 private:
  struct Node {
    std::int32_t child[8] = {-1, -1, -1, -1, -1, -1, -1, -1};
    std::uint64_t count = 0;
    std::uint64_t sum[3] = {0, 0, 0};
    std::uint64_t order = 0;  // creation order, for ties
    int level = 0;
    bool leaf = false;
  };

  std::int32_t newNode(int level) {
    std::int32_t id;
    if (!free_.empty()) {
      id = free_.back();
      free_.pop_back();
      nodes_[static_cast<std::size_t>(id)] = Node{};
    } else {
      id = static_cast<std::int32_t>(nodes_.size());
      nodes_.emplace_back();
    }
    Node& node = nodes_[static_cast<std::size_t>(id)];
    node.level = level;
    node.order = created_++;
    node.leaf = level == 8;
    if (node.leaf)
      ++leaves_;
    else
      reducible_[static_cast<std::size_t>(level)].push_back(id);
    return id;
  }

  // Merges the children of one inner node of the deepest level that has inner
  // nodes (their children are all leaves) into it: the one with the fewest
  // pixels, the earliest created on a tie (T53).
  void reduce() {
    int level = 7;
    while (reducible_[static_cast<std::size_t>(level)].empty()) --level;
    auto& list = reducible_[static_cast<std::size_t>(level)];
    std::size_t best = 0;
    for (std::size_t i = 1; i < list.size(); ++i) {
      const Node& a = nodes_[static_cast<std::size_t>(list[i])];
      const Node& b = nodes_[static_cast<std::size_t>(list[best])];
      if (a.count < b.count || (a.count == b.count && a.order < b.order)) best = i;
    }
    const std::int32_t id = list[best];
    list.erase(list.begin() + static_cast<std::ptrdiff_t>(best));
    Node& node = nodes_[static_cast<std::size_t>(id)];
    int merged = 0;
    for (std::int32_t& c : node.child) {
      if (c < 0) continue;
      const Node& child = nodes_[static_cast<std::size_t>(c)];
      for (int k = 0; k < 3; ++k) node.sum[k] += child.sum[k];
      free_.push_back(c);
      c = -1;
      ++merged;
    }
    node.leaf = true;
    leaves_ -= merged - 1;
  }

  void collect(std::int32_t n, Palette& p) const {
    const Node& node = nodes_[static_cast<std::size_t>(n)];
    if (node.leaf) {
      if (node.count > 0) p.levels.push_back(levelsOfMean(p, node.sum, node.count));
      return;
    }
    for (std::int32_t c : node.child)
      if (c >= 0) collect(c, p);
  }

  int colours_;
  int leaves_ = 0;
  std::uint64_t created_ = 0;
  std::int32_t root_ = -1;
  std::vector<Node> nodes_;
  std::vector<std::int32_t> free_;
  std::array<std::vector<std::int32_t>, 8> reducible_;
};

// Nearest entries, remembered per colour in a small direct-mapped table (the
// answer is exact: a slot holds the colour it answers for).
class NearestCache {
 public:
  explicit NearestCache(const Palette& p) {
    for (std::size_t i = 0; i < p.levels.size(); ++i) {
      const Colour8 c = p.shown(i);
      r_.push_back(c[0]);
      g_.push_back(c[1]);
      b_.push_back(c[2]);
    }
    slots_.assign(kSlots, Slot{});
  }

  int operator()(int r, int g, int b) {
    const std::uint32_t key = static_cast<std::uint32_t>(r << 16 | g << 8 | b) | 0x1000000u;
    Slot& s = slots_[(key * 2654435761u) >> (32 - kBits)];
    if (s.key != key) {
      s.key = key;
      s.index = static_cast<std::int16_t>(search(r, g, b));
    }
    return s.index;
  }

  int search(int r, int g, int b) const {
    int best = 0, bestD = 1 << 30;
    const std::size_t n = r_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const int dr = r_[i] - r, dg = g_[i] - g, db = b_[i] - b;
      const int d = dr * dr + dg * dg + db * db;
      if (d < bestD) {
        bestD = d;
        best = static_cast<int>(i);
      }
    }
    return best;
  }

  Colour8 shown(int i) const {
    return {static_cast<std::uint8_t>(r_[static_cast<std::size_t>(i)]),
            static_cast<std::uint8_t>(g_[static_cast<std::size_t>(i)]),
            static_cast<std::uint8_t>(b_[static_cast<std::size_t>(i)])};
  }

 private:
  static constexpr int kBits = 16;
  static constexpr std::size_t kSlots = std::size_t{1} << kBits;
  struct Slot {
    std::uint32_t key = 0;
    std::int16_t index = 0;
  };
  std::vector<int> r_, g_, b_;
  std::vector<Slot> slots_;
};

// Bayer's 8 x 8 threshold matrix (values 0..63).
constexpr int kBayer[8][8] = {{0, 32, 8, 40, 2, 34, 10, 42},  {48, 16, 56, 24, 50, 18, 58, 26},
                              {12, 44, 4, 36, 14, 46, 6, 38}, {60, 28, 52, 20, 62, 30, 54, 22},
                              {3, 35, 11, 43, 1, 33, 9, 41},  {51, 19, 59, 27, 49, 17, 57, 25},
                              {15, 47, 7, 39, 13, 45, 5, 37}, {63, 31, 55, 23, 61, 29, 53, 21}};

// The ordered dither's amplitude (T55): the median over the entries of the
// distance from each to the nearest other shown colour, in 8-bit units, the
// largest of the three channel differences (so a grey ramp's step is its
// spread, and a flat grey between two steps dithers to its own mean).
double orderedSpread(const Palette& p) {
  std::vector<double> nearest;
  for (std::size_t i = 0; i < p.levels.size(); ++i) {
    const Colour8 a = p.shown(i);
    double best = -1;
    for (std::size_t j = 0; j < p.levels.size(); ++j) {
      const Colour8 b = p.shown(j);
      const double d =
          std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
      if (d > 0 && (best < 0 || d < best)) best = d;
    }
    if (best > 0) nearest.push_back(best);
  }
  if (nearest.empty()) return 0;
  std::nth_element(nearest.begin(),
                   nearest.begin() + static_cast<std::ptrdiff_t>(nearest.size() / 2),
                   nearest.end());
  return nearest[nearest.size() / 2];
}

int clamp8(double v) {
  return static_cast<int>(std::lround(std::clamp(v, 0.0, 255.0)));
}

}  // namespace

Palette choosePalette(const Image8& image, Method method, int colours, int dacBits) {
  checkSettings(image, colours, dacBits);
  Palette p;
  p.dacBits = dacBits;
  switch (method) {
    case Method::Popularity:
      popularity(image, p, colours);
      break;
    case Method::MedianCut:
      medianCut(image, p, colours);
      break;
    case Method::Octree: {
      Octree tree(colours);
      const std::size_t n = image.rgb.size() / 3;
      for (std::size_t i = 0; i < n; ++i) tree.add(&image.rgb[3 * i]);
      tree.palette(p);
      break;
    }
  }
  if (p.levels.empty()) p.levels.push_back(Levels{0, 0, 0});  // an empty picture
  return p;
}

std::vector<std::uint8_t> mapToPalette(const Image8& image, const Palette& palette, Dither dither) {
  if (palette.levels.empty() || palette.levels.size() > 256)
    throw std::invalid_argument("mapToPalette: the palette must hold 1..256 entries");
  NearestCache nearest(palette);
  const int w = image.width, h = image.height;
  std::vector<std::uint8_t> out(static_cast<std::size_t>(w) * h);
  const auto px = [&](int x, int y, int c) {
    return image.rgb[(static_cast<std::size_t>(y) * w + x) * 3 + c];
  };
  switch (dither) {
    case Dither::None:
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          out[static_cast<std::size_t>(y) * w + x] =
              static_cast<std::uint8_t>(nearest(px(x, y, 0), px(x, y, 1), px(x, y, 2)));
      break;
    case Dither::Ordered: {
      const double spread = orderedSpread(palette);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const double offset = ((kBayer[y & 7][x & 7] + 0.5) / 64.0 - 0.5) * spread;
          out[static_cast<std::size_t>(y) * w + x] = static_cast<std::uint8_t>(
              nearest(clamp8(px(x, y, 0) + offset), clamp8(px(x, y, 1) + offset),
                      clamp8(px(x, y, 2) + offset)));
        }
      break;
    }
    case Dither::FloydSteinberg: {
      // Floyd and Steinberg (1976): rows left to right, 7/16 ahead, 3/16,
      // 5/16, 1/16 below (T56). Errors against the shown colour.
      std::vector<double> here(static_cast<std::size_t>(w + 2) * 3, 0.0);
      std::vector<double> below(here.size(), 0.0);
      for (int y = 0; y < h; ++y) {
        std::fill(below.begin(), below.end(), 0.0);
        for (int x = 0; x < w; ++x) {
          double v[3];
          int q[3];
          for (int c = 0; c < 3; ++c) {
            v[c] =
                std::clamp(px(x, y, c) + here[static_cast<std::size_t>(x + 1) * 3 + c], 0.0, 255.0);
            q[c] = clamp8(v[c]);
          }
          const int i = nearest(q[0], q[1], q[2]);
          out[static_cast<std::size_t>(y) * w + x] = static_cast<std::uint8_t>(i);
          const Colour8 s = nearest.shown(i);
          for (int c = 0; c < 3; ++c) {
            const double e = v[c] - s[c];
            here[static_cast<std::size_t>(x + 2) * 3 + c] += e * 7 / 16;
            below[static_cast<std::size_t>(x) * 3 + c] += e * 3 / 16;
            below[static_cast<std::size_t>(x + 1) * 3 + c] += e * 5 / 16;
            below[static_cast<std::size_t>(x + 2) * 3 + c] += e * 1 / 16;
          }
        }
        std::swap(here, below);
      }
      break;
    }
  }
  return out;
}

Result quantize(const Image8& image, const Settings& s) {
  Result r;
  r.palette = choosePalette(image, s.method, s.colours, s.dacBits);
  r.indices = mapToPalette(image, r.palette, s.dither);
  return r;
}

Image8 present(const Result& r, int width, int height) {
  Image8 img{width, height, {}};
  img.rgb.resize(static_cast<std::size_t>(width) * height * 3);
  std::vector<Colour8> shown;
  for (std::size_t i = 0; i < r.palette.levels.size(); ++i) shown.push_back(r.palette.shown(i));
  for (std::size_t i = 0; i < r.indices.size() && i * 3 < img.rgb.size(); ++i)
    for (int c = 0; c < 3; ++c) img.rgb[3 * i + c] = shown[r.indices[i]][c];
  return img;
}

int nearestEntry(const Palette& palette, int r, int g, int b) {
  return NearestCache(palette).search(r, g, b);
}

}  // namespace prime::quantize
