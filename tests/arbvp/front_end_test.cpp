// The front end's fast paths against the slow, obvious ones they replace: number parsing
// against strtof, binding keys against canonical names, and lexical errors reported before
// the parser's however the text is read.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "binding_key.h"
#include "check_fixture.h"

namespace arbiter::arbvp {
namespace {

using ::testing::ElementsAre;

// The value the parser gives one number, as the x of `PARAM c = {number};`.
float ParsedValue(const std::string& number) {
  Checked c = CheckVp("PARAM c = {" + number + "};\nMOV result.position, c;\n");
  EXPECT_NE(c.result.program, nullptr);
  for (const Variable& var : c.result.program->vars) {
    if (var.name == "c") return var.bindings.at(0).value[0];
  }
  ADD_FAILURE() << "no PARAM c for " << number;
  return 0.0f;
}

TEST(FrontEnd, NumbersRoundAsStrtof) {
  const char* numbers[] = {
      "0", "1", "0.1", ".5", "5.", "007", "0000.0001e+0005", "1E3", "2.5e-3",
      // float range edges: largest finite, just past it (rounds down, then overflows)
      "3.4028235e38", "3.40282356e38", "3.4028236e38", "3.5e38", "1e39", "1e999",
      // smallest normal, subnormals, underflow to zero
      "1.17549435e-38", "1.1754942e-38", "1e-40", "1.4e-45", "1e-45", "7e-46", "1e-46", "1e-999",
      // rounding: 2^24 + 1, halfway cases (ties to even), just above halfway
      "16777217", "16777219", "1.000000059604644775390625", "1.0000000596046447753906250001",
      "0.30000000000000004", "123456789012345678901234567890",
      "0.000000000000000000000000000000000000000000001401298464324817"};
  for (const char* n : numbers) {
    float expected = std::strtof(n, nullptr);
    EXPECT_EQ(std::bit_cast<uint32_t>(ParsedValue(n)), std::bit_cast<uint32_t>(expected)) << n;
  }
}

// The parser reads short plain decimals (an integer part and at most ten decimals, below
// 2^24 as digits) by one float division; that shortcut and its edges must round as strtof.
TEST(FrontEnd, ShortDecimalsRoundAsStrtof) {
  std::vector<std::string> numbers = {
      "16777215",      "16777216",     "16777217",    "1677721.5", "0.1234567891",
      "0.12345678912", "0.0000000001", "9999999999.", "123.4567",  "0.3",
      "0.7",           "2.675",        "1.0000001"};
  // A fixed pseudo-random sweep of the shortcut's shape: up to 8 digits, the point anywhere.
  uint32_t state = 12345;
  for (int i = 0; i < 400; ++i) {
    state = state * 1664525u + 1013904223u;
    std::string digits = std::to_string(state % 100000000u);
    const size_t point = (state >> 8) % (digits.size() + 1);
    numbers.push_back(digits.substr(0, point) + "." + digits.substr(point));
  }
  for (const std::string& n : numbers) {
    float expected = std::strtof(n.c_str(), nullptr);
    EXPECT_EQ(std::bit_cast<uint32_t>(ParsedValue(n)), std::bit_cast<uint32_t>(expected)) << n;
  }
}

TEST(FrontEnd, MalformedExponentKeepsItsMantissa) {
  // Reported by the lexer; the value is what strtof reads of it.
  Checked c = CheckVp("PARAM c = {1.5e};\nMOV result.position, c;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:12 arb-lex-bad-number")) << c.Dump();
  ASSERT_NE(c.result.program, nullptr);
  EXPECT_EQ(c.result.program->vars.at(0).bindings.at(0).value[0], 1.5f);
}

TEST(FrontEnd, LexicalErrorsComeBeforeParserErrors) {
  // The parser meets its error on line 2 before the lexer reaches the '@' of line 3, the
  // non-ASCII comment or the '`' after END: the lexer's diagnostics still come first.
  Checked c = CheckVp(
      "MOV result.position, vertex.positon;\nMOV result.color, @vertex.color;\n"
      "# caf\xC3\xA9\nEND\n`\n");
  std::vector<std::string> keys;
  for (const Reported& d : c.diags) keys.push_back(d.code + " " + std::to_string(d.line));
  EXPECT_THAT(keys,
              ElementsAre("arb-lex-invalid-char 3", "arb-lex-non-ascii 4", "arb-lex-invalid-char 6",
                          "arb-binding-unknown 2", "arb-syntax-after-end 7"))
      << c.Dump();
}

// Bindings that differ in every field BindingName may or may not spell.
std::vector<Binding> SampleBindings() {
  std::vector<Binding> out;
  for (int kind = 0; kind <= static_cast<int>(BindingKind::Constant); ++kind) {
    for (int sub = 0; sub <= static_cast<int>(StateItem::MatrixRow); ++sub) {
      for (int index : {0, 1, 4}) {
        for (int variant = 0; variant < 16; ++variant) {
          Binding b;
          b.kind = static_cast<BindingKind>(kind);
          b.vertex_attrib = static_cast<VertexAttrib>(sub % 9);
          b.fragment_attrib = static_cast<FragmentAttrib>(sub % 5);
          b.result = static_cast<ResultReg>(sub % 7);
          b.state = static_cast<StateItem>(sub);
          b.index = index;
          b.face = static_cast<Face>(variant & 1);
          b.secondary = (variant & 2) != 0;
          b.indexed = (variant & 4) != 0;
          b.coord = static_cast<uint8_t>(variant % 4);
          b.matrix = static_cast<MatrixName>((variant + sub) % 6);
          b.modifier = static_cast<MatrixModifier>(variant % 4);
          b.row = static_cast<uint8_t>((variant / 4) % 4);
          float zero = (variant & 8) ? -0.0f : 0.0f;
          b.value = {zero, static_cast<float>(index), variant & 2 ? 0.5f : 1.0f, 1.0f};
          out.push_back(b);
        }
      }
    }
  }
  return out;
}

TEST(FrontEnd, BindingKeysTellApartWhatNamesTellApart) {
  std::vector<Binding> bindings = SampleBindings();
  std::map<std::string, BindingKey> key_of_name;
  std::map<BindingKey, std::string> name_of_key;
  for (const Binding& b : bindings) {
    std::string name = BindingName(b, ProgramKind::Vertex);
    BindingKey key = KeyOf(b);
    auto [by_name, new_name] = key_of_name.emplace(name, key);
    EXPECT_TRUE(by_name->second == key) << name << ": one name, two keys";
    auto [by_key, new_key] = name_of_key.emplace(key, name);
    EXPECT_EQ(by_key->second, name) << "one key, two names";
  }
  EXPECT_GT(key_of_name.size(), 150u);  // the sample is varied
}

TEST(FrontEnd, ParameterKeysEquateNumericallyEqualConstants) {
  Binding zero;
  zero.value = {0.0f, 1.0f, 2.0f, 3.0f};
  Binding negative_zero = zero;
  negative_zero.value[0] = -0.0f;
  EXPECT_FALSE(KeyOf(zero) == KeyOf(negative_zero));  // "{0, ...}" and "{-0, ...}"
  EXPECT_TRUE(KeyOf(zero, /*signed_zero=*/false) == KeyOf(negative_zero, false));
}

}  // namespace
}  // namespace arbiter::arbvp
