// Per-vertex incidence lists in blocks of one store, see incidence_lists.hpp.
#include "remesh/incidence_lists.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cstdint>
#include <utility>

#include "remesh/slot_renumbering.hpp"

namespace isopatch {
namespace {

constexpr std::size_t kMaxEntries = 65535;  // a count is 16 bits (and a run fits in one block)

}  // namespace

IncidenceLists::IncidenceLists(std::size_t vertices)
    : start_(vertices, 0), count_(vertices, 0), room_(vertices, 0) {
  blocks_.reserve(kMaxBlocks);
}

IncidenceLists::IncidenceLists(const IncidenceLists& other)
    : end_(other.end_), start_(other.start_), count_(other.count_), room_(other.room_) {
  blocks_.reserve(kMaxBlocks);
  for (const auto& block : other.blocks_) {
    blocks_.push_back(std::make_unique<std::uint32_t[]>(kBlock));
    std::copy_n(block.get(), kBlock, blocks_.back().get());
  }
}

IncidenceLists& IncidenceLists::operator=(const IncidenceLists& other) {
  if (this != &other) *this = IncidenceLists(other);
  return *this;
}

std::uint32_t IncidenceLists::new_run(std::size_t room) {
  const tbb::spin_mutex::scoped_lock guard(*lock_);
  if ((end_ & (kBlock - 1)) + room > kBlock)
    end_ = static_cast<std::uint32_t>((end_ >> kBlockBits << kBlockBits) + kBlock);
  while ((end_ + room - 1) >> kBlockBits >= blocks_.size()) {
    if (blocks_.size() == kMaxBlocks) throw InputError("more than 2^30 triangle corners in the clean-up");
    blocks_.push_back(std::make_unique<std::uint32_t[]>(kBlock));
  }
  const std::uint32_t offset = end_;
  end_ += static_cast<std::uint32_t>(room);
  return offset;
}

void IncidenceLists::make_room(std::uint32_t v, std::size_t room) {
  if (room <= room_[v]) return;
  if (room > kMaxEntries) throw InputError("more than 65535 triangles at one mesh vertex");
  const std::uint32_t offset = new_run(room);
  if (count_[v] > 0) std::copy_n(at(start_[v]), count_[v], at(offset));
  start_[v] = offset;
  room_[v] = static_cast<std::uint16_t>(room);
}

void IncidenceLists::push_back(std::uint32_t v, std::uint32_t t) {
  if (count_[v] >= kMaxEntries) throw InputError("more than 65535 triangles at one mesh vertex");
  if (count_[v] == room_[v]) make_room(v, std::min<std::size_t>(kMaxEntries, std::size_t{room_[v]} + 4));
  at(start_[v])[count_[v]++] = t;
}

void IncidenceLists::remove(std::uint32_t v, std::uint32_t t) {
  if (count_[v] == 0) return;
  std::uint32_t* first = at(start_[v]);
  std::uint32_t* last = first + count_[v];
  std::uint32_t* found = std::find(first, last, t);
  if (found == last) return;
  std::copy(found + 1, last, found);
  --count_[v];
}

void IncidenceLists::move_all(std::uint32_t from, std::uint32_t to) {
  // Entries read by index: a push may move `to`'s run.
  for (std::uint16_t k = 0; k < count_[from]; ++k) push_back(to, at(start_[from])[k]);
  count_[from] = 0;
}

std::uint32_t IncidenceLists::add_vertex() {
  const auto id = static_cast<std::uint32_t>(start_.size());
  start_.push_back(end_);
  count_.push_back(0);
  room_.push_back(0);
  return id;
}

void IncidenceLists::reserve(std::size_t vertices) {
  start_.reserve(start_.size() + vertices);
  count_.reserve(count_.size() + vertices);
  room_.reserve(room_.size() + vertices);
}

void IncidenceLists::renumber_in_order(const std::vector<std::uint32_t>& vertex_id, std::size_t vertices,
                                       const std::vector<std::uint32_t>& triangle_id) {
  std::vector<std::uint32_t> owners;  // kept vertices with a run, in the order the runs lie
  owners.reserve(vertices);
  for (std::uint32_t v = 0; v < start_.size(); ++v)
    if (vertex_id[v] != kDroppedSlot && room_[v] > 0) owners.push_back(v);
  std::sort(owners.begin(), owners.end(), [&](std::uint32_t a, std::uint32_t b) {
    return start_[a] < start_[b] || (start_[a] == start_[b] && a < b);
  });
  // Packed greedily in the order they lie, each run lands at or below where it was (a run never
  // crosses a block: one that does not fit the rest of a block starts the next).
  std::uint32_t next = 0;
  for (std::uint32_t v : owners) {
    if ((next & (kBlock - 1)) + room_[v] > kBlock)
      next = static_cast<std::uint32_t>((next >> kBlockBits << kBlockBits) + kBlock);
    std::uint32_t* from = at(start_[v]);
    std::uint32_t* to = at(next);
    for (std::uint16_t i = 0; i < count_[v]; ++i) to[i] = triangle_id[from[i]];  // to <= from
    start_[v] = next;
    next += room_[v];
  }
  end_ = next;
  blocks_.resize((std::size_t{end_} + kBlock - 1) >> kBlockBits);
  for (std::uint32_t v = 0; v < start_.size(); ++v) {
    if (vertex_id[v] == kDroppedSlot) continue;
    const std::uint32_t k = vertex_id[v];  // k <= v: moved down in place
    if (room_[v] == 0) start_[v] = end_;
    start_[k] = start_[v], count_[k] = count_[v], room_[k] = room_[v];
  }
  start_.resize(vertices), count_.resize(vertices), room_.resize(vertices);
  start_.shrink_to_fit(), count_.shrink_to_fit(), room_.shrink_to_fit();
}

void IncidenceLists::rebuild(const std::vector<std::uint32_t>& order,
                             const std::vector<std::uint32_t>& triangle_id) {
  IncidenceLists lists(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::uint32_t old = order[k];
    lists.make_room(static_cast<std::uint32_t>(k), std::min(kMaxEntries, count_[old] + kSpare));
    std::uint32_t* out = lists.at(lists.start_[k]);
    const std::uint32_t* in = count_[old] > 0 ? at(start_[old]) : nullptr;
    for (std::uint16_t i = 0; i < count_[old]; ++i) out[i] = triangle_id[in[i]];
    lists.count_[k] = count_[old];
  }
  *this = std::move(lists);
}

}  // namespace isopatch
