// The fragment stage of the GLSL exec: one point per vector at its pixel (arbvp::FragmentPixel,
// a scissor of that one pixel), gl_FragColor / gl_FragData[n] read from RGBA32F colour
// attachments (colour clamping off), gl_FragDepth from a DEPTH32F depth buffer, and discard
// from the stencil buffer (every fragment that survives writes stencil 1).
//
// A fragment shader alone is fed by a generated vertex shader that writes each input it
// reads from a uniform set per point; a pair's own vertex shader runs with its main renamed
// and a second vertex shader object placing the point at the vector's pixel afterwards.
#include <fmt/format.h>

#include <algorithm>
#include <regex>
#include <sstream>

#include "exec/draw.h"
#include "exec/framebuffer.h"
#include "glsl_exec/run.h"
#include "glsl_exec/types.h"

namespace arbiter::runtime::glsl_exec {
namespace {

constexpr const char* kPixelUniform = "arbiter_pixel";
// Mesa's GL_MAX_DRAW_BUFFERS (softpipe, llvmpipe; lavapipe's colour attachments too).
constexpr int kMesaDrawBuffers = 8;

// One uniform of the generated vertex shader fed from an input slot.
struct Feed {
  std::string uniform;  // arbiter_in_3
  std::string type;     // vec4
  std::string slot;     // the input's name
};

// The vertex shader that stands for the vertex stage of a fragment shader alone.
std::string PassThroughShader(const std::vector<GlslInputSlot>& slots,
                              const glsl::Reflection& fragment, std::vector<Feed>* feeds) {
  std::ostringstream decl;
  std::ostringstream body;
  decl << "#version 120\nuniform vec4 " << kPixelUniform << ";\n";
  body << "void main() {\n  gl_Position = " << kPixelUniform << ";\n";
  // User varyings: declared as the fragment shader declares them.
  for (const glsl::ReflectedVariable& v : fragment.varyings) {
    decl << "varying " << v.type << " " << v.name;
    if (v.array_size > 0) decl << "[" << v.array_size << "]";
    decl << ";\n";
  }
  for (const GlslInputSlot& slot : slots) {
    if (!slot.read || slot.name == "gl_FragCoord.z") continue;
    const std::string uniform = fmt::format("arbiter_in_{}", feeds->size());
    feeds->push_back({uniform, slot.type, slot.name});
    decl << "uniform " << slot.type << " " << uniform << ";\n";
    std::string target = slot.name;
    if (slot.name == "gl_Color") target = "gl_FrontColor";
    if (slot.name == "gl_SecondaryColor") target = "gl_FrontSecondaryColor";
    body << "  " << target << " = " << uniform << ";\n";
  }
  body << "}\n";
  return decl.str() + body.str();
}

// The user's vertex shader with its main renamed (a macro after #version), and the shader
// object whose main calls it and then places the point.
std::vector<std::string> PairVertexShaders(const std::string& user) {
  static const std::regex version(R"((^|\n)[ \t]*#[ \t]*version[^\n]*\n)");
  std::smatch match;
  std::string renamed;
  const std::string define = "#define main arbiter_user_main\n";
  if (std::regex_search(user, match, version)) {
    const size_t end = static_cast<size_t>(match.position(0) + match.length(0));
    renamed = user.substr(0, end) + define + user.substr(end);
  } else {
    renamed = define + user;
  }
  std::string wrapper = fmt::format(
      "#version 110\nuniform vec4 {0};\nvoid arbiter_user_main();\n"
      "void main() {{\n  arbiter_user_main();\n  gl_Position = {0};\n}}\n",
      kPixelUniform);
  return {renamed, wrapper};
}

std::vector<float> Value(const std::map<std::string, std::vector<float>>& v,
                         const std::string& name, const std::vector<float>& fallback) {
  auto it = v.find(name);
  return it != v.end() ? it->second : fallback;
}

}  // namespace

FragmentOutputs OutputsOf(const glsl::Reflection& fragment) {
  FragmentOutputs out;
  for (const glsl::BuiltinUse& use : fragment.builtins_written) {
    if (use.name.starts_with("gl_FragColor")) out.color = true;
    if (use.name.starts_with("gl_FragDepth")) out.depth = true;
    if (!use.name.starts_with("gl_FragData")) continue;
    if (use.name.starts_with("gl_FragData[")) {
      out.data.push_back(std::stoi(use.name.substr(12)));
    } else {  // indexed by a variable: every draw buffer
      // The checker's gl_FragData has glslang's default size (32); Mesa has 8 draw buffers
      // (GL_MAX_DRAW_BUFFERS, gl_MaxDrawBuffers), and a framebuffer of more fails the draw.
      const int buffers = std::min(std::max(use.components / 4, 1), kMesaDrawBuffers);
      for (int i = 0; i < buffers; ++i) out.data.push_back(i);
    }
  }
  std::sort(out.data.begin(), out.data.end());
  out.data.erase(std::unique(out.data.begin(), out.data.end()), out.data.end());
  return out;
}

bool RunFragment(const RunContext& run, std::vector<GlslVectorResult>* results,
                 std::string* error) {
  const Gl& gl = run.gl;
  const glsl::Reflection& fragment = *run.shaders.fragment_reflection;
  const bool pair = !run.shaders.vertex.empty();
  const FragmentOutputs outputs = OutputsOf(fragment);
  const size_t count = run.inputs.vectors.size();
  const int width = arbvp::kFramebufferWidth;
  const int height = arbvp::FramebufferHeight(count);

  ProgramSpec spec;
  std::vector<Feed> feeds;
  spec.fragment = {run.shaders.fragment};
  if (pair) {
    spec.vertex = PairVertexShaders(run.shaders.vertex);
    spec.attributes = run.inputs.slots;
  } else {
    spec.vertex = {PassThroughShader(run.inputs.slots, fragment, &feeds)};
  }
  const GLuint program = PrepareProgram(run, spec, error);
  if (program == 0) return false;
  std::vector<GLint> feed_locations;
  feed_locations.reserve(feeds.size());
  for (const Feed& feed : feeds) {
    feed_locations.push_back(gl.GetUniformLocation(program, feed.uniform.c_str()));
  }
  const GLint pixel = gl.GetUniformLocation(program, kPixelUniform);

  int attachments = outputs.color ? 1 : 0;
  if (!outputs.data.empty()) attachments = std::max(attachments, outputs.data.back() + 1);
  attachments = std::max(attachments, 1);
  exec::Framebuffer framebuffer(gl);
  bool ok = framebuffer.Create(width, height, attachments, error);
  GLuint depth_stencil = 0;
  if (ok) {
    gl.GenRenderbuffers(1, &depth_stencil);
    gl.BindRenderbuffer(GL_RENDERBUFFER, depth_stencil);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH32F_STENCIL8, width, height);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                               depth_stencil);
    gl.BindRenderbuffer(GL_RENDERBUFFER, 0);
    if (const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
        status != GL_FRAMEBUFFER_COMPLETE) {
      *error = fmt::format(
          "the framebuffer with a DEPTH32F_STENCIL8 buffer is incomplete (0x{:04x})", status);
      ok = false;
    }
  }
  if (ok) {
    // A pair keeps GL's vertex colour clamping (GL 2.0 2.14.6); a fragment shader alone reads
    // its inputs as given.
    gl.ClampColorARB(GL_CLAMP_VERTEX_COLOR_ARB, pair ? GL_TRUE : GL_FALSE);
    gl.ClampColorARB(GL_CLAMP_FRAGMENT_COLOR_ARB, GL_FALSE);
    gl.ClampColorARB(GL_CLAMP_READ_COLOR_ARB, GL_FALSE);
    gl.Disable(GL_VERTEX_PROGRAM_POINT_SIZE);
    framebuffer.Begin(attachments);
    gl.ClearDepth(1.0);
    gl.ClearStencil(0);
    gl.Clear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_ALWAYS);
    gl.DepthMask(GL_TRUE);
    gl.Enable(GL_STENCIL_TEST);
    gl.StencilFunc(GL_ALWAYS, 1, 0xff);
    gl.StencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE);
    gl.Enable(GL_SCISSOR_TEST);
    for (size_t i = 0; i < count; ++i) {
      const auto& v = run.inputs.vectors[i];
      const arbvp::Pixel p = arbvp::FragmentPixel(i);
      gl.Scissor(p.x, p.y, 1, 1);
      const float depth = pair ? 0.5f : Value(v, "gl_FragCoord.z", {0.5f})[0];
      const arbvp::Vec4 clip = exec::PixelClipPosition(i, width, height, depth, run.inputs.state);
      if (pixel >= 0) gl.Uniform4fv(pixel, 1, clip.data());
      for (size_t f = 0; f < feeds.size(); ++f) {
        if (feed_locations[f] < 0) continue;
        UploadUniform(gl, feed_locations[f], feeds[f].type, 1,
                      Value(v, feeds[f].slot, {0, 0, 0, 0}));
      }
      gl.Begin(GL_POINTS);
      if (pair) {
        EmitVertex(gl, run.inputs.slots, v);
      } else {
        gl.Vertex4fv(clip.data());
      }
      gl.End();
    }
    gl.Disable(GL_SCISSOR_TEST);
    gl.Disable(GL_STENCIL_TEST);
    gl.Disable(GL_DEPTH_TEST);
    if (const GLenum code = gl.GetError(); code != GL_NO_ERROR) {
      *error = fmt::format("drawing the fragments raised {}", exec::GlErrorName(code));
      ok = false;
    }
  }
  if (ok) {
    std::vector<std::vector<float>> colors(static_cast<size_t>(attachments));
    for (int a = 0; a < attachments; ++a) framebuffer.Read(a, &colors[static_cast<size_t>(a)]);
    std::vector<float> depths(static_cast<size_t>(width * height), 0.0f);
    std::vector<GLubyte> stencil(static_cast<size_t>(width * height), 0);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.ReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depths.data());
    gl.ReadPixels(0, 0, width, height, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil.data());
    gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
    if (const GLenum code = gl.GetError(); code != GL_NO_ERROR) {
      *error = fmt::format("reading the fragments back raised {}", exec::GlErrorName(code));
      ok = false;
    }
    for (size_t i = 0; ok && i < count; ++i) {
      const arbvp::Pixel p = arbvp::FragmentPixel(i);
      const size_t pixel_index =
          static_cast<size_t>(p.y) * static_cast<size_t>(width) + static_cast<size_t>(p.x);
      GlslVectorResult& result = (*results)[i];
      if (stencil[pixel_index] != 1) {
        result.discarded = true;
        continue;
      }
      auto color = [&](std::string name, int a) {
        const auto& c = colors[static_cast<size_t>(a)];
        result.outputs.push_back(
            {std::move(name), "fragment", "vec4",
             std::vector<float>(c.begin() + static_cast<ptrdiff_t>(pixel_index * 4),
                                c.begin() + static_cast<ptrdiff_t>(pixel_index * 4 + 4))});
      };
      if (outputs.color) color("gl_FragColor", 0);
      for (int n : outputs.data) color(fmt::format("gl_FragData[{}]", n), n);
      if (outputs.depth) {
        result.outputs.push_back({"gl_FragDepth", "fragment", "float", {depths[pixel_index]}});
      }
    }
  }
  if (depth_stencil != 0) {
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);
    gl.DeleteRenderbuffers(1, &depth_stencil);
  }
  gl.UseProgram(0);
  gl.DeleteProgram(program);
  return ok;
}

}  // namespace arbiter::runtime::glsl_exec
