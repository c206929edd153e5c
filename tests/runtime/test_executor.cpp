#include "test_executor.h"

#include <cstdlib>
#include <memory>

namespace arbiter::runtime::testing {
namespace {

std::string Env(const char* name, const char* fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? value : fallback;
}

}  // namespace

std::string TestDriver() { return Env("ARBITER_TEST_DRIVER", "softpipe"); }

ArbExecutor* SharedExecutor(std::string* error) {
  static std::string create_error;
  static std::unique_ptr<ArbExecutor> executor = [] {
    ExecOptions options;
    if (!ParseBackend(Env("ARBITER_TEST_BACKEND", "osmesa"), &options.backend)) {
      create_error = "bad ARBITER_TEST_BACKEND";
      return std::unique_ptr<ArbExecutor>();
    }
    options.driver = TestDriver();
    return CreateArbExecutor(options, &create_error);
  }();
  *error = create_error;
  return executor.get();
}

}  // namespace arbiter::runtime::testing
