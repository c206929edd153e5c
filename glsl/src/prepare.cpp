// PrepareShader: #version and #extension read before glslang, and glslang's input made.
#include "prepare.h"

#include <fmt/format.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <mutex>

#include "charset.h"
#include "diag.h"
#include "extensions.h"
#include "frag_coord.h"
#include "function_names.h"
#include "gpu4_preamble.h"
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
      out->version_offset = number.offset;
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
void ReadExtensions(Stage stage, const SourceFile& file, const std::vector<Directive>& directives,
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
    // A name outside the table is glslang's to judge: it enables the extensions it implements
    // (Mesa has more than the table lists) and reports the others ("extension not supported",
    // glsl-extension-unsupported in info_log.cpp), in the #if groups it compiles only.
    if (extension == nullptr) continue;
    if (!available) {
      // 3.3: require: "give an error on the #extension if the extension is not supported";
      // enable, warn, disable: "warn on the #extension if the extension is not supported".
      std::string message =
          fmt::format("extension '{}' is not supported by the target profile '{}' (it has {})",
                      name, options.profile != nullptr ? options.profile->name : "mesa",
                      ProfileExtensionList(options.profile));
      sink->Report(Info(Diag::ExtensionUnsupported),
                   behavior == "require" ? compiler::Severity::Error : compiler::Severity::Warning,
                   &file, RangeOf(d.words[0]), std::move(message));
      Blank(text, d.hash, d.end);
      continue;
    }
    if (wanted && stage == Stage::Vertex) out->enabled_preamble += extension->vertex_preamble;
    switch (extension->support) {
      case ExtensionSupport::Native:
        break;
      case ExtensionSupport::Core:
        Blank(text, d.hash, d.end);
        break;
      case ExtensionSupport::Include:
        Blank(text, d.hash, d.end);
        if (wanted) out->include = true;
        break;
      case ExtensionSupport::Gpu4:
        Blank(text, d.hash, d.end);
        if (wanted && name == "GL_EXT_gpu_shader4") out->gpu_shader4 = true;
        if (wanted && name == "GL_EXT_texture_array") out->texture_array = true;
        break;
    }
  }
}

// GLSL 1.30 spellings of EXT_gpu_shader4's words, same length: "unsigned int" is "uint", and
// a fragment shader's "varying out" is "out" (1.30 takes neither).
void RewriteGpu4Words(Stage stage, std::string* text) {
  const std::vector<Token> tokens = Tokenize(*text);
  for (size_t i = 0; i + 1 < tokens.size(); ++i) {
    const Token& t = tokens[i];
    const Token& next = tokens[i + 1];
    if (t.text == "unsigned" && next.text == "int") {
      text->replace(t.offset, t.text.size(), "uint    ");
      Blank(text, next.offset, next.offset + next.text.size());
    } else if (stage == Stage::Fragment && t.text == "varying" && next.text == "out") {
      Blank(text, t.offset, t.offset + t.text.size());
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
  PreparedShader out;
  out.files = sources;
  std::vector<std::string> strings;  // the user's offsets: rewritten once the preamble is made
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
      ReadExtensions(stage, file, directives, options, &text, &out, sink);
    }
    strings.push_back(std::move(text));
  }
  // ARB_texture_rectangle: "the compiler behaves as if #extension GL_ARB_texture_rectangle :
  // require" is present, where the implementation supports the extension.
  const Extension* rectangle = FindExtension("GL_ARB_texture_rectangle");
  const bool has_rectangle = rectangle != nullptr && ProfileHas(options.profile, *rectangle);
  if (has_rectangle) out.preamble += "#extension GL_ARB_texture_rectangle : enable\n";
  // glslang's `defined` does not see its built-in macros (`#if defined __VERSION__` is false);
  // the same name as an ordinary macro makes it true, and glslang still expands its own.
  out.preamble += fmt::format("#define __VERSION__ {}\n", out.version);
  // 3.3: each supported extension defines a macro of its name (glslang defines some of those
  // it knows, as 1 too: an identical definition is no redefinition).
  for (const Extension& e : KnownExtensions()) {
    if (ProfileHas(options.profile, e)) {
      out.preamble += fmt::format("#define {} 1\n", e.name);
    }
  }
  if (out.gpu4()) {
    out.preamble +=
        Gpu4Preamble(stage == Stage::Vertex, out.gpu_shader4, out.texture_array, has_rectangle);
    if (out.gpu_shader4) {
      // The built-in variables glslang's 1.30 lacks: the vertex shader's gl_InstanceID (1.40)
      // and the fragment shader's gl_PrimitiveID (1.50): read-only ints, whose values a check
      // never needs.
      out.preamble += stage == Stage::Vertex ? "#define gl_InstanceID (int(0))\n"
                                             : "#define gl_PrimitiveID (int(0))\n";
    }
  }
  if (out.include) {
    // glslang reads #include (and #line with a file name) under its own extension's name.
    out.preamble += "#extension GL_GOOGLE_include_directive : enable\n";
    out.include_dirs = options.preprocessor.include_dirs;
  }
  out.preamble += out.enabled_preamble;
  out.preamble += DefineLines(options.preprocessor.defines);
  for (char c : out.preamble) out.preamble_generated_lines += c == '\n';
  if (options.preprocessor.preamble != nullptr) {
    out.preamble_file = options.preprocessor.preamble;
    out.preamble += PrepareForGlslang(options.preprocessor.preamble->text());
    if (!out.preamble.empty() && out.preamble.back() != '\n') out.preamble += '\n';
  }
  // The conditional groups of the strings follow the preamble's macros.
  const Extension* frag_coord = FindExtension("GL_ARB_fragment_coord_conventions");
  HideFragCoordRedeclarations(stage, sources, out.preamble,
                              frag_coord != nullptr && ProfileHas(options.profile, *frag_coord),
                              &strings, sink);
  for (const std::string& text : strings) out.texts.push_back(PrepareForGlslang(text));
  if (out.gpu4()) {
    if (out.version_offset != std::string::npos) {
      out.texts.front().replace(out.version_offset, 3, "130");
    }
    for (std::string& text : out.texts) RewriteGpu4Words(stage, &text);
  }
  // 1.20 4.2 puts functions in the name space of variables; 1.10 gives them their own.
  if (out.version == 110) {
    std::vector<std::string*> texts;
    for (std::string& text : out.texts) texts.push_back(&text);
    texts.push_back(&out.preamble);
    out.renames = SeparateFunctionNames(texts);
  }
  return out;
}

