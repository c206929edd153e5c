// ARB_fragment_coord_conventions' redeclarations of gl_FragCoord (frag_coord.h). The
// extension's GLSL section (against GLSL 1.40, "4.3.x.1 Input Layout Qualifiers"):
//   "Fragment shaders can have an input layout only for redeclaring the built-in variable
//   gl_FragCoord ... Redeclarations are done as follows
//       in vec4 gl_FragCoord;  // redeclaration that changes nothing is allowed
//       layout(origin_upper_left) in vec4 gl_FragCoord;
//       layout(pixel_center_integer) in vec4 gl_FragCoord;
//       layout(origin_upper_left, pixel_center_integer) in vec4 gl_FragCoord;
//   ... All redeclarations of gl_FragCoord in all fragment shaders in a single program must
//   have the same set of qualifiers. Within any shader, the first redeclarations of
//   gl_FragCoord must appear before any use of gl_FragCoord. The built-in gl_FragCoord is only
//   predeclared in fragment shaders, so redeclaring it in any other shader language will be
//   illegal."
// and 4.3.x: "Declarations of layouts can only be made at global scope"; the identifiers "are
// not case-sensitive". Mesa takes these in GLSL 1.10 and 1.20 with the extension enabled;
// glslang 12 makes 'layout' a keyword for it only from 1.40 and refuses a global 'in' before
// 1.30. A redeclaration leaves gl_FragCoord's type as it is, so glslang need not see it: each
// judged one is blanked. The text is read as written, before macro expansion.
#include "frag_coord.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <set>

#include "conditionals.h"
#include "diag.h"
#include "scan.h"

namespace arbiter::glsl {
namespace {

using compiler::Range;
using compiler::SourceFile;

constexpr std::string_view kExtension = "GL_ARB_fragment_coord_conventions";
constexpr std::string_view kFragCoord = "gl_FragCoord";
constexpr size_t kNone = static_cast<size_t>(-1);

bool EqualsIgnoringCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(b[i]))) {
      return false;
    }
  }
  return true;
}

// The qualifiers of a redeclaration, as a set of bits.
constexpr unsigned kUpperLeft = 1;
constexpr unsigned kPixelCenter = 2;

unsigned QualifierOf(std::string_view id) {
  if (EqualsIgnoringCase(id, "origin_upper_left")) return kUpperLeft;
  if (EqualsIgnoringCase(id, "pixel_center_integer")) return kPixelCenter;
  return 0;
}

// "layout(origin_upper_left)", "no layout qualifier".
std::string Spelled(unsigned qualifiers) {
  switch (qualifiers) {
    case kUpperLeft:
      return "layout(origin_upper_left)";
    case kPixelCenter:
      return "layout(pixel_center_integer)";
    case kUpperLeft | kPixelCenter:
      return "layout(origin_upper_left, pixel_center_integer)";
    default:
      return "no layout qualifier";
  }
}

// Whether the extension is enabled where a token is (#extension, 3.3).
enum class Enabled : uint8_t { No, Yes, Warn, Maybe };

// A token of code that the preprocessor may compile.
struct Tok {
  Token token;
  size_t string;  // the source string it is in
  bool active;    // Reach::Active
  Enabled enabled;
  int depth;      // braces open before it
  bool mentions;  // gl_FragCoord, or a macro whose expansion names it
  bool names;     // gl_FragCoord, or a macro that expands to it alone
};

// `layout ( id [= value], ... )`: the indexes of its tokens.
struct LayoutList {
  size_t close = kNone;
  std::vector<size_t> ids;
  std::vector<size_t> equals;  // per id: its '=', or kNone
  size_t malformed = kNone;    // the first token that is not in the list's grammar
  size_t ours = kNone;         // the first id that is the extension's
};

// Where a diagnostic points.
struct Place {
  const SourceFile* file;
  Range range;
};

// A declaration this pass judges: [layout(...)] storage type name end.
struct Declaration {
  size_t begin;
  std::optional<LayoutList> layout;
  size_t storage;
  size_t type;
  size_t name;
  size_t end;
};

class Redeclarations {
 public:
  Redeclarations(Stage stage, std::span<const SourceFile* const> files, std::string_view preamble,
                 bool available, compiler::DiagnosticSink* sink)
      : stage_(stage),
        files_(files),
        available_(available),
        sink_(sink),
        preamble_(BlankComments(preamble)),
        tracker_("") {
    // The preamble's own directives, #extension included, through this pass's copy.
    for (const Directive& d : Directives(preamble_)) Follow(d);
  }

