// LinkProgram: a vertex and a fragment shader checked as one program (GLSL 1.10 4.3.4-4.3.6,
// GL 2.0 2.15.3-2.15.4): varyings, uniforms and samplers across the stages, resource limits.
#include "arbiter/glsl/link.h"

#include <fmt/format.h>
#include <glslang/Public/ShaderLang.h>

#include <string>

#include "diag.h"
#include "info_log.h"
#include "prepare.h"
#include "reflect_ast.h"

namespace arbiter::glsl {
namespace {

using compiler::Range;
using compiler::SourceFile;
using Sources = std::vector<const SourceFile*>;

// GLSL limits: key, GL name, GL 2.0 minimum (state tables 6.35-6.36), Mesa 22.3.6 through
// OSMesa (softpipe and llvmpipe agree except MAX_COMBINED_TEXTURE_IMAGE_UNITS, softpipe 128,
// llvmpipe 192: the smaller is kept, as in compiler/src/limits.def).
const std::vector<GlslLimit> kLimits = {
    {"glsl.max_vertex_uniform_components", "MAX_VERTEX_UNIFORM_COMPONENTS", 512, 16384,
     "uniform values a vertex shader uses (user and built-in uniforms)"},
    {"glsl.max_fragment_uniform_components", "MAX_FRAGMENT_UNIFORM_COMPONENTS", 64, 16384,
     "uniform values a fragment shader uses (user and built-in uniforms)"},
    {"glsl.max_varying_floats", "MAX_VARYING_FLOATS", 32, 128,
     "varying values written by the vertex shader or read by the fragment shader"},
    {"glsl.max_vertex_attribs", "MAX_VERTEX_ATTRIBS", 16, 16,
     "active generic and conventional vertex attributes (a matN takes N)"},
    {"glsl.max_vertex_texture_image_units", "MAX_VERTEX_TEXTURE_IMAGE_UNITS", 0, 32,
     "active samplers of the vertex shader"},
    {"glsl.max_texture_image_units", "MAX_TEXTURE_IMAGE_UNITS", 2, 32,
     "active samplers of the fragment shader"},
    {"glsl.max_combined_texture_image_units", "MAX_COMBINED_TEXTURE_IMAGE_UNITS", 2, 128,
     "active samplers of both stages together"},
};

const GlslLimit& Limit(std::string_view key) {
  for (const GlslLimit& limit : kLimits) {
    if (limit.key == key) return limit;
  }
  return kLimits.front();  // unreachable: every key used below is in the table
}

// A type with its array size: "vec4", "float[3]".
std::string Spelled(const ReflectedVariable& v) {
  return v.array_size > 0 ? fmt::format("{}[{}]", v.type, v.array_size) : v.type;
}

const ReflectedVariable* Find(const std::vector<ReflectedVariable>& list, const std::string& name) {
  for (const ReflectedVariable& v : list) {
    if (v.name == name) return &v;
  }
  return nullptr;
}

struct LinkContext {
  const Sources& vertex_sources;
  const Sources& fragment_sources;
  const Reflection& vertex;
  const Reflection& fragment;
  const compiler::LimitProfile* profile;
  compiler::DiagnosticSink* sink;