namespace {

// ARB_shading_language_include on files: a name is looked up from the including file's
// directory, then in each -I directory ("/a/b.glsl" is relative to those roots).
class FileIncluder : public glslang::TShader::Includer {
 public:
  static constexpr size_t kMaxIncludeDepth = 64;

  explicit FileIncluder(PreparedShader* prepared) : prepared_(prepared) {}

  IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override {
    if (TooDeep(header, depth)) return nullptr;
    std::string name(header);
    if (!name.empty() && name.front() != '/') {
      const SourceFile* from = IncludedFile(*prepared_, includer);
      if (from == nullptr) from = prepared_->files.front();
      if (IncludeResult* r = Open(DirectoryOf(from->path()) + name)) return r;
    }
    return includeSystem(header, includer, 0);
  }

  IncludeResult* includeSystem(const char* header, const char*, size_t depth) override {
    if (TooDeep(header, depth)) return nullptr;
    std::string name(header);
    while (!name.empty() && name.front() == '/') name.erase(0, 1);
    for (const std::string& dir : prepared_->include_dirs) {
      std::string path = dir.empty() || dir.back() == '/' ? dir + name : dir + "/" + name;
      if (IncludeResult* r = Open(path)) return r;
    }
    return nullptr;
  }

  void releaseInclude(IncludeResult* result) override { delete result; }

 private:
  // An include cycle (a file that includes itself, directly or not) would never end: past
  // kMaxIncludeDepth nested includes the include fails, and says why.
  bool TooDeep(const char* header, size_t depth) {
    if (depth <= kMaxIncludeDepth) return false;
    prepared_->include_failures[header] = fmt::format(
        "#include nested more than {} deep (a file that includes itself?)", kMaxIncludeDepth);
    return true;
  }

  static std::string DirectoryOf(const std::string& path) {
    size_t slash = path.rfind('/');
    return slash == std::string::npos ? "" : path.substr(0, slash + 1);
  }

  IncludeResult* Open(const std::string& path) {
    std::string bytes;
    std::string error;
    if (!compiler::ReadFileBytes(path, &bytes, &error)) return nullptr;
    auto file = std::make_unique<SourceFile>(path, std::move(bytes));
    const SourceFile* kept = file.get();
    prepared_->included.push_back(std::move(file));
    // glslang keeps the pointer until the string is read; the file lives in `prepared`.
    return new IncludeResult(path, kept->text().data(), kept->text().size(), nullptr);
  }

  PreparedShader* prepared_;
};

}  // namespace

const SourceFile* IncludedFile(const PreparedShader& prepared, std::string_view name) {
  for (const auto& file : prepared.included) {
    if (file->path() == name) return file.get();
  }
  return nullptr;
}

std::unique_ptr<glslang::TShader> ParsePrepared(Stage stage, PreparedShader* prepared,
                                                bool* parsed) {
  std::vector<const char*> strings;
  std::vector<int> lengths;
  for (const std::string& text : prepared->texts) {
    strings.push_back(text.data());
    lengths.push_back(static_cast<int>(text.size()));
  }
  auto shader =
      std::make_unique<glslang::TShader>(stage == Stage::Vertex ? EShLangVertex : EShLangFragment);
  // No names: glslang would then expand __FILE__ to a file name, where GLSL 1.10 (3.3) says
  // it is the source string number. Messages say "<string>:<line>:".
  shader->setStringsWithLengths(strings.data(), lengths.data(), static_cast<int>(strings.size()));
  if (!prepared->preamble.empty()) shader->setPreamble(prepared->preamble.c_str());
  FileIncluder includer(prepared);
  // A shader without #version is 1.10 desktop (without a default glslang would take such a
  // shader as ES 1.00); EXT_gpu_shader4 and EXT_texture_array: 1.30 (PreparedShader::gpu4).
  *parsed = shader->parse(GetDefaultResources(), prepared->gpu4() ? 130 : 110, ENoProfile, false,
                          false, kMessages, includer);
  return shader;
}

}  // namespace arbiter::glsl