  // Reads the strings' directives and code, in order.
  void Read(const std::vector<std::string>& texts) {
    blanked_.reserve(texts.size());
    for (const std::string& text : texts) blanked_.push_back(BlankComments(text));
    for (size_t i = 0; i < blanked_.size(); ++i) {
      const std::vector<Token> code = Tokenize(blanked_[i]);
      auto next = code.begin();
      for (const Directive& d : Directives(blanked_[i])) {
        for (; next != code.end() && next->offset < d.hash; ++next) Code(i, *next);
        Follow(d);
      }
      for (; next != code.end(); ++next) Code(i, *next);
    }
  }

  // Judges the declarations read, blanking them in `texts`.
  void Judge(std::vector<std::string>* texts) {
    for (size_t i = 0; i < toks_.size();) {
      if (std::optional<size_t> next = Judge(i, texts)) {
        i = *next;
        continue;
      }
      if (toks_[i].mentions && toks_[i].active && first_use_ == kNone) first_use_ = i;
      ++i;
    }
  }

 private:
  void Follow(const Directive& d) {
    const Reach reach = tracker_.Follow(d).reach;
    if (d.name != "extension" || reach == Reach::Skipped) return;
    if (d.words.size() != 3 || d.words[1].text != ":") return;  // glslang reports it
    std::optional<Enabled> to = Behavior(d.words[0].text, d.words[2].text);
    if (!to) return;
    if (reach == Reach::Active) {
      enabled_ = *to;
    } else if (*to != enabled_) {
      enabled_ = Enabled::Maybe;
    }
  }

  // What "#extension name : behavior" makes of the extension (3.3); nullopt: nothing.
  std::optional<Enabled> Behavior(std::string_view name, std::string_view behavior) const {
    const bool all = name == "all";
    if (!all && name != kExtension) return std::nullopt;
    if (behavior == "disable") return Enabled::No;
    if (!available_) return std::nullopt;  // reported by ReadExtensions (or glslang)
    if (behavior == "warn") return Enabled::Warn;
    if (!all && (behavior == "require" || behavior == "enable")) return Enabled::Yes;
    return std::nullopt;
  }

  void Code(size_t string, const Token& t) {
    const Reach reach = tracker_.reach();
    if (reach == Reach::Skipped) return;
    toks_.push_back(
        {t, string, reach == Reach::Active, enabled_, depth_, Mentions(t), Names(t.text, 0)});
    if (t.text == "{") ++depth_;
    if (t.text == "}" && depth_ > 0) --depth_;
  }

  bool Mentions(const Token& t) const {
    if (t.kind != Token::Identifier) return false;
    std::set<std::string_view> seen;
    return t.text == kFragCoord || MacroNames(t.text, &seen);
  }

  // Whether the macro `name` expands to text naming gl_FragCoord.
  bool MacroNames(std::string_view name, std::set<std::string_view>* seen) const {
    auto it = tracker_.macros().find(name);
    if (it == tracker_.macros().end() || !seen->insert(name).second) return false;
    for (const Token& b : it->second.body) {
      if (b.text == kFragCoord) return true;
      if (b.kind == Token::Identifier && MacroNames(b.text, seen)) return true;
    }
    return false;
  }

  // Whether `text` is gl_FragCoord or an object-like macro that expands to it alone.
  bool Names(std::string_view text, int depth) const {
    if (text == kFragCoord) return true;
    auto it = tracker_.macros().find(text);
    if (it == tracker_.macros().end() || depth > 32) return false;
    const Macro& macro = it->second;
    return !macro.function_like && macro.body.size() == 1 && Names(macro.body[0].text, depth + 1);
  }

  bool IsFragCoord(size_t k) const { return k < toks_.size() && toks_[k].names; }

  bool Is(size_t k, std::string_view text) const {
    return k < toks_.size() && toks_[k].token.text == text;
  }
  bool IsName(size_t k) const {
    return k < toks_.size() && toks_[k].token.kind == Token::Identifier;
  }
  // "'text'" of token `k`; past the last token, "the end of the shader".
  std::string Quoted(size_t k) const {
    return k < toks_.size() ? fmt::format("'{}'", toks_[k].token.text) : "the end of the shader";
  }

