// DescribeReadInputs: the inputs a program reads and their values for one vector, one line
// each, for `arbiter verify`'s disagreement report.
#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "arbiter/arbvp/exec_io.h"
#include "arbiter/arbvp/generate.h"
#include "arbiter/glstate/values.h"
#include "exec/generate_internal.h"

namespace arbiter::arbvp {
namespace {

std::string FormatVec4(const Vec4& v) {
  return fmt::format("({}, {}, {}, {})", FormatFloat(v[0]), FormatFloat(v[1]), FormatFloat(v[2]),
                     FormatFloat(v[3]));
}

template <size_t N>
Vec4 Element(const std::array<Vec4, N>& a, int32_t index, Vec4 outside) {
  if (index < 0 || static_cast<size_t>(index) >= N) return outside;
  return a[static_cast<size_t>(index)];
}

// The value a vertex attribute binding reads (ARBvp table X.2, as the interpreter reads it).
Vec4 VertexAttribValue(const Binding& b, const VertexInput& in) {
  const Vec4 unset{0.0f, 0.0f, 0.0f, 1.0f};
  switch (b.vertex_attrib) {
    case VertexAttrib::Position:
      return in.position;
    case VertexAttrib::Weight:
      return b.index == 0 ? in.weight : unset;
    case VertexAttrib::Normal:
      return {in.normal[0], in.normal[1], in.normal[2], 1.0f};
    case VertexAttrib::Color:
      return in.color;
    case VertexAttrib::SecondaryColor:
      return {in.secondary_color[0], in.secondary_color[1], in.secondary_color[2], 1.0f};
    case VertexAttrib::FogCoord:
      return {in.fogcoord[0], 0.0f, 0.0f, 1.0f};
    case VertexAttrib::TexCoord:
      return Element(in.texcoord, b.index, unset);
    case VertexAttrib::MatrixIndex:
      return b.index == 0 ? in.matrix_index : unset;
    case VertexAttrib::Generic:
      if (b.index == 0) return in.position;
      return Element(in.generic, b.index, unset);
  }
  return unset;
}

// The value a fragment attribute binding reads in a fragment program run alone (ARBfp
// table X.1); fragment.position is the vector's pixel centre and its window depth.
Vec4 FragmentAttribValue(const Binding& b, const FragmentInput& in, size_t index, size_t count,
                         FragCoordConvention convention) {
  switch (b.fragment_attrib) {
    case FragmentAttrib::Color:
      return in.color;
    case FragmentAttrib::SecondaryColor:
      return in.secondary_color;
    case FragmentAttrib::TexCoord:
      return Element(in.texcoord, b.index, Vec4{0.0f, 0.0f, 0.0f, 1.0f});
    case FragmentAttrib::FogCoord:
      return {in.fogcoord, 0.0f, 0.0f, 1.0f};
    case FragmentAttrib::Facing:  // a point is front facing
      return {1.0f, 0.0f, 0.0f, 1.0f};
    case FragmentAttrib::Position: {
      const auto [x, y] = FragmentCoordXY(index, count, convention);
      return {x, y, in.depth, 1.0f};
    }
  }
  return {0.0f, 0.0f, 0.0f, 1.0f};
}

std::string_view WrapName(TexWrap wrap) {
  switch (wrap) {
    case TexWrap::Repeat:
      return "repeat";
    case TexWrap::ClampToEdge:
      return "clamp";
    case TexWrap::MirroredRepeat:
      return "mirror";
  }
  return "?";
}

std::string_view CompareName(CompareFunc func) {
  static constexpr std::string_view kNames[] = {"never",   "less",     "equal",  "lequal",
                                                "greater", "notequal", "gequal", "always"};
  return kNames[static_cast<size_t>(func)];
}

std::string_view DepthModeName(DepthMode mode) {
  switch (mode) {
    case DepthMode::Luminance:
      return "luminance";
    case DepthMode::Intensity:
      return "intensity";
    case DepthMode::Alpha:
      return "alpha";
  }
  return "?";
}

// The parameter and state lines of one program; `prefix` tells a pair's programs apart.
void DescribeParams(const Program& program, const gen::ReadInputs& read, const ExecInputs& inputs,
                    std::string_view prefix, std::set<std::string>* lines) {
  const ProgramParameters& params =
      program.kind == ProgramKind::Vertex ? inputs.vertex_params : inputs.fragment_params;
  for (const Binding& b : read.params) {
    std::string name = BindingName(b, program.kind);
    switch (b.kind) {
      case BindingKind::ProgramEnv:
        lines->insert(fmt::format("{}{} = {}", prefix, name,
                                  FormatVec4(glstate::ParameterValue(params.env, b.index))));
        break;
      case BindingKind::ProgramLocal:
        lines->insert(fmt::format("{}{} = {}", prefix, name,
                                  FormatVec4(glstate::ParameterValue(params.local, b.index))));
        break;
      case BindingKind::State:
        lines->insert(fmt::format("{} = {}", name, FormatVec4(ReadStateBinding(inputs.state, b))));
        break;
      case BindingKind::VertexAttrib:
      case BindingKind::FragmentAttrib:
      case BindingKind::Result:
      case BindingKind::Constant:
        break;
    }
  }
}

}  // namespace

std::string DescribeTexture(const Texture& t) {
  std::string size = fmt::format("{}", t.width);
  if (t.dim != TexDim::Tex1D) size += fmt::format("x{}", t.height);
  if (t.dim == TexDim::Tex3D) size += fmt::format("x{}", t.depth);
  std::string text =
      fmt::format("{} {} {} {}", TexDimName(t.dim), size,
                  t.filter == TexFilter::Linear ? "linear" : "nearest", WrapName(t.wrap));
  if (t.depth_texture) {
    text += " depth";
    if (t.compare) text += fmt::format(" compare {}", CompareName(t.compare_func));
    text += fmt::format(" {}", DepthModeName(t.depth_mode));
  }
  return text;
}

std::vector<std::string> DescribeReadInputs(const Program* vertex, const Program* fragment,
                                            const ExecInputs& inputs, size_t index) {
  std::set<std::string> lines;
  if (index >= inputs.vectors.size() || (!vertex && !fragment)) return {};
  const InputVector& in = inputs.vectors[index];
  const bool pair = vertex && fragment;
  for (const Program* p : {vertex, fragment}) {
    if (!p) continue;
    gen::ReadInputs read = gen::FindReadInputs(*p, false);
    // A pair's fragment attributes come from the vertex program: not inputs.
    if (p == vertex || !pair) {
      for (const Binding& b : read.attribs) {
        Vec4 value = p->kind == ProgramKind::Vertex
                         ? VertexAttribValue(b, in.vertex)
                         : FragmentAttribValue(b, in.fragment, index, inputs.vectors.size(),
                                               FragCoordConventionOf(*p));
        lines.insert(fmt::format("{} = {}", BindingName(b, p->kind), FormatVec4(value)));
      }
    }
    std::string_view prefix;
    if (pair) prefix = p == vertex ? "vertex." : "fragment.";
    DescribeParams(*p, read, inputs, prefix, &lines);
    for (const auto& [unit, target] : read.textures) {
      auto it = inputs.textures.find(unit);
      lines.insert(fmt::format(
          "texture[{}] = {}", unit,
          it == inputs.textures.end() ? std::string("none") : DescribeTexture(it->second)));
    }
  }
  return {lines.begin(), lines.end()};
}

}  // namespace arbiter::arbvp
