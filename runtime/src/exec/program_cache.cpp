// ProgramCache: see program_cache.h. A handful of entries: a linear scan beats a map.
#include "exec/program_cache.h"

#include <algorithm>

namespace arbiter::runtime::exec {

GLuint ProgramCache::Find(const std::string& key) {
  auto it = std::find_if(entries_.begin(), entries_.end(),
                         [&](const auto& entry) { return entry.first == key; });
  if (it == entries_.end()) return 0;
  std::rotate(entries_.begin(), it, it + 1);
  return entries_.front().second;
}

GLuint ProgramCache::Add(std::string key, GLuint id) {
  entries_.insert(entries_.begin(), {std::move(key), id});
  if (entries_.size() <= capacity_) return 0;
  const GLuint evicted = entries_.back().second;
  entries_.pop_back();
  return evicted;
}

}  // namespace arbiter::runtime::exec
