// A 1991 disk's Model.c read as the scene's calls (legacy_io/prime/model_c.h,
// M42), and the text rule every text input follows (M41: ^Z ends the text,
// a leading byte order mark is skipped).
#include "legacy_io/prime/model_c.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"
#include "legacy_io/prime/text_inputs.h"
#include "tests/support/error_message.h"

namespace prime::io {
namespace {

using ::testing::HasSubstr;

using test::messageOf;

// The listing's Model.c (module Model), as the appendix prints it, with the
// calls of a two-object scene.
const char* kListingStyle = R"(/*****
/* Module: Model
/* Main module for the modelling of objects in the scene.
/*****/
#include <stdio.h>
#include "define.h"
extern void InitFiles(void),
          OpenFiles(void),
          CloseFiles(void),
          AddObj(char *fileName),
          AddToObjList(int num),
          CopyObj(char *srcObj, char *destObj, char *copyFile),
          AddMap(char *mapFile),
          FreeAll(void),
          Error(char *msg),
          Message(char *msg);
extern int MemoryEmpty(void);

void main(void);

void main(void)
/* Model the scene to be ray traced. */
{
  Message("Initialising Files");
  InitFiles();
  OpenFiles();
  Message("Building model of scene");
  AddObj("d1.txt");
  AddToObjList(1);
  CopyObj("d1.txt", "d2.txt", "c1.txt"); // a copy
  AddToObjList(0x2);
  Message("Adding model texture");
  AddMap("Map1.txt");
  CloseFiles();
  if (!MemoryEmpty())
  {
    FreeAll();
    Error("main(): Number of Mallocs != Number of Frees");
  }
}
)";

TEST(ModelC, ReadsTheCallsOfMainInOrderAndPassesOverItsHousekeeping) {
  const auto calls = parseModelC(kListingStyle, "D/Model.c");
  ASSERT_EQ(calls.size(), 5u);
  EXPECT_EQ(calls[0].name, "AddObj");
  EXPECT_EQ(calls[0].args, (std::vector<std::string>{"d1.txt"}));
  EXPECT_EQ(calls[0].line, 28);
  EXPECT_EQ(calls[1].name, "AddToObjList");
  EXPECT_EQ(calls[1].args, (std::vector<std::string>{"1"}));
  EXPECT_EQ(calls[2].args, (std::vector<std::string>{"d1.txt", "d2.txt", "c1.txt"}));
  EXPECT_EQ(calls[3].args, (std::vector<std::string>{"2"}));  // 0x2, as C reads it
  EXPECT_EQ(calls[4].name, "AddMap");
  EXPECT_EQ(calls[4].line, 33);
}

TEST(ModelC, CrLfAndADosEndOfFileReadTheSame) {
  std::string dos;
  for (const char* p = kListingStyle; *p; ++p) {
    if (*p == '\n') dos += '\r';
    dos += *p;
  }
  dos += "\x1A";
  dos += "garbage after DOS's end of file";
  const auto calls = parseModelC("\xEF\xBB\xBF" + dos, "D/MODEL.C");
  ASSERT_EQ(calls.size(), 5u);
  EXPECT_EQ(calls[4].line, 33);
}

TEST(ModelC, RefusesAnythingElseInMainNamingTheLineAndWhatItFound) {
  EXPECT_THAT(messageOf([] {
                parseModelC("void main(void)\n{\n  int i;\n  AddObj(\"d1.txt\");\n}\n", "Model.c");
              }),
              HasSubstr("Model.c:3: statement of main(): expected a call of AddObj"));
  EXPECT_THAT(messageOf([] {
                parseModelC("void main(void)\n{\n  for (;;) AddObj(\"d1.txt\");\n}\n", "Model.c");
              }),
              HasSubstr("Model.c:3"));
  EXPECT_THAT(messageOf([] { parseModelC("void main(void)\n{\n  AddObj(name);\n}\n", "Model.c"); }),
              HasSubstr("Model.c:3: AddObj argument 1: expected a string literal"));
  EXPECT_THAT(
      messageOf([] { parseModelC("void main(void)\n{\n  AddToObjList(\"1\");\n}\n", "Model.c"); }),
      HasSubstr("expected an integer literal, found the string \"1\""));
  EXPECT_THAT(messageOf([] {
                parseModelC("void main(void)\n{\n  CopyObj(\"a\", \"b\");\n}\n", "Model.c");
              }),
              HasSubstr("CopyObj arguments: expected \",\""));
  EXPECT_THAT(messageOf([] { parseModelC("void main(void)\n{\n  Render();\n}\n", "Model.c"); }),
              HasSubstr("found \"Render\""));
  // A scene call inside the MemoryEmpty check is not the listing's.
  EXPECT_THAT(messageOf([] {
                parseModelC("void main(void) {\n if (!MemoryEmpty()) {\n AddMap(\"m\");\n }\n}\n",
                            "Model.c");
              }),
              HasSubstr("Model.c:3: statement of main()'s MemoryEmpty check"));
  // No definition of main(), only its prototype.
  EXPECT_THAT(messageOf([] { parseModelC("void main(void);\n", "Model.c"); }),
              HasSubstr("Model.c:2: main(): expected the definition of main()"));
  // Found by the fuzzer (text_inputs, reader C): an error without a line.
  EXPECT_THAT(messageOf([] { parseModelC("0.5\n0,5\n0.\x15\n", "Model.c"); }),
              HasSubstr("Model.c:4: main()"));
  EXPECT_THAT(
      messageOf([] { parseModelC("void main(void)\n{\n  AddObj(\"d1.txt\");\n", "Model.c"); }),
      HasSubstr("found the end of the file"));
  EXPECT_THAT(messageOf([] { parseModelC("/* never closed\nvoid main(void) {}\n", "Model.c"); }),
              HasSubstr("Model.c:1: comment: expected */"));
  EXPECT_THAT(
      messageOf([] { parseModelC("void main(void) {\nAddObj(\"d1.txt);\n}\n", "Model.c"); }),
      HasSubstr("Model.c:2: string"));
  EXPECT_THAT(messageOf([] { parseModelC("void main(void) {\nAddToObjList(40000);\n}\n", "M.c"); }),
              HasSubstr("at most 32767"));
}

TEST(ModelC, ControlBytesInWhatItFoundAreEscaped) {
  const std::string m =
      messageOf([] { parseModelC(std::string("void main(void) {\n\x01x();\n}\n"), "Model.c"); });
  EXPECT_THAT(m, HasSubstr("\\x01"));
  EXPECT_EQ(m.find('\x01'), std::string::npos);
}

TEST(TextRule, ADosEndOfFileEndsAnyText) {
  std::string t = "AddObj d1.txt\r\n\x1A\x1A junk";
  endAtDosEof(t);
  EXPECT_EQ(t, "AddObj d1.txt\r\n");
  std::string none = "no end";
  endAtDosEof(none);
  EXPECT_EQ(none, "no end");
  EXPECT_EQ(bomLength("\xEF\xBB\xBF"
                      "AddObj"),
            3u);
  EXPECT_EQ(bomLength("\xEF\xBB"), 0u);
}

TEST(TextRule, ModelTxtSkipsAByteOrderMarkAndStopsAtADosEndOfFile) {
  const auto calls = parseModelText(
      "\xEF\xBB\xBF"
      "AddObj d1.txt\r\nAddToObjList 1\r\n\x1A",
      "MODEL.TXT");
  ASSERT_EQ(calls.size(), 2u);
  EXPECT_EQ(calls[0].name, "AddObj");
  EXPECT_EQ(calls[1].line, 2);
  // A control byte where a call should be is shown escaped.
  const std::string m = messageOf([] { parseModelText("AddObj d1.txt\n\x02Oops\n", "Model.txt"); });
  EXPECT_THAT(m, HasSubstr("Model.txt:2: call: expected one of AddObj"));
  EXPECT_THAT(m, HasSubstr("\\x02Oops"));
}

}  // namespace
}  // namespace prime::io
