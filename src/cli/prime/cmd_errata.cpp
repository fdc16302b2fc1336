// prime errata: every K quirk of the PRIME listing (docs/prime/listing-
// errata.md, section B), one line each on what the 1991 program does, with
// the correction `--fix ID` applies on top of the 1991 profile or why there
// is none, and the shipped scenes whose picture the switch changes.
#include <iostream>

#include "src/cli/commands.h"
#include "src/prime/render/listing_fixes.h"
#include "src/render/probe_log.h"

namespace prime::cli {

void addErrataCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "errata",
      "List the PRIME listing's quirks (K ids), which --fix ID corrects, where each shows");
  auto json = std::make_shared<bool>(false);
  auto switches = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json,
                "Print one JSON array of {id, where, summary, fix, noSwitch, shows}");
  cmd->add_flag("--switches", *switches, "Only the quirks --fix can switch off");
  cmd->callback([=, &action] {
    action = [=] {
      if (*json) {
        std::string out = "[";
        bool first = true;
        for (const ListingQuirk& q : listingQuirks()) {
          if (*switches && q.fix == nullptr) continue;
          JsonObject o;
          o.add("id", q.id).add("where", q.where).add("summary", q.summary);
          o.add("fix", q.fix ? q.fix : "").add("noSwitch", q.noSwitch ? q.noSwitch : "");
          o.add("shows", q.shows);
          out += (first ? "\n  " : ",\n  ") + o.str();
          first = false;
        }
        std::cout << out << "\n]\n";
        return 0;
      }
      std::cout << "The PRIME listing's quirks (docs/prime/listing-errata.md, section B). The 1991 "
                   "profile keeps them all;\n--fix ID[,ID...] corrects the ones with a switch on "
                   "top of it (prime trace DIR --fix K18).\n\n";
      for (const ListingQuirk& q : listingQuirks()) {
        if (*switches && q.fix == nullptr) continue;
        std::cout << q.id << (q.id[2] ? "  " : "   ") << q.summary << "  [" << q.where << "]\n";
        if (q.fix != nullptr)
          std::cout << "      --fix " << q.id << ": " << q.fix << "; shows in "
                    << (*q.shows ? q.shows : "no shipped scene") << "\n";
        else
          std::cout << "      no switch: " << q.noSwitch << "\n";
      }
      return 0;
    };
  });
}

}  // namespace prime::cli