  // `layout ( ... )` with '(' at `open`; nullopt when no ')' comes before ';', '{' or '}'.
  std::optional<LayoutList> ReadLayout(size_t open) const {
    LayoutList list;
    bool want_id = true;
    for (size_t k = open + 1; k < toks_.size(); ++k) {
      std::string_view t = toks_[k].token.text;
      if (t == ";" || t == "{" || t == "}") return std::nullopt;
      if (t == ")") {
        if (want_id && !list.ids.empty() && list.malformed == kNone) list.malformed = k;
        list.close = k;
        return list;
      }
      if (list.malformed != kNone) continue;
      if (want_id && IsName(k)) {
        list.ids.push_back(k);
        list.equals.push_back(kNone);
        if (list.ours == kNone && QualifierOf(t) != 0) list.ours = k;
        want_id = false;
      } else if (!want_id && t == ",") {
        want_id = true;
      } else if (!want_id && t == "=" && list.equals.back() == kNone && k + 1 < toks_.size() &&
                 !Is(k + 1, ")")) {
        list.equals.back() = k++;  // the value after it
      } else {
        list.malformed = k;
      }
    }
    return std::nullopt;
  }

  // The declaration starting at `begin` if this pass judges it.
  std::optional<Declaration> Find(size_t begin) const {
    const bool starts =
        begin == 0 || Is(begin - 1, ";") || Is(begin - 1, "{") || Is(begin - 1, "}");
    if (!starts) return std::nullopt;
    const Tok& first = toks_[begin];
    Declaration d{begin, std::nullopt, kNone, kNone, kNone, kNone};
    if (first.token.text == "layout" && Is(begin + 1, "(")) {
      d.layout = ReadLayout(begin + 1);
      if (!d.layout || !IsName(d.layout->close + 1)) return std::nullopt;
      d.storage = d.layout->close + 1;
    } else if (first.token.text == "in" && first.depth == 0 && first.enabled != Enabled::No &&
               IsName(begin + 1) && IsFragCoord(begin + 2)) {
      d.storage = begin;
    } else {
      return std::nullopt;
    }
    d.type = d.storage + 1;
    d.name = d.storage + 2;
    d.end = d.storage + 3;
    // A layout is the extension's when it names one of its identifiers; any layout on
    // gl_FragCoord is judged where the extension may be enabled.
    const bool ours = !d.layout || d.layout->ours != kNone;
    if (!ours && (first.enabled == Enabled::No || !IsFragCoord(d.name))) return std::nullopt;
    return d;
  }

  // The last token of `d`: its ';', else the name (or the shader's last token).
  size_t Last(const Declaration& d) const {
    return Is(d.end, ";") ? d.end : std::min(d.name, toks_.size() - 1);
  }

  std::optional<size_t> Judge(size_t begin, std::vector<std::string>* texts) {
    std::optional<Declaration> found = Find(begin);
    if (!found) return std::nullopt;
    const Declaration& d = *found;
    const size_t last = Last(d);
    const bool shape =
        Is(d.storage, "in") && Is(d.type, "vec4") && IsFragCoord(d.name) && Is(d.end, ";");
    bool sure = true;
    for (size_t k = begin; k <= last; ++k) {
      sure = sure && toks_[k].active && toks_[k].enabled != Enabled::Maybe;
    }
    if (!sure) {
      // Where arbiter cannot tell whether the text is compiled or the extension enabled: a
      // valid redeclaration is hidden, anything else left to glslang.
      if (shape && Valid(d)) Blank(begin, last, texts);
      return last + 1;
    }
    if (Report(d)) Order(d);
    const bool built_in =
        IsName(d.name) && toks_[d.name].token.text.substr(0, 3) == "gl_" && Is(d.end, ";");
    if (shape || built_in) {
      Blank(begin, last, texts);
    } else if (d.layout) {
      Blank(begin, d.layout->close, texts);
    }
    return last + 1;
  }

  // Whether `d`, of the right shape, is allowed where it is.
  bool Valid(const Declaration& d) const {
    const Tok& first = toks_[d.begin];
    if (first.enabled == Enabled::No || stage_ != Stage::Fragment || first.depth > 0) return false;
    if (!d.layout) return true;
    const LayoutList& list = *d.layout;
    if (list.malformed != kNone || list.ids.empty()) return false;
    for (size_t n = 0; n < list.ids.size(); ++n) {
      if (QualifierOf(toks_[list.ids[n]].token.text) == 0 || list.equals[n] != kNone) return false;
    }
    return true;
  }