  // Reports at a declaration (at the start of the stage's first string when it was not found).
  compiler::Diagnostic* Report(Diag diag, compiler::Severity severity, const SourceFile* file,
                               Range range, const Sources& fallback, std::string message) const {
    if (file == nullptr) {
      file = fallback.front();
      range = {0, 0};
    }
    return sink->Report(Info(diag), severity, file, range, std::move(message));
  }
  compiler::Diagnostic* Report(Diag diag, const ReflectedVariable& at, const Sources& fallback,
                               std::string message) const {
    return Report(diag, Info(diag).severity, at.file, at.range, fallback, std::move(message));
  }
};

void AddNote(compiler::Diagnostic* d, const ReflectedVariable& at, std::string message) {
  if (d != nullptr) d->notes.push_back(compiler::Note{at.file, at.range, std::move(message)});
}

// GLSL 1.10 4.3.6: varyings declared in both stages have the same type; those the fragment
// shader reads are declared and written by the vertex shader. Built-in varyings need neither.
void CheckVaryings(const LinkContext& ctx) {
  for (const ReflectedVariable& in : ctx.fragment.varyings) {
    const ReflectedVariable* out = Find(ctx.vertex.varyings, in.name);
    if (out != nullptr && Spelled(*out) != Spelled(in)) {
      compiler::Diagnostic* d = ctx.Report(
          Diag::LinkVaryingType, in, ctx.fragment_sources,
          fmt::format("varying '{}' is '{}' in the fragment shader but '{}' in the vertex shader; "
                      "a varying must have the same type in both stages",
                      in.name, Spelled(in), Spelled(*out)));
      AddNote(d, *out,
              fmt::format("'{}' declared as '{}' in the vertex shader", out->name, Spelled(*out)));
      continue;
    }
    if (!in.read) continue;
    if (out == nullptr) {
      ctx.Report(Diag::LinkVaryingUndeclared, in, ctx.fragment_sources,
                 fmt::format("the fragment shader reads varying '{}', which the vertex shader "
                             "does not declare; declare 'varying {} {}{}' there and write it",
                             in.name, in.type, in.name,
                             in.array_size > 0 ? fmt::format("[{}]", in.array_size) : ""));
    } else if (!out->written) {
      compiler::Diagnostic* d =
          ctx.Report(Diag::LinkVaryingUnwritten, in, ctx.fragment_sources,
                     fmt::format("the fragment shader reads varying '{}', which the vertex "
                                 "shader declares but never writes",
                                 in.name));
      AddNote(d, *out, fmt::format("'{}' declared here, never written", out->name));
    }
  }
}

// GLSL 1.10 4.3.5: uniforms of one name have one type across the program; for samplers a
// different type would put two targets on one texture image unit (GL 2.0 2.15.3).
void CheckUniforms(const LinkContext& ctx) {
  auto all = [](const Reflection& r) {
    std::vector<const ReflectedVariable*> list;
    for (const ReflectedVariable& v : r.uniforms) list.push_back(&v);
    for (const ReflectedVariable& v : r.samplers) list.push_back(&v);
    return list;
  };
  std::vector<const ReflectedVariable*> vertex = all(ctx.vertex);
  for (const ReflectedVariable* f : all(ctx.fragment)) {
    for (const ReflectedVariable* v : vertex) {
      if (v->name != f->name || Spelled(*v) == Spelled(*f)) continue;
      bool samplers = Find(ctx.fragment.samplers, f->name) != nullptr &&
                      Find(ctx.vertex.samplers, v->name) != nullptr;
      std::string message =
          samplers ? fmt::format(
                         "sampler '{}' is '{}' in the fragment shader but '{}' in the "
                         "vertex shader; one sampler uniform selects one texture image "
                         "unit, which may not serve two texture targets",
                         f->name, Spelled(*f), Spelled(*v))
                   : fmt::format(
                         "uniform '{}' is '{}' in the fragment shader but '{}' in the "
                         "vertex shader; uniforms of one name must have one type in a "
                         "program",
                         f->name, Spelled(*f), Spelled(*v));
      compiler::Diagnostic* d = ctx.Report(samplers ? Diag::LinkSamplerType : Diag::LinkUniformType,
                                           *f, ctx.fragment_sources, std::move(message));
      AddNote(d, *v,
              fmt::format("'{}' declared as '{}' in the vertex shader", v->name, Spelled(*v)));
    }
  }
}

// The value of a limit to enforce: Mesa's without a profile.
int64_t Enforced(const LinkContext& ctx, const GlslLimit& limit) {
  if (ctx.profile == nullptr) return limit.mesa;
  auto it = ctx.profile->values.find(limit.key);
  if (it != ctx.profile->values.end()) return it->second;
  return ctx.profile->name == "mesa" ? limit.mesa : limit.spec_min;
}

// Sums `items` against one limit; reports an error at the item that goes past the enforced
// limit. Going past only the spec minimum is no warning: `--limits spec-min` makes it an error.
void CheckLimit(const LinkContext& ctx, std::string_view key, Diag diag, std::string_view what,
                std::string_view unit, const std::vector<Contribution>& items,
                const Sources& fallback) {
  const GlslLimit& limit = Limit(key);
  int64_t total = 0;
  for (const Contribution& c : items) total += c.amount;
  int64_t enforced = Enforced(ctx, limit);
  if (total <= enforced) return;
  if (total == 1 && !unit.empty() && unit.back() == 's') unit.remove_suffix(1);
  int64_t running = 0;
  const Contribution* past = &items.back();
  for (const Contribution& c : items) {
    running += c.amount;
    if (running > enforced) {
      past = &c;
      break;
    }
  }
  ctx.Report(diag, compiler::Severity::Error, past->file, past->range, fallback,
             fmt::format("{} take {} {}, more than {} = {} in profile '{}' ({} goes past it)", what,
                         total, unit, limit.gl_name, enforced,
                         ctx.profile ? ctx.profile->name : "mesa", past->what));
}

// GL 2.0 2.15.3-2.15.4 and 3.11.1: the program's resources against the limits.
void CheckLimits(const LinkContext& ctx) {
  const Sources& vs = ctx.vertex_sources;
  const Sources& fs = ctx.fragment_sources;
  CheckLimit(ctx, "glsl.max_vertex_uniform_components", Diag::LinkLimitUniforms,
             "the vertex shader's active uniforms", "components",
             Contributions(ctx.vertex, Resource::UniformComponents), vs);
  CheckLimit(ctx, "glsl.max_fragment_uniform_components", Diag::LinkLimitUniforms,
             "the fragment shader's active uniforms", "components",
             Contributions(ctx.fragment, Resource::UniformComponents), fs);

  // One interpolant counts once, whichever stage writes or reads it.
  std::vector<Contribution> varyings = Contributions(ctx.vertex, Resource::VaryingFloats);
  for (Contribution& c : Contributions(ctx.fragment, Resource::VaryingFloats)) {
    bool known = false;
    for (const Contribution& v : varyings) known = known || v.key == c.key;
    if (!known) varyings.push_back(std::move(c));
  }
  CheckLimit(ctx, "glsl.max_varying_floats", Diag::LinkLimitVaryings, "the program's varyings",
             "components", varyings, vs);
  CheckLimit(ctx, "glsl.max_vertex_attribs", Diag::LinkLimitAttributes,
             "the vertex shader's active attributes", "locations",
             Contributions(ctx.vertex, Resource::VertexAttribs), vs);

  std::vector<Contribution> vertex_samplers = Contributions(ctx.vertex, Resource::Samplers);
  std::vector<Contribution> fragment_samplers = Contributions(ctx.fragment, Resource::Samplers);
  CheckLimit(ctx, "glsl.max_vertex_texture_image_units", Diag::LinkLimitSamplers,
             "the vertex shader's active samplers", "texture image units", vertex_samplers, vs);
  CheckLimit(ctx, "glsl.max_texture_image_units", Diag::LinkLimitSamplers,
             "the fragment shader's active samplers", "texture image units", fragment_samplers, fs);
  // A unit both stages use counts twice (GL 2.0 2.15.4).
  std::vector<Contribution> combined = vertex_samplers;
  combined.insert(combined.end(), fragment_samplers.begin(), fragment_samplers.end());
  CheckLimit(ctx, "glsl.max_combined_texture_image_units", Diag::LinkLimitSamplers,
             "the program's active samplers", "texture image units", combined, vs);
}

int Errors(const compiler::DiagnosticSink& sink) { return sink.error_count() + sink.dropped(); }

}  // namespace

const std::vector<GlslLimit>& GlslLimits() { return kLimits; }

LinkResult LinkProgram(const Sources& vertex, const Sources& fragment, const LinkOptions& options,
                       compiler::DiagnosticSink* sink) {
  LinkResult result;
  int errors_before = Errors(*sink);
  if (vertex.empty() && fragment.empty()) {
    sink->Report(Info(Diag::LinkError), nullptr, {0, 0}, "a program needs a shader");
    return result;
  }
  // Each stage's own diagnostics; a vertex shader that never writes gl_Position does not link.
  // A stage not given is reflected as empty: a one-stage program gets the limits alone.
  CheckOptions check = options.check;
  check.link = true;
  if (check.profile == nullptr) check.profile = options.profile;
  bool vertex_ok = vertex.empty() || CheckShader(Stage::Vertex, vertex, check, sink).ok;
  bool fragment_ok = fragment.empty() || CheckShader(Stage::Fragment, fragment, check, sink).ok;

  CompiledProgram program(vertex, fragment, &check);
  result.vertex.ok = vertex.empty() || program.Reflect(Stage::Vertex, &result.vertex);
  result.fragment.ok = fragment.empty() || program.Reflect(Stage::Fragment, &result.fragment);
  result.fragment.stage = Stage::Fragment;
  if (result.vertex.ok && result.fragment.ok) {
    LinkContext ctx{vertex.empty() ? fragment : vertex,
                    fragment.empty() ? vertex : fragment,
                    result.vertex,
                    result.fragment,
                    options.profile,
                    sink};
    int before = Errors(*sink);
    if (!vertex.empty() && !fragment.empty()) {
      CheckVaryings(ctx);
      CheckUniforms(ctx);
    }
    CheckLimits(ctx);
    // glslang's cross-stage messages name no variable and repeat the rules above; they are
    // reported only when those found nothing, so that no program glslang refuses passes.
    if (!program.linked() && vertex_ok && fragment_ok && Errors(*sink) == before) {
      Sources all = vertex;
      all.insert(all.end(), fragment.begin(), fragment.end());
      ReportInfoLog(program.link_log(), InfoLogContext{all, Stage::Fragment}, /*link=*/true, sink);
      if (Errors(*sink) == before) {
        sink->Report(Info(Diag::LinkError), fragment.front(), {0, 0},
                     "glslang refused to link the program without a message");
      }
    }
  } else if (vertex_ok && fragment_ok) {
    sink->Report(Info(Diag::InternalError), vertex.front(), {0, 0},
                 "glslang rejected shaders it had accepted; the program was not checked");
  }
  result.ok = Errors(*sink) == errors_before;
  return result;
}

bool LinkShaders(const std::vector<ShaderObject>& objects, const LinkOptions& options,
                 compiler::DiagnosticSink* sink) {
  const int errors_before = Errors(*sink);
  Sources vertex_strings;
  Sources fragment_strings;
  int counts[2] = {0, 0};
  for (const ShaderObject& object : objects) {
    ++counts[object.stage == Stage::Vertex ? 0 : 1];
    Sources& strings = object.stage == Stage::Vertex ? vertex_strings : fragment_strings;
    strings.insert(strings.end(), object.strings.begin(), object.strings.end());
  }
  if (counts[0] <= 1 && counts[1] <= 1) {
    return LinkProgram(vertex_strings, fragment_strings, options, sink).ok;
  }
  CheckOptions check = options.check;
  if (check.profile == nullptr) check.profile = options.profile;
  // Several objects of a stage: each compiled as an object, then glslang links them all.
  check.link = false;
  for (const ShaderObject& object : objects) CheckShader(object.stage, object.strings, check, sink);
  if (Errors(*sink) != errors_before) return false;
  std::vector<std::unique_ptr<glslang::TShader>> shaders;
  glslang::TProgram program;
  Sources all;
  for (const ShaderObject& object : objects) {
    compiler::DiagnosticSink scratch(0);
    PreparedShader prepared = PrepareShader(object.stage, object.strings, check, &scratch);
    bool parsed = false;
    shaders.push_back(ParsePrepared(object.stage, &prepared, &parsed));
    program.addShader(shaders.back().get());
    all.insert(all.end(), object.strings.begin(), object.strings.end());
  }
  constexpr auto kMessages = static_cast<EShMessages>(EShMsgCascadingErrors);
  if (!program.link(kMessages)) {
    ReportInfoLog(program.getInfoLog(), InfoLogContext{all, objects.front().stage}, true, sink);
    if (Errors(*sink) == errors_before) {
      sink->Report(Info(Diag::LinkError), all.front(), {0, 0},
                   "glslang refused to link the program without a message");
    }
  }
  return Errors(*sink) == errors_before;
}

}  // namespace arbiter::glsl
