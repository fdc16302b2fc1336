#include "src/prime/render/listing_fixes.h"

#include <cctype>
#include <stdexcept>
#include <utility>

namespace prime {

namespace {

// Why a quirk has no switch, in the few words `prime errata` has room for.
constexpr const char* kModelled = "made when the scene is modelled: the databases hold it";
constexpr const char* kReading = "how the files are read: the scene would not load otherwise";
constexpr const char* kNoPixels = "changes no pixel";
constexpr const char* kTangled =
    "K6, K7, K8 and K19 are tangled: no correction of one alone renders";

constexpr ListingQuirk kQuirks[] = {
    {"K1", "Transfrm.c: Scale", "only the diagonal is scaled: copied objects keep unscaled terms",
     nullptr, kModelled, ""},
    {"K2", "Transfrm.c: Transform", "the pivot is in unscaled local units and ends at t", nullptr,
     kModelled, ""},
    {"K3", "Transfrm.c: RotateX/Y/Z", "degrees by Radient = 57.29578: no rotation is exact",
     nullptr, kModelled, ""},
    {"K4", "Rays.c: CastRay", "normals by the forward matrix: wrong under non-uniform scale",
     "normals by the inverse transpose of the primitive's matrix", nullptr,
     "copies, inside-maps, map-edge, plate2, plate2-thesis, primitives"},
    {"K5", "Rays.c: TransmittedRay", "the exit normal is used in local coordinates, unnormalised",
     "the exit normal in world coordinates, normalised (its direction stays K6's)", nullptr,
     "default, glass"},
    {"K6", "Intersect.c: Swap", "an exit normal points in or out by the order faces are tested",
     nullptr, kTangled, ""},
    {"K7", "Intersect.c: IntersectSphere, Swap", "a ray that starts inside a primitive misses it",
     nullptr, kTangled, ""},
    {"K8", "Bound.c: BoundSphere", "a secondary ray starting inside a bounding sphere skips it",
     nullptr, kTangled, ""},
    {"K9", "Rays.c: CastRay; Hall.c", "no shadow rays: no object shadows another", nullptr,
     "the thesis profile casts them (--profile thesis)", ""},
    {"K10", "Hall.c: ProcessWavelength", "l and v point the wrong way: lit faces get darker",
     "l from the surface to the light, v from the surface to the eye", nullptr,
     "copies, csg-operators, default, glass, inside-maps, lights, map-edge, plate2, "
     "plate2-thesis, plate3, plate3-thesis, primitives"},
    {"K11", "Hall.c: ProcessWavelength", "the texture colour enters only through FSR and FST",
     nullptr, "the thesis' own formula (Table 4.1): no single correction", ""},
    {"K12", "Hall.c: FSR, FST", "f90 = 0 makes tmp = 1 - cos; FST = 1 - FSR may be negative",
     nullptr, "the thesis' own formula: no single correction", ""},
    {"K13", "Hall.c: Hj_", "divides by indx - 1: indx = 1 gives Inf/NaN", nullptr,
     "no scene may use indx = 1; nothing to correct in the others", ""},
    {"K14", "Hall.c: ProcessWavelength", "transmissivity pow(tT, sT) over world units", nullptr,
     "the thesis' own formula", ""},
    {"K15", "Hall.c: ProcessColor", "negative colours are not clamped (only >= 1 is)",
     "negative colours clamped to 0", nullptr,
     "copies, csg-operators, default, inside-maps, lights, plate2, plate2-thesis, primitives"},
    {"K16", "Graph.c: ColorNum", "levels 0..6, 0..6, 0..2 and black drawn as index 1", nullptr,
     "the palette's, not the tracer's: prime export --palette shows others", ""},
    {"K17", "Graph.c: InitPalette", "entries 0-9 and 20 overwritten: the background is green",
     nullptr, "the palette's, not the tracer's: prime export --palette shows others", ""},
    {"K18", "Rays.c: ReflectedRay", "the reflected ray starts one world unit along it",
     "the reflected ray starts at the hit point", nullptr,
     "copies, csg-operators, default, inside-maps, map-edge, plate2, plate3, plate3-thesis, "
     "primitives"},
    {"K19", "Rays.c: TransmittedRay", "transmitted rays step one unit back, then one on", nullptr,
     kTangled, ""},
    {"K20", "Rays.c: CastRay", "depth++ < MaxDepth: six levels, reflected and transmitted rays",
     nullptr, "--max-depth sets the depth; the rest is the listing's design", ""},
    {"K21", "RayTrace.c: main", "350 x 769 rays on a 1000 x 1000 window: pixels 2.2:1", nullptr,
     "the camera flags give a free camera (--size, --frame-listing-window)", ""},
    {"K22", "RayTrace.c: main", "graph_scr's header says 349 x 768 for 350 x 769 pixels", nullptr,
     "the file format", ""},
    {"K23", "RayTrace.c: main", "wStepDown from the window's top only", nullptr,
     "right for the listing's window; --window-left moves it", ""},
    {"K24", "MathFunc.c: Roundoff", "snaps to integers within 1e-10 (1e-9 below zero)", nullptr,
     "used everywhere: no single correction", ""},
    {"K25", "TextureMp.c: ReadMap", "u = 1 reads the next row's first texel", nullptr,
     "a texture's edge is the map file's", ""},
    {"K26", "TextureMp.c: GetUVSphere", "the pole on +z: a mirrored dartboard facing the eye",
     nullptr, "no mapping is the right one: the listing's is the plates'", ""},
    {"K27", "TextureMp.c: GetUVCube", "an edge belongs to the first face tested", nullptr,
     "no mapping is the right one", ""},
    {"K28", "TextureMp.c: GetUVCylinder, GetUVCone", "NaN at a cap's centre; the cone uses x/z",
     nullptr, "no mapping is the right one", ""},
    {"K29", "CSG.c: CSG", "tList is never NULL: the right subtree is always evaluated", nullptr,
     "--skip-empty-right is Q4's other reading", ""},
    {"K30", "CSG.c: Union, Difference, Intersection", "unsorted lists; the first node wins",
     nullptr, "the modern profile's set operations (--profile modern)", ""},
    {"K31", "CSG.c: Difference", "A's front face shaded with B's normal", nullptr,
     "the modern profile's set operations (--profile modern)", ""},
    {"K32", "Obj.c: AddObj", "\"NULL\" overruns opCode[4] by one byte", nullptr, kNoPixels, ""},
    {"K33", "Obj.c: AddObj; Prim.c: CopyPrim", "'O' entries copy no primitive type", nullptr,
     "made when the scene is modelled: prime model --copy-type-from-source corrects it", ""},
    {"K34", "Prim.c: AddPrim", "unused map slots are heap garbage in PrimFile", nullptr, kNoPixels,
     ""},
    {"K35", "Obj.c: AddObj", "a leaf is two tokens, B 1, not B1", nullptr, kReading, ""},
    {"K36", "Prim.c: AddPrim; Bound.c", "the type letter must be byte 0", nullptr, kReading, ""},
    {"K37", "Prim.c: NewPrimNum", "16-bit primitive numbers: 113 per scene (0..112, M3)", nullptr,
     "made when the scene is modelled: prime model --no-16bit-limit lifts it", ""},
    {"K38", "Memory.c: Malloc, Free", "500 live blocks at most", nullptr, kNoPixels, ""},
    {"K39", "User_IO.c: KBEEmpty", "tests PF, not ZF", nullptr, kNoPixels, ""},
    {"K40", "Lighting.c: InitLighting", "the light file is never closed; light[10] unchecked",
     nullptr, kNoPixels, ""},
    {"K41", "Intersect.c: IntersectRayPlane", "Roundoff snaps tiny dot products to 0", nullptr,
     "used with K24's: no single correction", ""},
    {"K42", "Matrix.c: Inverse", "Gauss-Jordan without pivoting", nullptr, kModelled, ""},
    {"K43", "Intersect.c: IntersectCone", "no cap at the apex; the range test repeated", nullptr,
     "a cone has no cap to add", ""},
    {"K44", "User_IO.c: Error", "waits for Esc, then exit(1)", nullptr, kNoPixels, ""},
};

// Each switch's id and flag, in K order: what parse, "all" and fixIds walk.
constexpr std::pair<const char*, bool ListingFixes::*> kSwitches[] = {{"K4", &ListingFixes::k4},
                                                                      {"K5", &ListingFixes::k5},
                                                                      {"K10", &ListingFixes::k10},
                                                                      {"K15", &ListingFixes::k15},
                                                                      {"K18", &ListingFixes::k18}};

// The ids --fix takes, for its error messages.
std::string switchesText() {
  std::string s = "--fix takes ";
  for (const auto& [name, flag] : kSwitches) s += std::string(name) + ", ";
  return s + "or all; prime errata lists every quirk";
}

std::string upper(std::string_view s) {
  std::string out;
  for (const char c : s) out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

std::span<const ListingQuirk> listingQuirks() {
  return kQuirks;
}

ListingFixes parseListingFixes(std::string_view text) {
  ListingFixes f;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(',', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string id = upper(text.substr(start, end - start));
    start = end + 1;
    if (id == "ALL") {
      for (const auto& [name, flag] : kSwitches) f.*flag = true;
      continue;
    }
    const ListingQuirk* q = nullptr;
    for (const ListingQuirk& k : kQuirks)
      if (id == k.id) q = &k;
    if (q == nullptr)
      throw std::invalid_argument("'" + id + "' is no listing quirk (K1 .. K44); " +
                                  switchesText());
    if (q->fix == nullptr)
      throw std::invalid_argument(id + " has no switch: " + q->noSwitch + "; " + switchesText());
    for (const auto& [name, flag] : kSwitches)
      if (id == name) f.*flag = true;
  }
  return f;
}

std::string fixIds(const ListingFixes& f) {
  std::string s;
  for (const auto& [name, flag] : kSwitches)
    if (f.*flag) s += (s.empty() ? "" : ",") + std::string(name);
  return s;
}

}  // namespace prime
