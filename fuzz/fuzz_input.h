// What every fuzz target shares: the input-size cap and the bytes as a SourceFile.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "arbiter/compiler/source.h"

namespace arbiter::fuzz {

// Larger inputs add no new paths, only time: a run must stay far below libFuzzer's timeout.
inline constexpr size_t kMaxInputBytes = 64 * 1024;

inline std::unique_ptr<compiler::SourceFile> MakeSource(const uint8_t* data, size_t size,
                                                        const char* path) {
  return std::make_unique<compiler::SourceFile>(
      path, std::string(reinterpret_cast<const char*>(data), size));
}

}  // namespace arbiter::fuzz
