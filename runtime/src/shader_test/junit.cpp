// JunitXml: the results as JUnit XML (the schema CI systems read: testsuite, testcase,
// failure, skipped), escaped, without timings so that the file is deterministic.
#include <fmt/format.h>

#include "arbiter/runtime/shader_test.h"

namespace arbiter::runtime {
namespace {

std::string Escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        // XML 1.0 forbids most control characters even escaped.
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t' && c != '\r') {
          out += '?';
        } else {
          out += c;
        }
    }
  }
  return out;
}

}  // namespace

std::string JunitXml(const std::vector<ShaderTestResult>& results, const std::string& suite) {
  size_t failures = 0, skipped = 0;
  for (const ShaderTestResult& r : results) {
    failures += r.status == TestStatus::Fail ? 1 : 0;
    skipped += r.status == TestStatus::Skip ? 1 : 0;
  }
  std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml += fmt::format("<testsuites tests=\"{0}\" failures=\"{1}\" skipped=\"{2}\">\n",
                     results.size(), failures, skipped);
  xml += fmt::format("  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" skipped=\"{}\">\n",
                     Escape(suite), results.size(), failures, skipped);
  for (const ShaderTestResult& r : results) {
    const size_t slash = r.path.rfind('/');
    const std::string dir = slash == std::string::npos ? "." : r.path.substr(0, slash);
    const std::string name = slash == std::string::npos ? r.path : r.path.substr(slash + 1);
    xml += fmt::format("    <testcase classname=\"{}\" name=\"{}\"", Escape(dir), Escape(name));
    if (r.status == TestStatus::Pass) {
      xml += "/>\n";
      continue;
    }
    xml += ">\n";
    const std::string first = r.message.substr(0, r.message.find('\n'));
    if (r.status == TestStatus::Skip) {
      xml += fmt::format("      <skipped message=\"{}\"/>\n", Escape(first));
    } else {
      std::string body = r.message;
      for (const std::string& d : r.diagnostics) body += "\n" + d;
      xml +=
          fmt::format("      <failure message=\"{}\">{}</failure>\n", Escape(first), Escape(body));
    }
    xml += "    </testcase>\n";
  }
  xml += "  </testsuite>\n</testsuites>\n";
  return xml;
}

}  // namespace arbiter::runtime
