// Binding rules: selectors within the implementation's limits, features the implementation
// lacks, conventional/generic attribute aliasing, result.color[n] (ARBvp 2.14.3.1-2.14.3.4,
// ARBfp 3.11.3.1-3.11.3.4, ARB_draw_buffers).
#include <fmt/format.h>

#include <map>

#include "checks.h"

namespace arbiter::arbvp {
namespace {

// Checks a selector `index` (a count of index + 1) against `key`.
void CheckSelector(const CheckContext& ctx, const Binding& b, std::string_view key,
                   std::string_view what) {
  int64_t used = static_cast<int64_t>(b.index) + 1;
  if (used <= QuietLimit(ctx, key, 0)) return;
  CheckLimit(ctx, key, used, 0, Diag::BindingIndexRange, b.selector,
             fmt::format("{} {}", what, b.index));
}

// A feature whose limit is 0 in the enforced profile is not supported at all.
bool Supported(const CheckContext& ctx, std::string_view key) {
  const compiler::LimitProfile* enforced =
      ctx.profile ? ctx.profile : compiler::BuiltinProfile("mesa");
  return enforced->Get(key) > 0;
}

std::string_view EnforcedName(const CheckContext& ctx) {
  return ctx.profile ? std::string_view(ctx.profile->name) : "mesa";
}

void CheckVertexAttrib(const CheckContext& ctx, const Binding& b) {
  switch (b.vertex_attrib) {
    case VertexAttrib::Weight:
    case VertexAttrib::MatrixIndex: {
      bool weight = b.vertex_attrib == VertexAttrib::Weight;
      std::string_view ext = weight ? "ARB_vertex_blend" : "ARB_matrix_palette";
      std::string_view key = weight ? "arbvp.max_vertex_units" : "arbvp.max_palette_matrices";
      if (!Supported(ctx, key)) {
        ctx.Report(
            Diag::BindingUnsupported, b.item,
            fmt::format("'{}' needs {}, which profile '{}' does not support",
                        weight ? "vertex.weight" : "vertex.matrixindex", ext, EnforcedName(ctx)));
        return;
      }
      if (b.index % 4 != 0) {
        ctx.Report(Diag::BindingWeightIndex, b.selector,
                   fmt::format("{} number {} must be a multiple of four",
                               weight ? "weight" : "matrix index", b.index));
        return;
      }
      CheckSelector(ctx, b, "arbvp.max_vertex_units", weight ? "weight" : "matrix index");
      return;
    }
    case VertexAttrib::TexCoord:
      CheckSelector(ctx, b, "arbvp.max_texture_units", "texture coordinate set");
      return;
    case VertexAttrib::Generic:
      CheckSelector(ctx, b, "arbvp.max_vertex_attribs", "generic vertex attribute");
      return;
    case VertexAttrib::Position:
    case VertexAttrib::Normal:
    case VertexAttrib::Color:
    case VertexAttrib::SecondaryColor:
    case VertexAttrib::FogCoord:
      return;
  }
}

void CheckResultBinding(const CheckContext& ctx, const Binding& b) {
  switch (b.result) {
    case ResultReg::TexCoord:
      CheckSelector(ctx, b, "arbvp.max_texture_units", "texture coordinate set");
      return;
    case ResultReg::ClipDistance:
      CheckSelector(ctx, b, "gl.max_clip_planes", "clip plane");
      return;
    case ResultReg::FragColor:
      if (!b.indexed) return;
      if (!ctx.program.HasOption(OptionId::DrawBuffers)) {
        ctx.Report(Diag::OptionRequired, b.selector,
                   fmt::format("'result.color[{}]' needs OPTION ARB_draw_buffers (or ATI's "
                               "ATI_draw_buffers)",
                               b.index));
        return;
      }
      CheckSelector(ctx, b, "arbfp.max_draw_buffers", "draw buffer");
      return;
    case ResultReg::Position:
    case ResultReg::Color:
    case ResultReg::FogCoord:
    case ResultReg::PointSize:
    case ResultReg::FragDepth:
      return;
  }
}

// The selector of a state.matrix binding: matrices of other extensions first need them.
void CheckMatrix(const CheckContext& ctx, const Binding& b) {
  switch (b.matrix) {
    case MatrixName::Modelview:
      if (b.index > 0) {
        if (!Supported(ctx, "arbvp.max_vertex_units")) {
          ctx.Report(Diag::BindingUnsupported, b.selector,
                     fmt::format("'state.matrix.modelview[{}]' needs ARB_vertex_blend, "
                                 "which profile '{}' does not support; only modelview[0] "
                                 "exists",
                                 b.index, EnforcedName(ctx)));
          return;
        }
        CheckSelector(ctx, b, "arbvp.max_vertex_units", "modelview matrix");
      }
      return;
    case MatrixName::Palette:
      if (!Supported(ctx, "arbvp.max_palette_matrices")) {
        ctx.Report(Diag::BindingUnsupported, b.item,
                   fmt::format("'state.matrix.palette' needs ARB_matrix_palette, which "
                               "profile '{}' does not support",
                               EnforcedName(ctx)));
        return;
      }
      CheckSelector(ctx, b, "arbvp.max_palette_matrices", "palette matrix");
      return;
    case MatrixName::Program:
      CheckSelector(ctx, b, "gl.max_program_matrices", "program matrix");
      return;
    case MatrixName::Texture:
      CheckSelector(ctx, b, ctx.vp() ? "arbvp.max_texture_units" : "arbfp.max_texture_coords",
                    "texture matrix");
      return;
    case MatrixName::Projection:
    case MatrixName::Mvp:
      return;
  }
}

// The selector of any other state binding, against its limit in state_items.def.
void CheckState(const CheckContext& ctx, const Binding& b) {
  if (b.state == StateItem::MatrixRow) return CheckMatrix(ctx, b);
  const glstate::StateGroupInfo* group =
      glstate::FindStateGroup(glstate::GetStateItemInfo(b.state).group);
  if (!group || group->selector == glstate::StateSelector::None) return;
  const glstate::StateSelectorInfo& selector = glstate::GetStateSelectorInfo(group->selector);
  CheckSelector(ctx, b, selector.limit, selector.noun);
}

// ARBvp 2.14.3.2: "A vertex program will fail to load if any GL state vector is bound
// multiple times in a single array accessed using relative addressing or bound once in two
// or more arrays accessed using relative addressing."
void CheckRelativeArrayState(const CheckContext& ctx) {
  std::map<std::string, const Binding*> first;
  for (int v : RelativelyAddressed(ctx.program)) {
    const Variable& var = ctx.program.vars[static_cast<size_t>(v)];
    for (const Binding& b : var.bindings) {
      if (b.kind != BindingKind::State && b.kind != BindingKind::ProgramEnv &&
          b.kind != BindingKind::ProgramLocal) {
        continue;
      }
      std::string name = BindingName(b, ctx.program.kind);
      auto [it, fresh] = first.emplace(name, &b);
      if (fresh) continue;
      compiler::Diagnostic* d = ctx.Report(
          Diag::ParamRelativeState, b.range,
          fmt::format("'{}' is bound again in an array accessed with relative addressing; such "
                      "arrays may bind each state vector only once, in one array",
                      name));
      if (d) d->notes.push_back({&ctx.source, it->second->range, "first bound here"});
    }
  }
}

}  // namespace

std::set<int> RelativelyAddressed(const Program& program) {
  std::set<int> vars;
  for (const Instruction& inst : program.instructions) {
    for (size_t s = 0; s < inst.src_count; ++s) {
      if (inst.src[s].relative) vars.insert(inst.src[s].var);
    }
  }
  return vars;
}

void CheckBindings(const CheckContext& ctx) {
  CheckRelativeArrayState(ctx);
  // First binding of each generic slot, by conventional (0) and generic (1) spelling.
  std::map<int, const Binding*> seen[2];
  for (const Variable& var : ctx.program.vars) {
    // A relatively addressed attribute or result array binds no element of its own: its
    // index is the address register's, checked when the program runs.
    if (var.relative_array) continue;
    for (size_t i = 0; i < var.bindings.size(); ++i) {
      const Binding& b = var.bindings[i];
      // A range (program.env[a..b], a matrix's rows) expands to consecutive bindings of one
      // text: check only its last, which carries the largest selector.
      if (i + 1 < var.bindings.size() && var.bindings[i + 1].range.begin == b.range.begin) {
        continue;
      }
      switch (b.kind) {
        case BindingKind::VertexAttrib: {
          CheckVertexAttrib(ctx, b);
          bool generic = b.vertex_attrib == VertexAttrib::Generic;
          int slot = GenericAttribSlot(b);
          if (slot < 0) break;
          seen[generic ? 1 : 0].try_emplace(slot, &b);
          auto other = seen[generic ? 0 : 1].find(slot);
          if (other != seen[generic ? 0 : 1].end()) {
            compiler::Diagnostic* d = ctx.Report(
                Diag::BindingAttribAlias, b.range,
                fmt::format("'{}' aliases '{}', which the program also binds; a program may not "
                            "bind both a conventional attribute and its generic attribute",
                            BindingName(b, ctx.program.kind),
                            BindingName(*other->second, ctx.program.kind)));
            if (d) d->notes.push_back({&ctx.source, other->second->range, "also bound here"});
          }
          break;
        }
        case BindingKind::FragmentAttrib:
          if (b.fragment_attrib == FragmentAttrib::TexCoord) {
            CheckSelector(ctx, b, "arbfp.max_texture_coords", "texture coordinate set");
          }
          break;
        case BindingKind::Result:
          CheckResultBinding(ctx, b);
          break;
        case BindingKind::State:
          CheckState(ctx, b);
          break;
        case BindingKind::ProgramEnv:
          CheckSelector(ctx, b, ctx.StageKey("max_env_parameters"), "program.env parameter");
          break;
        case BindingKind::ProgramLocal:
          CheckSelector(ctx, b, ctx.StageKey("max_local_parameters"), "program.local parameter");
          break;
        case BindingKind::Constant:
          break;
      }
    }
  }
}

}  // namespace arbiter::arbvp
