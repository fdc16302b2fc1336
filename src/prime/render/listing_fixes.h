// Per-quirk switches on top of the 1991 profile (`--fix ID[,ID...]`): each
// corrects one K quirk of docs/prime/listing-errata.md and nothing else, so a
// class can see what one mistake of the 1991 program does. The 1991 profile
// without --fix is the listing, byte for byte. `prime errata` lists every K
// id with what it does, whether it has a switch, and where it shows.
#pragma once
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace prime {

struct ListingFixes {
  // K4: normals by the inverse transpose of the primitive's matrix, not by
  // the matrix itself (right under non-uniform scale).
  bool k4 = false;
  // K5: the exit normal of a transmitted ray in the world frame (the inverse
  // transpose of the exit primitive's matrix) and normalised, in the TIR loop
  // and the refraction out; the listing uses it as the primitive routine
  // returned it. Its direction stays K6's.
  bool k5 = false;
  // K10: Hall's l points from the surface to the light and v from the
  // surface to the eye (lit faces get N.L > 0, N.H > 0).
  bool k10 = false;
  // K15: ProcessColor also clamps negative colours to 0 (the listing clamps
  // only values >= 1).
  bool k15 = false;
  // K18: the reflected ray starts at the hit point, not one world unit along
  // its direction.
  bool k18 = false;
  bool any() const { return k4 || k5 || k10 || k15 || k18; }
};

// One K quirk as `prime errata` shows it.
struct ListingQuirk {
  const char* id;       // "K18"
  const char* where;    // the listing's file and function
  const char* summary;  // what the 1991 program does, one line
  // The correction `--fix ID` applies; nullptr when there is no switch.
  const char* fix;
  // Why there is no switch (nullptr when there is one).
  const char* noSwitch;
  // The shipped scenes whose 1991 picture the switch changes (measured:
  // tests/prime/e2e/check_fixes.py checks it); "" when it changes none.
  const char* shows;
};

// Every K quirk, K1 first.
std::span<const ListingQuirk> listingQuirks();

// The fixes `--fix` names: ids separated by commas ("K18,K10"), case as
// written or lower case, "all" for every switch. Throws std::invalid_argument
// naming the id for an unknown id or one without a switch (and why).
ListingFixes parseListingFixes(std::string_view text);
// The ids of the switches set, in K order ("K10,K18"); "" for none.
std::string fixIds(const ListingFixes& fixes);

}  // namespace prime
