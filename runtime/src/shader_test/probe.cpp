// Probes, with piglit's rules: a channel fails when |observed - expected| > tolerance (per
// channel, 3/256 by default for RGBA8); a rectangle reports its first failing pixel; a
// relative position is scaled by the window and clamped into it.
#include <fmt/format.h>

#include <cmath>

#include "shader_test/session.h"
#include "shader_test/words.h"

namespace arbiter::runtime::shader_test {
namespace {

constexpr float kDepthTolerance = 0.01f;  // piglit_probe_pixel_depth

std::string Values(const float* v, int n) {
  std::string s;
  for (int i = 0; i < n; ++i) s += fmt::format("{}{:.6f}", i ? " " : "", v[i]);
  return s;
}

}  // namespace

void Session::Probe(const std::vector<std::string>& words, bool relative, bool warn) {
  // [all|rect] rgb|rgba position... values...
  size_t i = 0;
  bool all = false;
  bool rect = false;
  if (i < words.size() && words[i] == "all" && !relative) {
    all = true;
    ++i;
  } else if (i < words.size() && words[i] == "rect") {
    rect = true;
    ++i;
  }
  if (i >= words.size() || (words[i] != "rgb" && words[i] != "rgba")) {
    Error("expected 'probe [all|rect] rgb|rgba ...'");
  }
  const int channels = words[i] == "rgba" ? 4 : 3;
  ++i;
  const size_t coords = all ? 0 : rect ? 4 : 2;
  // piglit reads its numbers with sscanf, which ignores what follows them.
  if (words.size() < i + coords + static_cast<size_t>(channels)) {
    Error(fmt::format("this probe takes {} coordinates and {} values", coords, channels));
  }
  int box[4] = {0, 0, window_.width, window_.height};
  if (!all) {
    float c[4] = {0, 0, 1, 1};
    for (size_t k = 0; k < coords; ++k) c[k] = Float(words, i + k);
    if (relative) {
      const auto w = static_cast<float>(window_.width);
      const auto h = static_cast<float>(window_.height);
      box[0] = std::min(static_cast<int>(c[0] * w), window_.width - 1);
      box[1] = std::min(static_cast<int>(c[1] * h), window_.height - 1);
      box[2] = rect ? static_cast<int>(c[2] * w) : 1;
      box[3] = rect ? static_cast<int>(c[3] * h) : 1;
    } else {
      for (size_t k = 0; k < coords; ++k) {
        box[k] = static_cast<int>(c[k]);
        if (static_cast<float>(box[k]) != c[k]) Error("probe coordinates must be integers");
      }
      if (!rect) box[2] = box[3] = 1;
    }
  }
  float expected[4] = {0, 0, 0, 1};
  for (int k = 0; k < channels; ++k)
    expected[k] = Float(words, i + coords + static_cast<size_t>(k));
  if (box[0] < 0 || box[1] < 0 || box[2] < 1 || box[3] < 1 || box[0] + box[2] > window_.width ||
      box[1] + box[3] > window_.height) {
    Error(fmt::format("probe region ({}, {}, {}, {}) is outside the {}x{} window", box[0], box[1],
                      box[2], box[3], window_.width, window_.height));
  }

  std::vector<float> pixels(static_cast<size_t>(box[2]) * static_cast<size_t>(box[3]) * 4);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, window_.framebuffer);
  gl_.ReadBuffer(GL_COLOR_ATTACHMENT0);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_.ReadPixels(box[0], box[1], box[2], box[3], GL_RGBA, GL_FLOAT, pixels.data());
  for (int y = 0; y < box[3]; ++y) {
    for (int x = 0; x < box[2]; ++x) {
      const float* p =
          &pixels[(static_cast<size_t>(y) * static_cast<size_t>(box[2]) + static_cast<size_t>(x)) *
                  4];
      bool ok = true;
      for (int k = 0; k < channels; ++k) {
        // NaN expectations never match, as in piglit.
        if (!(std::fabs(p[k] - expected[k]) <= tolerance_[static_cast<size_t>(k)])) ok = false;
      }
      if (ok) continue;
      ProbeFailed(fmt::format("probe {} at ({}, {}) failed\n  Expected: {}\n  Observed: {}",
                              channels == 4 ? "rgba" : "rgb", box[0] + x, box[1] + y,
                              Values(expected, channels), Values(p, channels)),
                  warn);
      return;
    }
  }
}

void Session::ProbeDepth(const std::vector<std::string>& words) {
  if (words.size() != 3) Error("expected 'probe depth x y d'");
  const int x = Int(words, 0);
  const int y = Int(words, 1);
  const float expected = Float(words, 2);
  if (x < 0 || y < 0 || x >= window_.width || y >= window_.height) {
    Error(fmt::format("probe depth ({}, {}) is outside the window", x, y));
  }
  float depth = 0.0f;
  gl_.BindFramebuffer(GL_FRAMEBUFFER, window_.framebuffer);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_.ReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  if (!(std::fabs(depth - expected) <= kDepthTolerance)) {
    ProbeFailed(
        fmt::format("probe depth at ({}, {}) failed\n  Expected: {:.6f}\n  Observed: {:.6f}", x, y,
                    expected, depth),
        false);
  }
}

}  // namespace arbiter::runtime::shader_test
