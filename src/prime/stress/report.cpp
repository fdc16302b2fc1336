// Tables and CSV of the stress suite's figures.
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "src/prime/stress/stress.h"

namespace prime::stress {

namespace {

std::string num(std::uint64_t v) {
  return std::to_string(v);
}

std::string sci(double v) {
  if (v == 0) return "0";
  char b[32];
  std::snprintf(b, sizeof b, "%.1e", v);
  return b;
}

std::string pct(std::uint64_t a, std::uint64_t b) {
  if (b == 0) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f%%", 100.0 * static_cast<double>(a) / static_cast<double>(b));
  return buf;
}

struct Column {
  const char* title;
  std::string (*get)(const Figures&);
};

const Column kColumns[] = {
    {"rays", [](const Figures& f) { return num(f.rays); }},
    {"wrong hit/miss", [](const Figures& f) { return num(f.wrongHitMiss); }},
    {"wrong in/out", [](const Figures& f) { return num(f.wrongInOut); }},
    {"wrong surface", [](const Figures& f) { return num(f.wrongSurface); }},
    {"ambiguous",
     [](const Figures& f) {
       return num(f.ambiguousHitMiss + f.ambiguousInOut + f.ambiguousSurface);
     }},
    {"NaN/Inf", [](const Figures& f) { return num(f.nanInf); }},
    {"t rel p99", [](const Figures& f) { return sci(f.tRel.quantile(0.99)); }},
    {"t rel max", [](const Figures& f) { return sci(f.tRel.max); }},
    {"normal p99 (rad)", [](const Figures& f) { return sci(f.normalAngle.quantile(0.99)); }},
    {"normal max", [](const Figures& f) { return sci(f.normalAngle.max); }},
    {"uv p99", [](const Figures& f) { return sci(f.uv.quantile(0.99)); }},
    {"uv max", [](const Figures& f) { return sci(f.uv.max); }},
    {"uv other face", [](const Figures& f) { return num(f.uvFaceChanges); }},
    {"uv NaN", [](const Figures& f) { return num(f.uvNan); }},
    {"self-hits / secondary",
     [](const Figures& f) { return num(f.selfHits) + " / " + num(f.secondary); }},
    {"wrong side", [](const Figures& f) { return num(f.wrongSide); }},
    {"chains complete",
     [](const Figures& f) {
       return f.chains ? num(f.chainsComplete) + " / " + num(f.chains) : std::string("-");
     }},
    {"K7 / K4 / Q3-K30 / E57",
     [](const Figures& f) {
       return num(f.semanticK7) + " / " + num(f.semanticK4) + " / " + num(f.semanticCsg) + " / " +
              num(f.listingErrors);
     }},
    {"ref ld != f128", [](const Figures& f) { return num(f.refDisagree); }},
};

}  // namespace

// Markdown: three tables (decisions; errors; secondary rays, chains and the
// listing's design differences), one row per class, every cell "1991 / modern".
std::string markdownTables(const std::vector<ClassResult>& results) {
  struct Part {
    const char* title;
    std::vector<std::pair<const char*, std::string (*)(const Figures&)>> cols;
  };
  const std::vector<Part> parts{
      {"Decisions (1991 / modern)",
       {{"rays", [](const Figures& f) { return num(f.rays); }},
        {"ref. hits", [](const Figures& f) { return num(f.refHits); }},
        {"wrong hit/miss", [](const Figures& f) { return num(f.wrongHitMiss); }},
        {"wrong in/out", [](const Figures& f) { return num(f.wrongInOut); }},
        {"wrong surface", [](const Figures& f) { return num(f.wrongSurface); }},
        {"within tolerance",
         [](const Figures& f) {
           return num(f.ambiguousHitMiss + f.ambiguousInOut + f.ambiguousSurface);
         }},
        {"NaN/Inf", [](const Figures& f) { return num(f.nanInf); }},
        {"ld != f128", [](const Figures& f) { return num(f.refDisagree); }}}},
      {"Errors where the decisions agree (1991 / modern)",
       {{"compared", [](const Figures& f) { return num(f.compared); }},
        {"t rel. p50", [](const Figures& f) { return sci(f.tRel.quantile(0.5)); }},
        {"t rel. p99", [](const Figures& f) { return sci(f.tRel.quantile(0.99)); }},
        {"t rel. max", [](const Figures& f) { return sci(f.tRel.max); }},
        {"normal p99 (rad)", [](const Figures& f) { return sci(f.normalAngle.quantile(0.99)); }},
        {"normal max", [](const Figures& f) { return sci(f.normalAngle.max); }},
        {"(u,v) p99", [](const Figures& f) { return sci(f.uv.quantile(0.99)); }},
        {"(u,v) max", [](const Figures& f) { return sci(f.uv.max); }},
        {"other face", [](const Figures& f) { return num(f.uvFaceChanges); }},
        {"(u,v) NaN", [](const Figures& f) { return num(f.uvNan); }}}},
      {"Secondary rays, chains, the listing's design (1991 / modern)",
       {{"secondary", [](const Figures& f) { return num(f.secondary); }},
        {"self-hits", [](const Figures& f) { return num(f.selfHits); }},
        {"wrong side", [](const Figures& f) { return num(f.wrongSide); }},
        {"chains complete",
         [](const Figures& f) {
           return f.chains ? num(f.chainsComplete) + " of " + num(f.chains) : std::string("-");
         }},
        {"K7", [](const Figures& f) { return num(f.semanticK7); }},
        {"K4", [](const Figures& f) { return num(f.semanticK4); }},
        {"Q3/K30/K31", [](const Figures& f) { return num(f.semanticCsg); }},
        {"E57", [](const Figures& f) { return num(f.listingErrors); }}}},
  };
  std::string s;
  for (const Part& part : parts) {
    s += std::string("**") + part.title + "**\n\n| class |";
    for (const auto& c : part.cols) s += std::string(" ") + c.first + " |";
    s += "\n|---|";
    for (std::size_t i = 0; i < part.cols.size(); ++i) s += "---|";
    s += "\n";
    for (const ClassResult& r : results) {
      s += "| " + r.name + " |";
      for (const auto& c : part.cols) {
        const std::string a = r.f1991.rays ? c.second(r.f1991) : "-";
        const std::string b = r.modern.rays ? c.second(r.modern) : "-";
        s += " " + a + " / " + b + " |";
      }
      s += "\n";
    }
    s += "\n";
  }
  return s;
}

std::string formatTable(const std::vector<ClassResult>& results, bool markdown) {
  if (markdown) return markdownTables(results);
  std::string s;
  auto row = [&](const std::vector<std::string>& cells) {
    if (markdown) {
      s += "|";
      for (const auto& c : cells) s += " " + c + " |";
      s += "\n";
    } else {
      for (std::size_t i = 0; i < cells.size(); ++i) {
        char b[64];
        std::snprintf(b, sizeof b, i == 0 ? "%-24s" : "%14s", cells[i].c_str());
        s += b;
      }
      s += "\n";
    }
  };
  std::vector<std::string> head{"class / profile"};
  for (const Column& c : kColumns) head.push_back(c.title);
  row(head);
  if (markdown) {
    std::vector<std::string> sep(head.size(), "---");
    row(sep);
  }
  for (const ClassResult& r : results) {
    for (int p = 0; p < 2; ++p) {
      const Figures& f = p == 0 ? r.f1991 : r.modern;
      if (f.rays == 0) continue;
      std::vector<std::string> cells{r.name + (p == 0 ? " 1991" : " modern")};
      for (const Column& c : kColumns) cells.push_back(c.get(f));
      row(cells);
    }
  }
  return s;
}

std::string formatCsv(const std::vector<ClassResult>& results) {
  std::string s =
      "class,profile,rays,refHits,compared,wrongHitMiss,ambiguousHitMiss,wrongInOut,ambiguousInOut,"
      "wrongSurface,ambiguousSurface,nanInf,uvNan,tRelP50,tRelP99,tRelMax,normalP50,normalP99,"
      "normalMax,uvP50,uvP99,uvMax,uvFaceChanges,secondary,selfHits,wrongSide,chains,chainSteps,"
      "chainsComplete,semanticK7,semanticK4,semanticCsg,listingErrors,refDisagree\n";
  for (const ClassResult& r : results) {
    for (int p = 0; p < 2; ++p) {
      const Figures& f = p == 0 ? r.f1991 : r.modern;
      if (f.rays == 0) continue;
      char b[1024];
      std::snprintf(b, sizeof b,
                    "%s,%s,%llu,%llu,%llu,%llu,%llu,%llu,%llu,%llu,%llu,%llu,%llu,%.3g,%.3g,%.3g,%."
                    "3g,%.3g,%.3g,%.3g,"
                    "%.3g,%.3g,%llu,%llu,%llu,%llu,%llu,%llu,%llu,%llu,%llu,%llu,%llu,%llu\n",
                    r.name.c_str(), p == 0 ? "1991" : "modern", (unsigned long long)f.rays,
                    (unsigned long long)f.refHits, (unsigned long long)f.compared,
                    (unsigned long long)f.wrongHitMiss, (unsigned long long)f.ambiguousHitMiss,
                    (unsigned long long)f.wrongInOut, (unsigned long long)f.ambiguousInOut,
                    (unsigned long long)f.wrongSurface, (unsigned long long)f.ambiguousSurface,
                    (unsigned long long)f.nanInf, (unsigned long long)f.uvNan, f.tRel.quantile(0.5),
                    f.tRel.quantile(0.99), f.tRel.max, f.normalAngle.quantile(0.5),
                    f.normalAngle.quantile(0.99), f.normalAngle.max, f.uv.quantile(0.5),
                    f.uv.quantile(0.99), f.uv.max, (unsigned long long)f.uvFaceChanges,
                    (unsigned long long)f.secondary, (unsigned long long)f.selfHits,
                    (unsigned long long)f.wrongSide, (unsigned long long)f.chains,
                    (unsigned long long)f.chainSteps, (unsigned long long)f.chainsComplete,
                    (unsigned long long)f.semanticK7, (unsigned long long)f.semanticK4,
                    (unsigned long long)f.semanticCsg, (unsigned long long)f.listingErrors,
                    (unsigned long long)f.refDisagree);
      s += b;
    }
  }
  return s;
}

std::string formatStability(const std::vector<StabilityRow>& rows, bool markdown) {
  std::string s;
  if (markdown)
    s += "| scene | transform | pixels | changed 1991 | of which colour > 0.01 | changed modern | "
         "of which "
         "colour > 0.01 | NaN colours 1991 | NaN colours modern "
         "|\n|---|---|---|---|---|---|---|---|---|\n";
  for (const StabilityRow& r : rows) {
    if (markdown) {
      s += "| " + r.scene + " | " + r.transform + " | " + num(r.pixels) + " | " +
           pct(r.changed1991, r.pixels) + " | " + pct(r.big1991, r.pixels) + " | " +
           pct(r.changedModern, r.pixels) + " | " + pct(r.bigModern, r.pixels) + " | " +
           num(r.nan1991) + " | " + num(r.nanModern) + " |\n";
    } else {
      char b[320];
      std::snprintf(
          b, sizeof b,
          "%-16s %-14s %8llu pixels  1991 %9s (%9s big)  modern %9s (%9s big)  NaN %llu / %llu\n",
          r.scene.c_str(), r.transform.c_str(), static_cast<unsigned long long>(r.pixels),
          pct(r.changed1991, r.pixels).c_str(), pct(r.big1991, r.pixels).c_str(),
          pct(r.changedModern, r.pixels).c_str(), pct(r.bigModern, r.pixels).c_str(),
          static_cast<unsigned long long>(r.nan1991), static_cast<unsigned long long>(r.nanModern));
      s += b;
    }
  }
  return s;
}

}  // namespace prime::stress
