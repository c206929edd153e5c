// Option rules: stage, mutually exclusive groups, repetition (ARBvp 2.14.4.5, ARBfp 3.11.4.5).
#include <fmt/format.h>

#include "checks.h"

namespace arbiter::arbvp {

void CheckProgramOptions(const CheckContext& ctx) {
  const auto& options = ctx.program.options;
  for (size_t i = 0; i < options.size(); ++i) {
    const Option& option = options[i];
    const OptionInfo& info = GetOptionInfo(option.id);
    bool in_stage = (static_cast<unsigned>(info.stages) & (ctx.vp() ? 1u : 2u)) != 0;
    if (!in_stage) {
      ctx.Report(Diag::OptionStage, option.range,
                 fmt::format("option '{}' is for {} programs only", info.spelling,
                             ctx.vp() ? "fragment" : "vertex"));
      continue;
    }
    for (size_t j = 0; j < i; ++j) {
      const OptionInfo& earlier = GetOptionInfo(options[j].id);
      if (options[j].id == option.id) {
        compiler::Diagnostic* d =
            ctx.Report(Diag::OptionRepeated, option.range,
                       fmt::format("option '{}' is given twice", info.spelling));
        if (d) d->notes.push_back({&ctx.source, options[j].range, "first given here"});
        break;
      }
      if (!info.group.empty() && earlier.group == info.group) {
        compiler::Diagnostic* d = ctx.Report(
            Diag::OptionConflict, option.range,
            fmt::format("option '{}' conflicts with '{}': a program may specify only one {} "
                        "option",
                        info.spelling, earlier.spelling,
                        info.group == "fog" ? "fog" : "precision hint"));
        if (d)
          d->notes.push_back(
              {&ctx.source, options[j].range, fmt::format("'{}' given here", earlier.spelling)});
        break;
      }
    }
  }
}

}  // namespace arbiter::arbvp
