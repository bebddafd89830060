#pragma once
/// \file index_map.hpp
/// A small open-addressing hash map from keys to dense indices 0, 1, 2, ... in insertion order
/// (linear probing, power-of-two capacity, load factor <= 1/2). The partition's caches keep their
/// values in flat arrays indexed by it: one allocation per growth instead of one per entry, which
/// made std::unordered_map the largest cost of a build.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace isopatch {

/// SplitMix64 finaliser (Steele, Lea & Flood 2014): a cheap, well-mixing hash of a 64-bit key.
inline std::uint64_t mix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

struct Mix64Hash {
  std::size_t operator()(std::uint64_t key) const { return static_cast<std::size_t>(mix64(key)); }
};

template <class Key, class Hash>
class IndexMap {
 public:
  /// The index of `key`, or nullopt.
  std::optional<std::uint32_t> find(const Key& key) const {
    if (slots_.empty()) return std::nullopt;
    for (std::size_t s = start(key);; s = (s + 1) & mask()) {
      if (slots_[s].index == kEmpty) return std::nullopt;
      if (slots_[s].key == key) return slots_[s].index;
    }
  }

  /// The index of `key`, inserting it with index size() when absent; second is true when inserted.
  std::pair<std::uint32_t, bool> insert(const Key& key) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    std::size_t s = start(key);
    for (; slots_[s].index != kEmpty; s = (s + 1) & mask())
      if (slots_[s].key == key) return {slots_[s].index, false};
    slots_[s] = Slot{key, static_cast<std::uint32_t>(size_)};
    return {static_cast<std::uint32_t>(size_++), true};
  }

  std::size_t size() const { return size_; }

 private:
  static constexpr std::uint32_t kEmpty = std::numeric_limits<std::uint32_t>::max();
  struct Slot {
    Key key{};
    std::uint32_t index = kEmpty;
  };

  std::size_t mask() const { return slots_.size() - 1; }
  std::size_t start(const Key& key) const { return static_cast<std::size_t>(Hash{}(key)) & mask(); }

  void grow() {
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(old.empty() ? 1024 : 2 * old.size(), Slot{});
    for (const Slot& slot : old) {
      if (slot.index == kEmpty) continue;
      std::size_t s = start(slot.key);
      while (slots_[s].index != kEmpty) s = (s + 1) & mask();
      slots_[s] = slot;
    }
  }

  std::vector<Slot> slots_;
  std::size_t size_ = 0;
};

}  // namespace isopatch
