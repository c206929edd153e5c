// PrepareShader: #version and #extension read before glslang, and glslang's input made.
#include "prepare.h"

#include <fmt/format.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <mutex>

#include "charset.h"
#include "diag.h"
#include "extensions.h"
#include "scan.h"
#include "source_text.h"

namespace arbiter::glsl {
namespace {

using compiler::SourceFile;

// Every error, not only the first (EShMsgCascadingErrors).
constexpr auto kMessages = static_cast<EShMessages>(EShMsgCascadingErrors);

compiler::Range RangeOf(const Token& t) {
  return {t.offset, static_cast<uint32_t>(t.offset + t.text.size())};
}

// The message for a #version number arbiter does not check (its digits as written).
std::string VersionMessage(std::string_view digits) {
  if (digits.front() == '0') {
    return fmt::format(
        "#version {} is not 110 or 120 (a leading 0 makes an octal number); the shader is "
        "checked as GLSL 1.10",
        digits);
  }
  if (digits.size() < 3 || (digits.size() == 3 && digits < "110")) {
    return fmt::format(
        "#version {} is below 110; GLSL 1.10 requires an error for any number less than 110 "
        "(100 is OpenGL ES); the shader is checked as GLSL 1.10",
        digits);
  }
  return fmt::format(
      "#version {} is not checked: arbiter checks GLSL 1.10 and 1.20 (#version 110 or 120, or "
      "none) and their extensions",
      digits);
}

// Blanks `text` from `begin` to `end` (the line's end), keeping its length and newlines.
void Blank(std::string* text, size_t begin, size_t end) {
  for (size_t i = begin; i < end && i < text->size(); ++i) {
    if ((*text)[i] != '\n') (*text)[i] = ' ';
  }
}

// #version in the first string: sets the version and edits `text` (the first string) where
// glslang must read another number.
void ReadVersion(const SourceFile& file, const std::vector<Directive>& directives,
                 std::string* text, PreparedShader* out, compiler::DiagnosticSink* sink) {
  bool first = true;
  for (const Directive& d : directives) {
    if (d.name != "version") {
      if (d.before_code && d.name.empty() && d.words.empty()) continue;  // a null directive
      first = false;
      continue;
    }
    // A missing or malformed number, or a macro, is glslang's to report (at its position).
    if (d.words.empty() || d.words[0].kind != Token::Number) return;
    const Token& number = d.words[0];
    std::string_view digits = number.text;
    bool all_digits =
        std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!all_digits) return;
    const bool known = digits == "110" || digits == "120";
    if (known && first && d.before_code) {
      out->version = digits == "120" ? 120 : 110;
      return;
    }
    if (known) return;  // too late: glslang says "must occur first"
    sink->Report(Info(Diag::Version), &file, RangeOf(number), VersionMessage(digits));
    const bool above = digits.front() != '0' && (digits.size() > 3 || digits > "120");
    if (above && first && d.before_code) {
      out->checked = false;
      return;
    }
    if (first && d.before_code) {
      // Blank the whole directive, a profile word included: glslang checks as 1.10.
      Blank(text, d.hash, d.end);
    } else if (digits.size() == 3) {
      // Too late anyway: glslang says so ("must occur first") for a "#version 110", where it
      // would take another number as the shader's version (and report that at 1:1).
      text->replace(number.offset, 3, "110");
    }
    return;
  }
}

// The #extension directives of one string: checked against the target's extensions; those
// glslang must not see are blanked in `text`.
void ReadExtensions(const SourceFile& file, const std::vector<Directive>& directives,
                    const CheckOptions& options, std::string* text, PreparedShader* out,
                    compiler::DiagnosticSink* sink) {
  for (const Directive& d : directives) {
    if (d.name != "extension") continue;
    // "#extension name : behavior"; anything else is glslang's to report.
    if (d.words.size() != 3 || d.words[0].kind != Token::Identifier || d.words[1].text != ":" ||
        d.words[2].kind != Token::Identifier) {
      continue;
    }
    std::string_view name = d.words[0].text;
    std::string_view behavior = d.words[2].text;
    if (name == "all") continue;  // glslang applies 3.3's rules for 'all'
    const bool wanted = behavior == "require" || behavior == "enable" || behavior == "warn";
    if (!wanted && behavior != "disable") continue;  // glslang reports the behaviour
    const Extension* extension = FindExtension(name);
    const bool available = extension != nullptr && ProfileHas(options.profile, *extension);
    if (!available) {
      // 3.3: require: "give an error on the #extension if the extension is not supported";
      // enable, warn, disable: "warn on the #extension if the extension is not supported".
      std::string message =
          extension == nullptr
              ? fmt::format("unknown extension '{}': arbiter knows {}", name,
                            ProfileExtensionList(nullptr))
              : fmt::format(
                    "extension '{}' is not supported by the target profile '{}' (it "
                    "has {})",
                    name, options.profile->name, ProfileExtensionList(options.profile));
      sink->Report(Info(Diag::ExtensionUnsupported),
                   behavior == "require" ? compiler::Severity::Error : compiler::Severity::Warning,
                   &file, RangeOf(d.words[0]), std::move(message));
      Blank(text, d.hash, d.end);
      continue;
    }
    switch (extension->support) {
      case ExtensionSupport::Native:
        break;
      case ExtensionSupport::Core:
        Blank(text, d.hash, d.end);
        break;
      case ExtensionSupport::Include:
        Blank(text, d.hash, d.end);
        break;
      case ExtensionSupport::Gpu4:
        Blank(text, d.hash, d.end);
        if (wanted) out->gpu4 = true;
        break;
    }
  }
}

// -D NAME[=VALUE] and -U NAME as preprocessor lines.
std::string DefineLines(const std::vector<std::string>& defines) {
  std::string out;
  for (const std::string& d : defines) {
    if (!d.empty() && d.front() == '-') {
      out += fmt::format("#undef {}\n", d.substr(1));
      continue;
    }
    size_t eq = d.find('=');
    // -D NAME defines NAME as 1, as C compilers and glslangValidator do.
    out += eq == std::string::npos
               ? fmt::format("#define {} 1\n", d)
               : fmt::format("#define {} {}\n", d.substr(0, eq), d.substr(eq + 1));
  }
  return out;
}

}  // namespace

