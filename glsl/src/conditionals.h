// The conditional groups of a shader (#if, #ifdef, #ifndef, #elif, #else, #endif) followed as
// a preprocessor does, over the preamble and then the source strings in order: which text is
// compiled, which is skipped, and which arbiter cannot tell; and the macros defined at each
// point. The one group tracker of the rules that read the text (strict_conditionals,
// strict_arrays, strict_preprocessor) and of info_log's line continuations.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "scan.h"

namespace arbiter::glsl {

// Whether a preprocessor processes some text.
enum class Reach : uint8_t {
  Active,   // compiled: the branch of every enclosing group is taken
  Skipped,  // in a branch known not taken: only its conditionals are followed (C++ 16.1)
  Unknown,  // in a branch whose condition arbiter cannot evaluate: a function-like macro, a
            // GL_ name the implementation may define, a macro (un)defined in such a branch
};

struct Macro {
  bool function_like = false;
  bool unsure = false;      // defined or undefined where the reach is Unknown: value unknown
  std::vector<Token> body;  // the tokens after the name, as written
};
using MacroTable = std::map<std::string, Macro, std::less<>>;

// What following one directive found.
struct FollowedDirective {
  // Of the directive itself: Active when a preprocessor processes it. A conditional that
  // continues or closes a group (#elif, #else, #endif) has the reach of the group's parent.
  Reach reach = Reach::Active;
  // An #if or #elif that a preprocessor surely evaluates (Active, no earlier branch of its
  // group taken or perhaps taken): the identifiers of its expression that are neither macros
  // nor operands of 'defined', which glslang takes as 0. A token from a macro's body is
  // placed at the macro's name.
  std::vector<Token> undefined;
};

// Follows a shader's directives in text order. Macros view the text of the directives that
// defined them, which must outlive the tracker.
class GroupTracker {
 public:
  // Starts by following `preamble`'s directives (-D, -U, --preamble: what glslang reads
  // before the shader's first line; prepare.h). The tracker keeps its own copy.
  explicit GroupTracker(std::string_view preamble);
  GroupTracker(const GroupTracker&) = delete;
  GroupTracker& operator=(const GroupTracker&) = delete;

  // Follows the next directive of the shader (Directives of a comment-blanked text).
  FollowedDirective Follow(const Directive& d);

  // The reach of the text after the directives followed so far.
  Reach reach() const { return groups_.empty() ? Reach::Active : groups_.back().reach; }
  // The macros defined so far.
  const MacroTable& macros() const { return macros_; }
  // Whether `name`, which is not in macros(), may still be a macro: one the implementation
  // defines (a GL_ name), or one of a file an #include read.
  bool MaybeMacro(std::string_view name) const;

 private:
  enum class Truth : uint8_t { False, True, Unknown };
  struct Group {
    Reach parent;  // the reach of the text around the group
    Reach reach;   // of the current branch's text
    bool taken;    // a branch is known taken
    bool maybe;    // a branch may have been taken (its condition unknown)
  };

  void Open(const Directive& d, FollowedDirective* out);
  void Continue(const Directive& d, FollowedDirective* out);
  void Define(const Directive& d);
  Truth Defined(std::string_view name) const;
  Truth Evaluate(std::span<const Token> words, bool report, FollowedDirective* out) const;
  class Condition;  // the #if expression evaluator (conditionals.cpp)

  std::string preamble_;  // comment-blanked; preamble macros view it
  MacroTable macros_;
  std::vector<Group> groups_;
  bool included_ = false;  // an #include was followed where the reach is not Skipped
};

// The reach of every part of a shader's source strings, followed once.
class ShaderReach {
 public:
  // `texts` are the source strings, in order, as written (comments are blanked here).
  ShaderReach(std::string_view preamble, std::span<const std::string_view> texts);

  // The reach at `offset` of texts[index]: on a directive's line from its '#', the directive's.
  Reach At(size_t index, uint32_t offset) const;

 private:
  // Per text: from each offset on, the reach (the first entry is at offset 0).
  std::vector<std::vector<std::pair<uint32_t, Reach>>> changes_;
};

}  // namespace arbiter::glsl