  // Reports what is wrong with `d` where it stands; true when nothing is.
  bool Report(const Declaration& d) {
    const Tok& first = toks_[d.begin];
    const std::string_view id = d.layout && d.layout->ours != kNone
                                    ? toks_[d.layout->ours].token.text
                                    : std::string_view("layout");
    if (first.enabled == Enabled::No) {
      // Only a layout naming the extension's identifiers is judged without the extension.
      Error(Span(d.begin, d.layout->close),
            available_
                ? fmt::format("layout qualifier '{}' belongs to {}: it needs '#extension {} : "
                              "enable' (or require) before it",
                              id, kExtension, kExtension)
                : fmt::format("layout qualifier '{}' belongs to {}, which the target profile "
                              "does not have",
                              id, kExtension));
      return false;
    }
    if (stage_ != Stage::Fragment) {
      if (IsFragCoord(d.name)) {
        Error(Span(d.name, d.name),
              "gl_FragCoord is a fragment shader input: a vertex shader cannot redeclare it "
              "(GL_ARB_fragment_coord_conventions: it is only predeclared in fragment shaders)");
      } else {
        Error(Span(d.begin, d.layout->close),
              fmt::format("a vertex shader has no input layout qualifiers: '{}' qualifies "
                          "gl_FragCoord, the fragment shader input",
                          id));
      }
      return false;
    }
    if (first.depth > 0) {
      Error(Span(d.begin, d.layout->close),
            fmt::format("a layout qualifier is allowed only at global scope: '{}' qualifies a "
                        "redeclaration of gl_FragCoord before any function",
                        id));
      return false;
    }
    if (!Is(d.storage, "in")) {
      Error(Span(d.storage, d.storage),
            fmt::format("'{}' qualifies only the fragment shader input gl_FragCoord, redeclared "
                        "as 'in vec4 gl_FragCoord;': not a {} declaration",
                        id, Quoted(d.storage)));
      return false;
    }
    if (!IsFragCoord(d.name)) {
      Error(Span(std::min(d.name, toks_.size() - 1), std::min(d.name, toks_.size() - 1)),
            fmt::format("'{}' qualifies only gl_FragCoord, not {}: a fragment shader has an "
                        "input layout only to redeclare gl_FragCoord",
                        id, Quoted(d.name)));
      return false;
    }
    bool ok = !d.layout || CheckLayout(*d.layout);
    if (!Is(d.type, "vec4")) {
      Error(Span(d.type, d.type), fmt::format("gl_FragCoord is a vec4: it is redeclared as 'in "
                                              "vec4 gl_FragCoord;', not as {}",
                                              Quoted(d.type)));
      ok = false;
    } else if (!Is(d.end, ";")) {
      const size_t at = std::min(d.end, toks_.size() - 1);
      Error(Span(at, at), fmt::format("a redeclaration of gl_FragCoord declares it alone: "
                                      "expected ';' after gl_FragCoord, found {}",
                                      Quoted(d.end)));
      ok = false;
    }
    return ok;
  }

  // The identifiers of a layout on gl_FragCoord; true when all are the extension's.
  bool CheckLayout(const LayoutList& list) {
    bool ok = true;
    for (size_t n = 0; n < list.ids.size(); ++n) {
      const size_t k = list.ids[n];
      if (QualifierOf(toks_[k].token.text) == 0) {
        Error(Span(k, k), fmt::format("'{}' is not a layout qualifier of gl_FragCoord: {} has "
                                      "origin_upper_left and pixel_center_integer",
                                      toks_[k].token.text, kExtension));
        ok = false;
      } else if (list.equals[n] != kNone) {
        Error(Span(list.equals[n], list.equals[n] + 1),
              fmt::format("'{}' takes no value", toks_[k].token.text));
        ok = false;
      }
    }
    if (list.malformed != kNone) {
      Error(Span(list.malformed, list.malformed),
            fmt::format("expected {} in the layout qualifier of gl_FragCoord, found {}",
                        list.ids.empty() || Is(list.malformed, ")")
                            ? "origin_upper_left or pixel_center_integer"
                            : "',' or ')'",
                        Quoted(list.malformed)));
      ok = false;
    } else if (list.ids.empty()) {
      Error(Span(list.close, list.close),
            "'layout()' names no qualifier: expected origin_upper_left or pixel_center_integer");
      ok = false;
    }
    return ok;
  }

