// ParseShaderTest and JunitXml: the sections of a .shader_test and the report CI reads (no GL).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "arbiter/runtime/shader_test.h"

namespace arbiter::runtime {
namespace {

TEST(ShaderTestParseTest, SplitsSectionsWithTheirLineNumbers) {
  const char* text =
      "# a comment before the first section, as piglit allows\n"
      "[require]\n"
      "GL >= 1.3\n"
      "\n"
      "# requirement comment\n"
      "GL_ARB_fragment_program\n"
      "[vertex program]\n"
      "!!ARBvp1.0\n"
      "MOV result.position, vertex.position;\n"
      "END\n"
      "[fragment shader]\n"
      "void main() { gl_FragColor = vec4(1.0); }\n"
      "[fragment shader]\n"
      "void f() {}\r\n"
      "[vertex data]\n"
      "vertex/float/2\n"
      "0 0\n"
      "[test]\n"
      "  draw rect -1 -1 2 2\n"
      "# a comment\n"
      "probe all rgba 1 1 1 1\n";
  ShaderTest test;
  std::string error;
  int line = 0;
  ASSERT_TRUE(ParseShaderTest(text, "t.shader_test", &test, &line, &error)) << error;
  ASSERT_EQ(test.require.size(), 2u);
  EXPECT_EQ(test.require[0].line, 3);
  EXPECT_EQ(test.require[1].text, "GL_ARB_fragment_program");
  EXPECT_EQ(test.vertex_program.line, 7);
  EXPECT_EQ(test.vertex_program.text, "!!ARBvp1.0\nMOV result.position, vertex.position;\nEND\n");
  EXPECT_EQ(test.fragment_program.line, 0);
  ASSERT_EQ(test.fragment_shaders.size(), 2u);  // a stage may have several shaders
  EXPECT_EQ(test.fragment_shaders[1].line, 13);
  EXPECT_EQ(test.fragment_shaders[1].text, "void f() {}\n");  // CR LF ends a line
  ASSERT_EQ(test.vertex_data.size(), 2u);
  ASSERT_EQ(test.commands.size(), 2u);
  EXPECT_EQ(test.commands[0].line, 19);
  EXPECT_EQ(test.commands[0].text, "draw rect -1 -1 2 2");
  EXPECT_EQ(test.commands[1].line, 21);
}

TEST(ShaderTestParseTest, RejectsUnknownAndRepeatedSections) {
  ShaderTest test;
  std::string error;
  int line = 0;
  EXPECT_FALSE(ParseShaderTest("[require]\n[geometry shader]\n", "t", &test, &line, &error));
  EXPECT_EQ(line, 2);
  EXPECT_EQ(error, "unknown section [geometry shader]");
  EXPECT_FALSE(ParseShaderTest("[test]\nclear\n[test]\n", "t", &test, &line, &error));
  EXPECT_EQ(line, 3);
  EXPECT_EQ(error, "section [test] appears twice");
  EXPECT_FALSE(ParseShaderTest("[vertex shader passthrough]\n[vertex shader]\nx\n", "t", &test,
                               &line, &error));
  EXPECT_EQ(line, 1);
  EXPECT_EQ(error, "[vertex shader passthrough] and [vertex shader] together");
  EXPECT_FALSE(
      ParseShaderTest("[vertex shader passthrough]\nvoid main() {}\n", "t", &test, &line, &error));
  EXPECT_EQ(line, 2);
  EXPECT_EQ(error, "[vertex shader passthrough] takes no text");
}

// A file with no section is no shader test, and one with only [require] has nothing to run:
// both fail (piglit's shader_runner passes them; issue 22).
TEST(ShaderTestParseTest, AFileWithoutSectionsOrWorkIsRefused) {
  ShaderTest test;
  std::string error;
  int line = 0;
  EXPECT_FALSE(ParseShaderTest("", "t", &test, &line, &error));
  EXPECT_EQ(line, 1);
  EXPECT_THAT(error, ::testing::HasSubstr("not a shader test"));
  EXPECT_FALSE(
      ParseShaderTest("\x7f"
                      "ELF\x02\x01\n binary",
                      "t", &test, &line, &error));
  EXPECT_THAT(error, ::testing::HasSubstr("not a shader test"));
  EXPECT_FALSE(ParseShaderTest("[require]\nGL >= 2.0\n", "t", &test, &line, &error));
  EXPECT_THAT(error, ::testing::HasSubstr("nothing to run"));
  // Shaders without [test] commands: piglit's link-only tests, accepted.
  EXPECT_TRUE(ParseShaderTest("[vertex program]\n!!ARBvp1.0\nEND\n", "t", &test, &line, &error));
  EXPECT_TRUE(test.commands.empty());
  EXPECT_TRUE(ParseShaderTest("[test]\nclear\n", "t", &test, &line, &error));
}

TEST(ShaderTestJunitTest, CountsAndEscapes) {
  std::vector<ShaderTestResult> results(3);
  results[0].path = "dir/a.shader_test";
  results[0].status = TestStatus::Pass;
  results[1].path = "dir/b.shader_test";
  results[1].status = TestStatus::Fail;
  results[1].message = "b.shader_test:3: probe <rgba> failed\n  Expected: 1 & 0";
  results[1].diagnostics = {"mesa: error"};
  results[2].path = "c.shader_test";
  results[2].status = TestStatus::Skip;
  results[2].message = "requires \"GL_X\"";
  EXPECT_EQ(JunitXml(results, "arbiter run"),
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<testsuites tests=\"3\" failures=\"1\" skipped=\"1\">\n"
            "  <testsuite name=\"arbiter run\" tests=\"3\" failures=\"1\" skipped=\"1\">\n"
            "    <testcase classname=\"dir\" name=\"a.shader_test\"/>\n"
            "    <testcase classname=\"dir\" name=\"b.shader_test\">\n"
            "      <failure message=\"b.shader_test:3: probe &lt;rgba&gt; failed\">"
            "b.shader_test:3: probe &lt;rgba&gt; failed\n  Expected: 1 &amp; 0\nmesa: error"
            "</failure>\n"
            "    </testcase>\n"
            "    <testcase classname=\".\" name=\"c.shader_test\">\n"
            "      <skipped message=\"requires &quot;GL_X&quot;\"/>\n"
            "    </testcase>\n"
            "  </testsuite>\n</testsuites>\n");
}

}  // namespace
}  // namespace arbiter::runtime
