// Unit tests of the OSMesa context: creation, driver validation, GLSL verdicts, ARB loading.
#include "arbiter/runtime/mesa.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <thread>

namespace arbiter::runtime {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

// One softpipe context for the whole test program (OSMesa keeps its driver per process).
MesaContext& Mesa() {
  static std::unique_ptr<MesaContext> context = [] {
    std::string error;
    std::unique_ptr<MesaContext> created = CreateMesaContext(MesaOptions{}, &error);
    EXPECT_NE(created, nullptr) << error;
    return created;
  }();
  if (context == nullptr) std::abort();
  return *context;
}

TEST(MesaContextTest, CreatesSoftpipeCompatibilityContext) {
  MesaContext& mesa = Mesa();
  EXPECT_EQ(mesa.driver(), "softpipe");
  EXPECT_THAT(mesa.description(), StartsWith("softpipe, "));
  EXPECT_THAT(mesa.description(), HasSubstr("Compatibility Profile"));
  const std::vector<std::string>& extensions = mesa.extensions();
  EXPECT_NE(std::find(extensions.begin(), extensions.end(), "GL_ARB_vertex_program"),
            extensions.end());
  EXPECT_NE(std::find(extensions.begin(), extensions.end(), "GL_ARB_fragment_program"),
            extensions.end());
}

TEST(MesaContextTest, RejectsUnknownDriverBeforeCreating) {
  // GALLIUM_DRIVER=zink would crash OSMesaCreateContextAttribs: the name never gets there.
  std::string error;
  MesaOptions options;
  options.driver = "zink";
  EXPECT_EQ(CreateMesaContext(options, &error), nullptr);
  EXPECT_THAT(error, HasSubstr("unsupported Mesa driver 'zink'"));
  options.driver = "";
  EXPECT_EQ(CreateMesaContext(options, &error), nullptr);
  EXPECT_FALSE(IsSupportedMesaDriver("Softpipe"));
  EXPECT_TRUE(IsSupportedMesaDriver("softpipe"));
  EXPECT_TRUE(IsSupportedMesaDriver("llvmpipe"));
}

TEST(MesaContextTest, SecondContextWithAnotherDriverIsRefused) {
  Mesa();  // softpipe is now this process's driver
  std::string error;
  MesaOptions options;
  options.driver = "llvmpipe";
  EXPECT_EQ(CreateMesaContext(options, &error), nullptr);
  EXPECT_THAT(error, HasSubstr("chosen once per process"));
  options.driver = "softpipe";
  std::unique_ptr<MesaContext> second = CreateMesaContext(options, &error);
  ASSERT_NE(second, nullptr) << error;
  EXPECT_TRUE(second
                  ->CompileGlsl(glsl::Stage::Fragment,
                                {"void main() { gl_FragColor = vec4(1.0); }\n"}, true)
                  .accepted);
}

TEST(MesaContextTest, CompilesValidVertexShader) {
  MesaVerdict v = Mesa().CompileGlsl(
      glsl::Stage::Vertex, {"#version 110\nvoid main() { gl_Position = ftransform(); }\n"}, false);
  EXPECT_TRUE(v.accepted) << v.compile_log;
  EXPECT_TRUE(v.compiled);
  EXPECT_FALSE(v.linked);  // no link asked for
  EXPECT_EQ(v.failure, "");
}

TEST(MesaContextTest, ReportsCompileErrorWithLine) {
  MesaVerdict v = Mesa().CompileGlsl(
      glsl::Stage::Fragment,
      {"#version 110\nvoid main() {\n  float x = 1;\n  gl_FragColor = vec4(x);\n}\n"}, true);
  EXPECT_FALSE(v.accepted);
  EXPECT_FALSE(v.compiled);
  EXPECT_EQ(v.link_log, "");  // no link after a failed compile
  EXPECT_THAT(FirstErrorLine(v), StartsWith("0:3("));
  EXPECT_THAT(FirstErrorLine(v), HasSubstr("error"));
}

TEST(MesaContextTest, SeveralStringsAreOneShader) {
  MesaVerdict v = Mesa().CompileGlsl(glsl::Stage::Fragment,
                                     {"#version 110\nuniform vec4 c;\n", "vec4 f() { return c; }\n",
                                      "void main() { gl_FragColor = f(); }\n"},
                                     true);
  EXPECT_TRUE(v.accepted) << v.compile_log << v.link_log;
}

TEST(MesaContextTest, LinkFailureIsRejection) {
  // Compiles, but a program needs main (GLSL 1.10 section 7: "each shader ... must have main"
  // is checked when linking).
  MesaVerdict compile_only =
      Mesa().CompileGlsl(glsl::Stage::Fragment, {"vec4 f() { return vec4(1.0); }\n"}, false);
  EXPECT_TRUE(compile_only.accepted) << compile_only.compile_log;
  MesaVerdict linked =
      Mesa().CompileGlsl(glsl::Stage::Fragment, {"vec4 f() { return vec4(1.0); }\n"}, true);
  EXPECT_TRUE(linked.compiled);
  EXPECT_FALSE(linked.linked);
  EXPECT_FALSE(linked.accepted);
  EXPECT_NE(linked.link_log, "");
  EXPECT_THAT(FirstErrorLine(linked), HasSubstr("error"));
}

TEST(MesaContextTest, LoadsArbPrograms) {
  MesaVerdict vp = Mesa().LoadArbProgram(
      arbvp::ProgramKind::Vertex, "!!ARBvp1.0\nMOV result.position, vertex.position;\nEND\n");
  EXPECT_TRUE(vp.accepted) << vp.error_string;
  EXPECT_EQ(vp.error_position, -1);
  MesaVerdict fp = Mesa().LoadArbProgram(arbvp::ProgramKind::Fragment,
                                         "!!ARBfp1.0\nMOV result.color, fragment.color;\nEND\n");
  EXPECT_TRUE(fp.accepted) << fp.error_string;
}

TEST(MesaContextTest, ReportsArbErrorPosition) {
  const std::string text = "!!ARBfp1.0\nMOV result.color, bogus;\nEND\n";
  MesaVerdict v = Mesa().LoadArbProgram(arbvp::ProgramKind::Fragment, text);
  EXPECT_FALSE(v.accepted);
  EXPECT_EQ(v.failure, "");  // GL_INVALID_OPERATION is the rejection itself
  EXPECT_GE(v.error_position, 0);
  EXPECT_LE(v.error_position, static_cast<int>(text.size()));
  EXPECT_THAT(v.error_string, HasSubstr("line 2"));
  EXPECT_EQ(FirstErrorLine(v), v.error_string.substr(0, v.error_string.find('\n')));
  // A vertex program in the fragment target is rejected too.
  EXPECT_FALSE(Mesa()
                   .LoadArbProgram(arbvp::ProgramKind::Fragment,
                                   "!!ARBvp1.0\nMOV result.position, vertex.position;\nEND\n")
                   .accepted);
}

TEST(MesaContextTest, WorkerThreadsShareTheContext) {
  MesaContext& mesa = Mesa();
  std::vector<std::thread> threads;
  std::vector<int> accepted(4, 0);
  for (size_t t = 0; t < accepted.size(); ++t) {
    threads.emplace_back([&mesa, &accepted, t] {
      for (int i = 0; i < 5; ++i) {
        bool ok = mesa.CompileGlsl(glsl::Stage::Fragment,
                                   {"void main() { gl_FragColor = vec4(0.5); }\n"}, true)
                      .accepted;
        bool bad = mesa.CompileGlsl(glsl::Stage::Fragment, {"void main() { x; }\n"}, true).accepted;
        accepted[t] += (ok ? 1 : 0) + (bad ? 100 : 0);
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (int count : accepted) EXPECT_EQ(count, 5);
}

TEST(MesaContextTest, FirstErrorLineOfNothingIsEmpty) {
  EXPECT_EQ(FirstErrorLine(MesaVerdict{}), "");
  MesaVerdict warning_only;
  warning_only.compile_log = "\n0:1(1): warning: something\n";
  EXPECT_EQ(FirstErrorLine(warning_only), "0:1(1): warning: something");
}

}  // namespace
}  // namespace arbiter::runtime
