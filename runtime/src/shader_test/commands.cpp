// The [test] commands: one table from the command's leading words to its handler, piglit's
// spelling first, then arbiter's extensions (docs/run.md). The longest match wins.
#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "shader_test/session.h"
#include "shader_test/words.h"

namespace arbiter::runtime::shader_test {
void Session::Execute(const ShaderTestLine& command) {
  using Args = std::vector<std::string>;
  using Handler = void (*)(Session*, const Args&);
  struct Entry {
    std::string_view words;  // the command's leading words
    Handler run;             // gets the words after them
  };
  static const std::vector<Entry> kCommands = [] {
    std::vector<Entry> table = {
        {"clear color",
         [](Session* s, const Args& a) {
           if (a.size() != 4) s->Error("expected 'clear color r g b a'");
           s->gl_.ClearColor(s->Float(a, 0), s->Float(a, 1), s->Float(a, 2), s->Float(a, 3));
         }},
        {"clear depth",
         [](Session* s, const Args& a) {
           if (a.size() != 1) s->Error("expected 'clear depth d'");
           s->gl_.ClearDepth(static_cast<double>(s->Float(a, 0)));
         }},
        {"clear",
         [](Session* s, const Args& a) {
           if (!a.empty()) s->Error("expected 'clear'");
           s->gl_.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
         }},
        {"color",
         [](Session* s, const Args& a) {
           if (a.size() != 4) s->Error("expected 'color r g b a'");
           const float v[4] = {s->Float(a, 0), s->Float(a, 1), s->Float(a, 2), s->Float(a, 3)};
           s->gl_.Color4fv(v);
         }},
        {"enable",
         [](Session* s, const Args& a) {
           if (a.size() != 1) s->Error("expected 'enable GL_CAP'");
           if (!s->EnableIsUniform(s->Enum(a[0]))) s->gl_.Enable(s->Enum(a[0]));
         }},
        {"disable",
         [](Session* s, const Args& a) {
           if (a.size() != 1) s->Error("expected 'disable GL_CAP'");
           if (!s->EnableIsUniform(s->Enum(a[0]))) s->gl_.Disable(s->Enum(a[0]));
         }},
        {"depthfunc",
         [](Session* s, const Args& a) {
           if (a.size() != 1) s->Error("expected 'depthfunc GL_LESS'");
           s->gl_.DepthFunc(s->Enum(a[0]));
         }},
        {"shade model",
         [](Session* s, const Args& a) {
           if (a.size() != 1 || (a[0] != "smooth" && a[0] != "flat")) {
             s->Error("expected 'shade model smooth' or 'shade model flat'");
           }
           s->gl_.ShadeModel(a[0] == "flat" ? GL_FLAT : GL_SMOOTH);
         }},
        {"clip plane",
         [](Session* s, const Args& a) {
           if (a.size() != 5) s->Error("expected 'clip plane i a b c d'");
           const int i = s->Int(a, 0);
           if (i < 0 || i >= 8) s->Error(fmt::format("clip plane {} out of range", i));
           double p[4];
           for (size_t k = 0; k < 4; ++k) p[k] = static_cast<double>(s->Float(a, k + 1));
           s->gl_.ClipPlane(static_cast<GLenum>(GL_CLIP_PLANE0 + i), p);
         }},
        {"texcoord",
         [](Session* s, const Args& a) {
           if (a.size() != 5) s->Error("expected 'texcoord unit (s, t, r, q)'");
           const int unit = s->Int(a, 0);
           if (unit < 0 || unit >= 8) s->Error(fmt::format("texture unit {} out of range", unit));
           const float v[4] = {s->Float(a, 1), s->Float(a, 2), s->Float(a, 3), s->Float(a, 4)};
           s->gl_.MultiTexCoord4fv(static_cast<GLenum>(GL_TEXTURE0 + unit), v);
         }},
        {"ortho",
         [](Session* s, const Args& a) {
           double box[4] = {0.0, static_cast<double>(s->window_.width), 0.0,
                            static_cast<double>(s->window_.height)};
           if (a.size() == 4) {
             for (size_t i = 0; i < 4; ++i) box[i] = static_cast<double>(s->Float(a, i));
           } else if (!a.empty()) {
             s->Error("expected 'ortho' or 'ortho left right bottom top'");
           }
           s->gl_.MatrixMode(GL_PROJECTION);
           s->gl_.LoadIdentity();
           s->gl_.Ortho(box[0], box[1], box[2], box[3], -1.0, 1.0);
           s->gl_.MatrixMode(GL_MODELVIEW);
           s->gl_.LoadIdentity();
         }},
        {"frustum",
         [](Session* s, const Args& a) {
           if (a.size() != 6) s->Error("expected 'frustum left right bottom top near far'");
           double f[6];
           for (size_t i = 0; i < 6; ++i) f[i] = static_cast<double>(s->Float(a, i));
           s->gl_.MatrixMode(GL_PROJECTION);
           s->gl_.LoadIdentity();
           s->gl_.Frustum(f[0], f[1], f[2], f[3], f[4], f[5]);
           s->gl_.MatrixMode(GL_MODELVIEW);
           s->gl_.LoadIdentity();
         }},
        {"draw rect",
         [](Session* s, const Args& a) {
           if (a.size() != 4) s->Error("expected 'draw rect x y w h'");
           s->DrawRect(s->Float(a, 0), s->Float(a, 1), s->Float(a, 2), s->Float(a, 3), nullptr);
         }},
        {"draw rect ortho",
         [](Session* s, const Args& a) {
           if (a.size() != 4) s->Error("expected 'draw rect ortho x y w h'");
           const auto w = static_cast<float>(s->window_.width);
           const auto h = static_cast<float>(s->window_.height);
           s->DrawRect(-1.0f + 2.0f * s->Float(a, 0) / w, -1.0f + 2.0f * s->Float(a, 1) / h,
                       2.0f * s->Float(a, 2) / w, 2.0f * s->Float(a, 3) / h, nullptr);
         }},
        {"draw rect tex",
         [](Session* s, const Args& a) {
           if (a.size() != 8) s->Error("expected 'draw rect tex x y w h tx ty tw th'");
           const float tex[4] = {s->Float(a, 4), s->Float(a, 5), s->Float(a, 6), s->Float(a, 7)};
           s->DrawRect(s->Float(a, 0), s->Float(a, 1), s->Float(a, 2), s->Float(a, 3), tex);
         }},
        {"draw arrays", [](Session* s, const Args& a) { s->DrawArrays(a); }},
        {"probe", [](Session* s, const Args& a) { s->Probe(a, false, false); }},
        {"probe warn", [](Session* s, const Args& a) { s->Probe(a, false, true); }},
        {"relative probe", [](Session* s, const Args& a) { s->Probe(a, true, false); }},
        {"probe depth", [](Session* s, const Args& a) { s->ProbeDepth(a); }},
        {"tolerance",
         [](Session* s, const Args& a) {
           if (a.size() != 1 && a.size() != 4) s->Error("expected 'tolerance t0 t1 t2 t3'");
           for (size_t i = 0; i < 4; ++i) s->tolerance_[i] = s->Float(a, a.size() == 1 ? 0 : i);
         }},
        {"parameter", [](Session* s, const Args& a) { s->SetParameter(a); }},
        {"uniform", [](Session* s, const Args& a) { s->SetUniform(a); }},
        {"texture", [](Session* s, const Args& a) { s->Texture(a); }},
        {"texparameter", [](Session* s, const Args& a) { s->TexParameter(a); }},
        {"link error",
         [](Session* s, const Args& a) {
           if (!a.empty()) s->Error("expected 'link error'");
           if (s->link_ok_)
             s->ProbeFailed("a link error was expected, but the program links", false);
         }},
        {"link success",
         [](Session* s, const Args& a) {
           if (!a.empty()) s->Error("expected 'link success'");
           if (!s->link_ok_)
             s->ProbeFailed("the program was expected to link, but it does not", false);
         }},
        {"hint",
         [](Session* s, const Args& a) {
           if (a.size() != 2) s->Error("expected 'hint GL_TARGET GL_MODE'");
           s->gl_.Hint(s->Enum(a[0]), s->Enum(a[1]));
         }},
        // light, and arbiter's material / lightmodel / fog / texenv: GL state set with
        // the matching glXxxfv call.
        {"light", [](Session* s, const Args& a) { s->SetState("light", a); }},
        {"material", [](Session* s, const Args& a) { s->SetState("material", a); }},
        {"lightmodel", [](Session* s, const Args& a) { s->SetState("lightmodel", a); }},
        {"fog", [](Session* s, const Args& a) { s->SetState("fog", a); }},
        {"texenv", [](Session* s, const Args& a) { s->SetState("texenv", a); }},
        {"matrix", [](Session* s, const Args& a) { s->SetState("matrix", a); }},
        {"depthrange",
         [](Session* s, const Args& a) {
           if (a.size() != 2) s->Error("expected 'depthrange near far'");
           s->gl_.DepthRange(static_cast<double>(s->Float(a, 0)),
                             static_cast<double>(s->Float(a, 1)));
         }},
    };
    // Longest first, so that "draw rect tex" is not taken for "draw rect".
    std::stable_sort(table.begin(), table.end(), [](const Entry& x, const Entry& y) {
      return std::count(x.words.begin(), x.words.end(), ' ') >
             std::count(y.words.begin(), y.words.end(), ' ');
    });
    return table;
  }();

  const std::vector<std::string> words = Words(command.text);
  if (words.empty()) return;
  for (const Entry& entry : kCommands) {
    std::vector<std::string> lead = Words(entry.words);
    if (words.size() < lead.size() || !std::equal(lead.begin(), lead.end(), words.begin())) {
      continue;
    }
    const Args args(words.begin() + static_cast<std::ptrdiff_t>(lead.size()), words.end());
    entry.run(this, args);
    TrackState(std::string(entry.words), args);  // the same state in state_ (--translate)
    return;
  }
  Error(fmt::format("unknown command '{}'", command.text));
}

}  // namespace arbiter::runtime::shader_test