void EnsureGlslang() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

PreparedShader PrepareShader(Stage stage, const std::vector<const SourceFile*>& sources,
                             const CheckOptions& options, compiler::DiagnosticSink* sink) {
  (void)stage;
  PreparedShader out;
  out.files = sources;
  for (size_t i = 0; i < sources.size(); ++i) {
    const SourceFile& file = *sources[i];
    std::string text = ReportInvalidCharacters(file, sink);
    if (text.empty()) text = file.text();
    if (text.find('#') != std::string::npos) {
      const std::string blanked = BlankComments(text);  // the directives view into it
      const std::vector<Directive> directives = Directives(blanked);
      // #version belongs to the first string (3.3: before anything else).
      if (i == 0) ReadVersion(file, directives, &text, &out, sink);
      if (!out.checked) return out;
      ReadExtensions(file, directives, options, &text, &out, sink);
    }
    out.texts.push_back(PrepareForGlslang(text));
  }
  // ARB_texture_rectangle: "the compiler behaves as if #extension GL_ARB_texture_rectangle :
  // require" is present, where the implementation supports the extension.
  const Extension* rectangle = FindExtension("GL_ARB_texture_rectangle");
  if (rectangle != nullptr && ProfileHas(options.profile, *rectangle)) {
    out.preamble += "#extension GL_ARB_texture_rectangle : enable\n";
  }
  out.preamble += DefineLines(options.preprocessor.defines);
  for (char c : out.preamble) out.preamble_generated_lines += c == '\n';
  if (options.preprocessor.preamble != nullptr) {
    out.preamble += PrepareForGlslang(options.preprocessor.preamble->text());
    if (!out.preamble.empty() && out.preamble.back() != '\n') out.preamble += '\n';
  }
  return out;
}

std::unique_ptr<glslang::TShader> ParsePrepared(Stage stage, const PreparedShader& prepared,
                                                bool* parsed) {
  std::vector<const char*> strings;
  std::vector<int> lengths;
  for (const std::string& text : prepared.texts) {
    strings.push_back(text.data());
    lengths.push_back(static_cast<int>(text.size()));
  }
  auto shader =
      std::make_unique<glslang::TShader>(stage == Stage::Vertex ? EShLangVertex : EShLangFragment);
  // No names: glslang would then expand __FILE__ to a file name, where GLSL 1.10 (3.3) says
  // it is the source string number. Messages say "<string>:<line>:".
  shader->setStringsWithLengths(strings.data(), lengths.data(), static_cast<int>(strings.size()));
  if (!prepared.preamble.empty()) shader->setPreamble(prepared.preamble.c_str());
  // A shader without #version is 1.10 desktop (without a default glslang would take such a
  // shader as ES 1.00).
  *parsed = shader->parse(GetDefaultResources(), 110, ENoProfile, false, false, kMessages);
  return shader;
}

}  // namespace arbiter::glsl
