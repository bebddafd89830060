#pragma once
// The triangles incident to each vertex, kept in blocks of one flat store: each vertex owns a run of
// slots (its list and some spare room), so that a pass over the vertices in order reads memory in
// order and a list costs no heap block of its own (a std::vector per vertex costs 24 bytes of header
// plus a scattered heap block of 32-48 bytes). A list that outgrows its run moves to the end of the
// store with four more entries of room; the runs left behind stay unused until rebuild(), which the clean-up
// calls whenever it compacts the mesh. The store grows by whole blocks, never by copying into a larger array:
// growing never holds two copies of the lists, and a list that is read never moves unless it is its
// own vertex's list that changes.
//
// Threads: changes of the lists of different vertices may run at once (the parallel flips do); a
// list may be read while other vertices' lists change. A new run is handed out under a lock.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <tbb/spin_mutex.h>

namespace isopatch {

class IncidenceLists {
 public:
  /// `vertices` empty lists.
  explicit IncidenceLists(std::size_t vertices = 0);
  /// Deep copies (the blocks are owned).
  IncidenceLists(const IncidenceLists& other);
  IncidenceLists& operator=(const IncidenceLists& other);
  IncidenceLists(IncidenceLists&&) noexcept = default;
  IncidenceLists& operator=(IncidenceLists&&) noexcept = default;
  ~IncidenceLists() = default;

  /// Number of vertex slots.
  std::size_t size() const { return start_.size(); }
  /// The list of vertex v (valid until the next change of any list).
  std::span<const std::uint32_t> operator[](std::uint32_t v) const {
    if (count_[v] == 0) return {};
    return {at(start_[v]), count_[v]};
  }
  bool empty(std::uint32_t v) const { return count_[v] == 0; }

  /// Appends triangle t to v's list (moving the list to the end, with four more entries of room, when
  /// its run is full: lists are short, and change by a few entries at a time).
  /// \throw InputError beyond 65535 triangles at one vertex
  void push_back(std::uint32_t v, std::uint32_t t);
  /// Removes the first t from v's list, keeping the order of the others; nothing when t is absent.
  void remove(std::uint32_t v, std::uint32_t t);
  /// Appends every entry of `from`'s list to `to`'s and empties `from`'s. \pre from != to
  void move_all(std::uint32_t from, std::uint32_t to);
  /// Adds an empty list for a new vertex slot; returns its id.
  std::uint32_t add_vertex();
  /// Room for `vertices` more vertex slots without reallocation of the per-vertex arrays.
  void reserve(std::size_t vertices);
  /// Gives v's run room for at least `room` entries (moving it to the end of the store if needed).
  /// \throw InputError beyond 65535 entries
  void make_room(std::uint32_t v, std::size_t room);

  /// Lists in a new numbering: new slot k takes old slot order[k]'s list with every triangle id t
  /// replaced by triangle_id[t]; runs laid out in the new order with two spare entries each.
  /// \pre every id in the kept lists has triangle_id[id] valid
  void rebuild(const std::vector<std::uint32_t>& order, const std::vector<std::uint32_t>& triangle_id);

  /// The same numbering change when it keeps the order (vertex_id rises over the kept slots,
  /// kDroppedSlot for a dropped one; `vertices` kept): in place, the runs squeezed down in the order
  /// they lie, so no second copy of the lists is held. \pre vertex_id.size() == size()
  void renumber_in_order(const std::vector<std::uint32_t>& vertex_id, std::size_t vertices,
                         const std::vector<std::uint32_t>& triangle_id);

  static constexpr std::size_t kSpare = 2;  ///< entries of room a rebuilt run keeps beyond its list
  static constexpr std::size_t kBlockBits = 16;
  static constexpr std::size_t kBlock = std::size_t{1} << kBlockBits;  ///< entries per block
  static constexpr std::size_t kMaxBlocks = 16384;                     ///< 2^30 entries in all

 private:
  std::uint32_t* at(std::uint32_t offset) const {
    return blocks_[offset >> kBlockBits].get() + (offset & (kBlock - 1));
  }
  /// Where a new run of `room` entries goes (within one block), moving end_ past it and adding a block
  /// when the store is full. Thread-safe.
  std::uint32_t new_run(std::size_t room);

  /// Blocks, reserved to kMaxBlocks at construction so that adding one never moves the others' pointers.
  std::vector<std::unique_ptr<std::uint32_t[]>> blocks_;
  std::uint32_t end_ = 0;                                                        ///< offset past the last run
  std::unique_ptr<tbb::spin_mutex> lock_ = std::make_unique<tbb::spin_mutex>();  ///< guards end_, blocks_
  std::vector<std::uint32_t> start_;  ///< per vertex: offset of its run (below 2^30)
  std::vector<std::uint16_t> count_;  ///< per vertex: entries in use
  std::vector<std::uint16_t> room_;   ///< per vertex: length of its run
};

}  // namespace isopatch
