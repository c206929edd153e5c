// A GLSL run for the tests: the shaders checked and reflected by arbiter (as `arbiter exec`
// does), inputs given as the CLI spells them (--set, --uniform, --state, --texture), and the
// run on Mesa (RunGlsl, in process or in a worker). Shared by run_test.cpp and the case table's
// test (glsl_case_test.cpp).
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "arbiter/arbvp/exec_io.h"
#include "arbiter/glsl/link.h"
#include "arbiter/glsl/reflect.h"
#include "arbiter/runtime/glsl_exec.h"

namespace arbiter::runtime::testing {

inline std::string Env(const char* name, const char* fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? value : fallback;
}

// The backend and driver of ARBITER_TEST_BACKEND (osmesa) and ARBITER_TEST_DRIVER (softpipe).
inline ExecOptions EnvOptions() {
  ExecOptions options;
  EXPECT_TRUE(ParseBackend(Env("ARBITER_TEST_BACKEND", "osmesa"), &options.backend));
  options.driver = Env("ARBITER_TEST_DRIVER", "softpipe");
  return options;
}

// One run: the shaders (checked and reflected by arbiter), the inputs, the result.
class GlslRun {
 public:
  GlslRun(const std::string& vertex, const std::string& fragment) {
    compiler::DiagnosticSink sink(20);
    if (!vertex.empty()) vs_ = std::make_unique<compiler::SourceFile>("t.vert", vertex);
    if (!fragment.empty()) fs_ = std::make_unique<compiler::SourceFile>("t.frag", fragment);
    if (vs_ && fs_) {
      glsl::LinkResult linked = glsl::LinkProgram({vs_.get()}, {fs_.get()}, {}, &sink);
      vr_ = std::move(linked.vertex);
      fr_ = std::move(linked.fragment);
    } else if (vs_) {
      vr_ = glsl::ReflectShader(glsl::Stage::Vertex, {vs_.get()}, &sink);
    } else {
      fr_ = glsl::ReflectShader(glsl::Stage::Fragment, {fs_.get()}, &sink);
    }
    check_errors_ = sink.error_count();
    std::string messages;
    for (const compiler::Diagnostic& d : sink.diagnostics()) {
      messages += (d.info != nullptr ? std::string(d.info->code) : "") + ": " + d.message + "\n";
    }
    EXPECT_EQ(check_errors_, 0u) << vertex << fragment << messages;
    shaders_.vertex = vertex;
    shaders_.fragment = fragment;
    shaders_.vertex_reflection = vs_ ? &vr_ : nullptr;
    shaders_.fragment_reflection = fs_ ? &fr_ : nullptr;
    inputs_.slots = GlslInputSlots(shaders_.vertex_reflection, shaders_.fragment_reflection);
    for (const glsl::Reflection* r : {&vr_, &fr_}) {
      for (const glsl::ReflectedVariable& v : r->uniforms)
        inputs_.declared_uniforms.push_back(v.name);
    }
    Vectors(1);
  }

  // `count` vectors, every slot at its fill.
  void Vectors(size_t count) {
    std::map<std::string, std::vector<float>> base;
    for (const GlslInputSlot& slot : inputs_.slots) base[slot.name] = slot.fill;
    inputs_.vectors.assign(count, base);
  }
  // --set on vector `v`.
  void Set(const std::string& assignment, size_t v = 0) {
    std::string name;
    std::vector<float> values;
    std::string error;
    ASSERT_TRUE(ParseGlslSet(inputs_.slots, assignment, &name, &values, &error)) << error;
    inputs_.vectors.at(v)[name] = values;
  }
  void Uniform(const std::string& assignment) {
    std::string name;
    std::vector<float> values;
    std::string error;
    ASSERT_TRUE(ParseGlslUniform(assignment, &name, &values, &error)) << error;
    inputs_.uniforms.emplace_back(name, values);
  }
  void State(const std::string& assignment) {
    arbvp::ExecInputs arb;
    arb.state = inputs_.state;
    arb.vectors.emplace_back();
    std::string error;
    ASSERT_TRUE(arbvp::ApplyAssignment(assignment, &arb, &arb.vectors[0], &error)) << error;
    inputs_.state = arb.state;
  }
  void Texture(const std::string& flag) {
    arbvp::ExecInputs arb;
    arb.textures = inputs_.textures;
    std::string error;
    ASSERT_TRUE(arbvp::ApplyTextureFlag(flag, &arb, &error)) << error;
    inputs_.textures = arb.textures;
  }

  // The same run in a worker process (results carried back as JSON).
  const GlslRunResult& RunInWorker(const ExecOptions& options = EnvOptions()) {
    std::string error;
    EXPECT_EQ(RunGlslInWorker(options, WorkerLimits{}, shaders_, inputs_, &result_, &error),
              WorkerStatus::Ok)
        << error;
    return result_;
  }

  const GlslRunResult& Run(const ExecOptions& options = EnvOptions()) {
    std::string error;
    EXPECT_TRUE(RunGlsl(options, shaders_, inputs_, &result_, &error)) << error;
    return result_;
  }

  // The value of output `name` of vector `v` (empty when it is not there).
  std::vector<float> Output(const std::string& name, size_t v = 0) const {
    for (const GlslOutput& o : result_.vectors.at(v).outputs) {
      if (o.name == name) return o.value;
    }
    return {};
  }

  size_t check_errors() const { return check_errors_; }
  const GlslShaders& shaders() const { return shaders_; }
  GlslExecInputs& inputs() { return inputs_; }
  GlslRunResult& result() { return result_; }

 private:
  std::unique_ptr<compiler::SourceFile> vs_;
  std::unique_ptr<compiler::SourceFile> fs_;
  glsl::Reflection vr_;
  glsl::Reflection fr_;
  GlslShaders shaders_;
  GlslExecInputs inputs_;
  GlslRunResult result_;
  size_t check_errors_ = 0;
};

}  // namespace arbiter::runtime::testing
