// Point submission: see draw.h. Immediate mode: every attribute of a vertex first, then the
// one that emits it (glVertex, or generic attribute 0 which aliases it).
#include "exec/draw.h"

#include <algorithm>

namespace arbiter::runtime::exec {

arbvp::Vec4 PixelClipPosition(size_t index, int width, int height, float depth,
                              const arbvp::GlState& state) {
  const arbvp::Pixel pixel = arbvp::FragmentPixel(index);
  // Window x = (x_ndc + 1) * width / 2 is exact for these values: the centre x + 0.5.
  const float x = (2.0f * (static_cast<float>(pixel.x) + 0.5f)) / static_cast<float>(width) - 1.0f;
  const float y = (2.0f * (static_cast<float>(pixel.y) + 0.5f)) / static_cast<float>(height) - 1.0f;
  // GL clamps the depth range to [0, 1]; window z = n + (f - n) (z_ndc + 1) / 2.
  const double n = std::clamp(static_cast<double>(state.depth_near), 0.0, 1.0);
  const double f = std::clamp(static_cast<double>(state.depth_far), 0.0, 1.0);
  const double z = f != n ? 2.0 * (static_cast<double>(depth) - n) / (f - n) - 1.0 : 0.0;
  return {x, y, static_cast<float>(z), 1.0f};
}

namespace {

// Sends the attributes of one vector, the emitting one last.
void EmitVertex(const ExecGl& gl, const RunPlan& plan, const arbvp::InputVector& v,
                const arbvp::Vec4& clip) {
  if (plan.mode == RunMode::Fragment) {
    const arbvp::FragmentInput& in = v.fragment;
    const FragmentInputAttribs& a = kFragmentInputAttribs;
    const arbvp::Vec4 fog{in.fogcoord, 0.0f, 0.0f, 1.0f};
    gl.VertexAttrib4fvARB(static_cast<GLuint>(a.color), in.color.data());
    gl.VertexAttrib4fvARB(static_cast<GLuint>(a.secondary_color), in.secondary_color.data());
    gl.VertexAttrib4fvARB(static_cast<GLuint>(a.fogcoord), fog.data());
    for (int k = 0; k < arbvp::kMaxTextureCoords; ++k) {
      gl.VertexAttrib4fvARB(static_cast<GLuint>(a.texcoord0 + k),
                            in.texcoord[static_cast<size_t>(k)].data());
    }
    gl.VertexAttrib4fvARB(static_cast<GLuint>(a.position), clip.data());
    return;
  }
  const arbvp::VertexInput& in = v.vertex;
  gl.Normal3fv(in.normal.data());
  gl.Color4fv(in.color.data());
  gl.SecondaryColor3fv(in.secondary_color.data());
  gl.FogCoordf(in.fogcoord[0]);
  for (int k = 0; k < arbvp::kMaxTextureCoords; ++k) {
    gl.MultiTexCoord4fv(static_cast<GLenum>(GL_TEXTURE0 + k),
                        in.texcoord[static_cast<size_t>(k)].data());
  }
  for (int n : plan.generics) {
    if (n != 0) {
      gl.VertexAttrib4fvARB(static_cast<GLuint>(n), in.generic[static_cast<size_t>(n)].data());
    }
  }
  if (plan.position_attrib >= 0) {
    gl.VertexAttrib4fvARB(static_cast<GLuint>(plan.position_attrib), clip.data());
  }
  // Generic attribute 0 aliases the position (ARBvp 2.7): the model's position is both.
  gl.Vertex4fv(in.position.data());
}

}  // namespace

void DrawPoints(const ExecGl& gl, const RunPlan& plan, const arbvp::ExecInputs& inputs, int width,
                int height, GLint pixel_uniform) {
  // A position in program.env or a uniform can only change between glBegin and glEnd pairs.
  const bool per_point = plan.position_env >= 0 || pixel_uniform >= 0;
  if (!per_point) gl.Begin(GL_POINTS);
  for (size_t i = 0; i < inputs.vectors.size(); ++i) {
    const arbvp::InputVector& v = inputs.vectors[i];
    const arbvp::Vec4 clip = PixelClipPosition(i, width, height, v.fragment.depth, inputs.state);
    if (pixel_uniform >= 0) {
      gl.Uniform4fv(pixel_uniform, 1, clip.data());
    } else if (per_point) {
      gl.ProgramEnvParameter4fvARB(GL_VERTEX_PROGRAM_ARB, static_cast<GLuint>(plan.position_env),
                                   clip.data());
    }
    if (per_point) gl.Begin(GL_POINTS);
    EmitVertex(gl, plan, v, clip);
    if (per_point) gl.End();
  }
  if (!per_point) gl.End();
}

void CollectResults(const RunPlan& plan, const std::vector<std::vector<float>>& values,
                    const std::vector<float>& alive, uint8_t (*written_mask)(const arbvp::Binding&),
                    std::vector<arbvp::VectorResult>* results) {
  const arbvp::ProgramKind kind =
      plan.mode == RunMode::Vertex ? arbvp::ProgramKind::Vertex : arbvp::ProgramKind::Fragment;
  for (size_t i = 0; i < results->size(); ++i) {
    const arbvp::Pixel pixel = arbvp::FragmentPixel(i);
    const size_t offset =
        (static_cast<size_t>(pixel.y) * arbvp::kFramebufferWidth + static_cast<size_t>(pixel.x)) *
        4;
    arbvp::VectorResult& result = (*results)[i];
    if (!alive.empty() && alive[offset] != 1.0f) {
      result.killed = true;
      continue;
    }
    for (size_t s = 0; s < plan.outputs.size(); ++s) {
      arbvp::OutputRegister out;
      out.binding = plan.outputs[s].binding;
      out.name = arbvp::BindingName(out.binding, kind);
      out.written = plan.outputs[s].written;
      if (written_mask != nullptr) out.written &= written_mask(out.binding);
      for (size_t c = 0; c < 4; ++c) out.value[c] = values[s][offset + c];
      result.outputs.push_back(std::move(out));
    }
  }
}

}  // namespace arbiter::runtime::exec
