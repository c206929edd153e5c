// TranslateChecked: emit (EmitTranslation), then compile (and link) the GLSL with glslang
// in process (SelfCheckTranslation).
#include <fmt/format.h>

#include "arbiter/glsl/check.h"
#include "arbiter/glsl/link.h"
#include "arbiter/runtime/translate.h"

namespace arbiter::runtime {
namespace {

// The first error of `sink` as "line:col: message [code]", or "" when there is none.
std::string FirstError(const compiler::DiagnosticSink& sink) {
  for (const compiler::Diagnostic& d : sink.diagnostics()) {
    if (d.severity != compiler::Severity::Error) continue;
    compiler::LineCol at = d.file ? d.file->Locate(d.range.begin) : compiler::LineCol{};
    return fmt::format("{}:{}: {} [{}]", at.line, at.column, d.message, d.info->code);
  }
  return "";
}

}  // namespace

CheckedTranslation EmitTranslation(const arbvp::Program* vertex, const arbvp::Program* fragment,
                                   const arbvp::EmitOptions& options,
                                   const compiler::SourceFile* vertex_source,
                                   const compiler::SourceFile* fragment_source) {
  CheckedTranslation out;
  for (const auto& [program, source] :
       {std::pair{vertex, vertex_source}, {fragment, fragment_source}}) {
    if (!program) continue;
    arbvp::Untranslatable u = arbvp::FindUntranslatable(*program, options);
    if (u.what.empty()) continue;
    compiler::LineCol at = source ? source->Locate(u.range.begin) : compiler::LineCol{};
    out.error = fmt::format("{}:{}: error: {}; arbiter cannot translate this program to {}",
                            at.line, at.column, u.what, arbvp::EmitTargetTitle(options.target));
    out.refused = true;
    return out;
  }
  if (vertex && fragment) {
    arbvp::PairTranslation pair =
        arbvp::EmitGlslPair(*vertex, *fragment, options, vertex_source, fragment_source);
    out.vertex = std::move(pair.vertex);
    out.fragment = std::move(pair.fragment);
    out.bindings = std::move(pair.bindings);
  } else if (vertex || fragment) {
    const arbvp::Program* one = vertex ? vertex : fragment;
    arbvp::Translation t = arbvp::EmitGlsl(*one, options, vertex ? vertex_source : fragment_source);
    (vertex ? out.vertex : out.fragment) = std::move(t.glsl);
    out.bindings = std::move(t.bindings);
  } else {
    out.error = "nothing to translate";
  }
  return out;
}

void SelfCheckTranslation(CheckedTranslation* translation) {
  CheckedTranslation& out = *translation;
  if (!out.error.empty()) return;
  const bool vertex = !out.vertex.empty();
  const bool fragment = !out.fragment.empty();
  compiler::SourceFile vs("translation.vert", out.vertex);
  compiler::SourceFile fs("translation.frag", out.fragment);
  // Each shader alone (linked as a single shader, as `arbiter check` does), then the pair.
  struct Shader {
    const compiler::SourceFile* file;
    glsl::Stage stage;
    const char* name;
  };
  const Shader shaders[] = {{&vs, glsl::Stage::Vertex, "vertex"},
                            {&fs, glsl::Stage::Fragment, "fragment"}};
  for (const Shader& s : shaders) {
    if (s.file->text().empty()) continue;
    compiler::DiagnosticSink sink(0);
    glsl::CheckOptions check;
    check.link = true;  // a translation is a whole program stage
    if (!glsl::CheckShader(s.stage, {s.file}, check, &sink).ok) {
      out.error = fmt::format("the GLSL {} shader does not compile: {}", s.name, FirstError(sink));
      return;
    }
  }
  if (vertex && fragment) {
    compiler::DiagnosticSink sink(0);
    if (!glsl::LinkProgram({&vs}, {&fs}, glsl::LinkOptions{}, &sink).ok) {
      out.error = fmt::format("the GLSL shaders do not link: {}", FirstError(sink));
      return;
    }
  }
  out.ok = true;
}

CheckedTranslation TranslateChecked(const arbvp::Program* vertex, const arbvp::Program* fragment,
                                    const arbvp::EmitOptions& options,
                                    const compiler::SourceFile* vertex_source,
                                    const compiler::SourceFile* fragment_source) {
  CheckedTranslation out =
      EmitTranslation(vertex, fragment, options, vertex_source, fragment_source);
  SelfCheckTranslation(&out);
  return out;
}

}  // namespace arbiter::runtime
