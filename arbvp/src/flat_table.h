// An open-addressing hash table of small trivially copyable entries: one array, no
// allocation per entry. The symbol table and the distinct-binding counts use it; node-based
// std::unordered_map allocated once per declared name and per bound vector, a large share of
// checking programs that declare hundreds of temporaries or parameters.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <type_traits>

namespace arbiter::arbvp {

// The caller hashes and compares: an entry may hold its key indirectly (a range of the
// source text). Iteration order is unspecified.
template <typename Entry>
class FlatTable {
  static_assert(std::is_trivially_copyable_v<Entry> && std::is_trivially_destructible_v<Entry>);

 public:
  // The entry whose key has `hash` and for which eq(entry) holds, or null.
  template <typename Eq>
  const Entry* Find(uint64_t hash, const Eq& eq) const {
    if (capacity_ == 0) return nullptr;
    const uint32_t tag = Tag(hash);
    for (size_t i = hash & mask_;; i = (i + 1) & mask_) {
      const Slot& s = slots_[i];
      if (s.tag == 0) return nullptr;
      if (s.tag == tag && eq(s.entry)) return &s.entry;
    }
  }

  // Find, or else a new value-initialised entry for the caller to fill in (*inserted true).
  // The pointer stays valid until the next insertion.
  template <typename Eq>
  Entry* FindOrInsert(uint64_t hash, const Eq& eq, bool* inserted) {
    if ((size_ + 1) * 2 > capacity_) Grow();
    const uint32_t tag = Tag(hash);
    for (size_t i = hash & mask_;; i = (i + 1) & mask_) {
      Slot& s = slots_[i];
      if (s.tag == 0) {
        s.tag = tag;
        s.hash = hash;
        s.entry = Entry{};
        ++size_;
        *inserted = true;
        return &s.entry;
      }
      if (s.tag == tag && eq(s.entry)) {
        *inserted = false;
        return &s.entry;
      }
    }
  }

  size_t size() const { return size_; }

  template <typename F>
  void ForEach(const F& f) const {
    for (size_t i = 0; i < capacity_; ++i) {
      if (slots_[i].tag != 0) f(slots_[i].entry);
    }
  }

 private:
  // An aggregate of trivially copyable members, hence an implicit-lifetime type: zeroed
  // malloc'd memory holds an array of empty slots. Most tables stay small, and constructing
  // the slots one by one (std::vector) showed in profiles; so did calloc, which glibc serves
  // without its per-thread cache.
  struct Slot {
    uint32_t tag;  // 0: empty; else the hash's high half, never 0
    uint64_t hash;
    Entry entry;
  };
  struct Free {
    void operator()(Slot* p) const { std::free(p); }
  };
  static uint32_t Tag(uint64_t hash) { return static_cast<uint32_t>(hash >> 32) | 1u; }

  // Doubles the capacity (at most half full); starts at 16 slots.
  void Grow() {
    std::unique_ptr<Slot[], Free> old = std::move(slots_);
    size_t old_capacity = capacity_;
    size_t capacity = old_capacity == 0 ? 16 : old_capacity * 2;
    slots_.reset(static_cast<Slot*>(std::malloc(capacity * sizeof(Slot))));
    if (!slots_) throw std::bad_alloc();
    std::memset(static_cast<void*>(slots_.get()), 0, capacity * sizeof(Slot));  // all tags 0
    capacity_ = capacity;
    mask_ = capacity_ - 1;
    for (size_t j = 0; j < old_capacity; ++j) {
      const Slot& s = old[j];
      if (s.tag == 0) continue;
      size_t i = s.hash & mask_;
      while (slots_[i].tag != 0) i = (i + 1) & mask_;
      slots_[i] = s;
    }
  }

  std::unique_ptr<Slot[], Free> slots_;
  size_t capacity_ = 0;
  size_t mask_ = 0;
  size_t size_ = 0;
};

}  // namespace arbiter::arbvp
