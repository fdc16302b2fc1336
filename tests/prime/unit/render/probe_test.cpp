// The probe's typed events: each keeps its one-line text and the same as a
// JSON object, built by JsonObject (keys and strings escaped).
#include "src/prime/render/probe.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace prime {
namespace {

TEST(JsonObject, FieldsInOrderWithEscapedStrings) {
  EXPECT_EQ(JsonObject().str(), "{}");
  EXPECT_EQ(JsonObject()
                .add("n", 3)
                .add("ok", false)
                .add("x", 0.5)
                .add("v", Vec3{1, 2, 3})
                .add("type", 's')
                .add("name", "a \"b\"\\c\n")
                .addJson("list", "[]")
                .str(),
            R"({"n":3,"ok":false,"x":0.5,"v":[1,2,3],"type":"s","name":"a \"b\"\\c\n","list":[]})");
  EXPECT_EQ(JsonObject().add("nan", std::nan("")).add("inf", -HUGE_VAL).str(),
            R"({"nan":"NaN","inf":"-Inf"})");
  EXPECT_EQ(jsonString(std::string_view("\x01", 1)), R"("\u0001")");
}

TEST(Probe, EventsKeepTextAndJson) {
  Probe probe;
  probe.ray(1, RayKind::Reflected, Ray{{0, 0, 0}, {0, 0, 1}});
  probe.boundTest(1, 2, io::PrimType::Sphere, 4, false);
  probe.primitive(1, 2, 3, io::PrimType::Cube, std::nullopt);
  probe.miss(1, {0, 0, 0});
  ASSERT_EQ(probe.events.size(), 4u);
  EXPECT_EQ(probe.events[0].kind, "ray");
  EXPECT_EQ(probe.events[0].text, "reflected ray, depth 1: from (0, 0, 0) dir (0, 0, 1)");
  EXPECT_EQ(probe.events[0].json,
            R"({"kind":"reflected","depth":1,"origin":[0,0,0],"dir":[0,0,1]})");
  EXPECT_EQ(probe.events[1].text, "object 2: bounding sphere (prim 4) missed: object skipped");
  EXPECT_EQ(probe.events[1].json, R"({"object":2,"boundPrim":4,"hit":false})");
  EXPECT_EQ(probe.events[2].text, "object 2 prim 3 (cube): miss");
  EXPECT_EQ(probe.events[2].json, R"({"object":2,"prim":3,"type":"B","hit":false})");
  EXPECT_EQ(probe.events[3].json, "{}");
}

}  // namespace
}  // namespace prime