  // A redeclaration allowed where it stands, against the shader's other redeclarations and
  // uses of gl_FragCoord.
  void Order(const Declaration& d) {
    unsigned qualifiers = 0;
    if (d.layout) {
      for (size_t k : d.layout->ids) qualifiers |= QualifierOf(toks_[k].token.text);
    }
    const Place whole = d.layout ? Span(d.begin, d.layout->close) : Span(d.begin, d.name);
    if (first_ == kNone) {
      first_ = d.begin;
      first_qualifiers_ = qualifiers;
      if (first_use_ != kNone) {
        compiler::Diagnostic* diag =
            Error(Span(d.name, d.name),
                  "gl_FragCoord is redeclared after a use: its first redeclaration must come "
                  "before any use of gl_FragCoord (GL_ARB_fragment_coord_conventions)");
        const Tok& use = toks_[first_use_];
        if (diag != nullptr) {
          const Place place = Span(first_use_, first_use_);
          diag->notes.push_back(
              {place.file, place.range,
               use.token.text == kFragCoord
                   ? std::string("gl_FragCoord is used here")
                   : fmt::format("gl_FragCoord is used here, through macro '{}'", use.token.text)});
        }
      }
    } else if (qualifiers != first_qualifiers_) {
      compiler::Diagnostic* diag =
          Error(whole, fmt::format("gl_FragCoord is redeclared with {} after {}: every "
                                   "redeclaration of gl_FragCoord has the same qualifiers",
                                   Spelled(qualifiers), Spelled(first_qualifiers_)));
      if (diag != nullptr) {
        const Place place = Span(first_, first_);
        diag->notes.push_back({place.file, place.range, "gl_FragCoord is first redeclared here"});
      }
    }
    if (toks_[d.begin].enabled == Enabled::Warn) {
      sink_->Report(Info(Diag::CompileWarning), whole.file, whole.range,
                    fmt::format("{} is used ('#extension {} : warn')", kExtension, kExtension));
    }
  }

  // Tokens `a` to `b` (`a` alone when they are in different strings).
  Place Span(size_t a, size_t b) const {
    const Token& from = toks_[a].token;
    const Token& to = toks_[toks_[b].string == toks_[a].string ? b : a].token;
    return {files_[toks_[a].string],
            {from.offset, static_cast<uint32_t>(to.offset + to.text.size())}};
  }

  compiler::Diagnostic* Error(const Place& at, std::string message) {
    return sink_->Report(Info(Diag::FragCoordRedeclaration), at.file, at.range, std::move(message));
  }

  void Blank(size_t first, size_t last, std::vector<std::string>* texts) const {
    for (size_t k = first; k <= last && k < toks_.size(); ++k) {
      const Token& t = toks_[k].token;
      (*texts)[toks_[k].string].replace(t.offset, t.text.size(), t.text.size(), ' ');
    }
  }

  Stage stage_;
  std::span<const SourceFile* const> files_;
  bool available_;
  compiler::DiagnosticSink* sink_;
  std::string preamble_;              // comment-blanked; the tracker's macros view it
  std::vector<std::string> blanked_;  // each string, comment-blanked; the tokens view them
  GroupTracker tracker_;
  Enabled enabled_ = Enabled::No;
  int depth_ = 0;
  std::vector<Tok> toks_;
  size_t first_use_ = kNone;  // the first use of gl_FragCoord in compiled text
  size_t first_ = kNone;      // the first redeclaration
  unsigned first_qualifiers_ = 0;
};

}  // namespace

bool IsFragCoordLayoutId(std::string_view id) { return QualifierOf(id) != 0; }

void HideFragCoordRedeclarations(Stage stage, std::span<const SourceFile* const> files,
                                 std::string_view preamble, bool available,
                                 std::vector<std::string>* texts, compiler::DiagnosticSink* sink) {
  const bool any = std::any_of(texts->begin(), texts->end(), [](const std::string& text) {
    return text.find("layout") != std::string::npos || text.find(kFragCoord) != std::string::npos;
  });
  if (!any) return;
  Redeclarations redeclarations(stage, files, preamble, available, sink);
  redeclarations.Read(*texts);
  redeclarations.Judge(texts);
}

}  // namespace arbiter::glsl
