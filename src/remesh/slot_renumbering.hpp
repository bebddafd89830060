#pragma once
// Per-slot arrays renumbered after a compaction of the editable mesh: value s moves to slot new_id[s],
// dropped slots (kDroppedSlot) vanish. In place, along the cycles of the renumbering, so that no second
// copy of a large array is held (the clean-up's peak memory is reached while it compacts); any
// injective renumbering onto 0..kept-1 works, the order-keeping one and a space-filling curve's alike.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace isopatch {

/// The new id of a slot that a compaction dropped.
inline constexpr std::uint32_t kDroppedSlot = 0xffffffffu;

/// Moves values[s] to new_id[s] for every kept slot s and cuts `values` to the kept slots (releasing
/// the spare capacity). Slots beyond values.size() take `fill` first; an empty array stays empty (a
/// cache that was never filled). \pre the kept new ids are 0..kept-1, each once; values.size() <=
/// new_id.size()
template <class T>
void renumber_slots(std::vector<T>& values, const std::vector<std::uint32_t>& new_id, const T& fill) {
  if (values.empty()) return;
  std::size_t kept = 0;
  bool in_order = true;  // every kept slot's new id is the number of kept slots before it
  for (std::uint32_t id : new_id)
    if (id != kDroppedSlot) {
      in_order = in_order && id == kept;
      ++kept;
    }
  values.resize(new_id.size(), fill);
  if (in_order) {  // the order-keeping compaction: new_id[s] <= s, one forward pass
    for (std::size_t s = 0; s < values.size(); ++s)
      if (new_id[s] != kDroppedSlot && new_id[s] != s) values[new_id[s]] = std::move(values[s]);
    values.resize(kept);
    values.shrink_to_fit();
    return;
  }
  std::vector<bool> moved(values.size(), false);  // the slot's own value has been taken out
  for (std::uint32_t s = 0; s < values.size(); ++s) {
    if (moved[s] || new_id[s] == kDroppedSlot) continue;
    T carry = std::move(values[s]);
    moved[s] = true;
    // Carried along the cycle until it lands where nothing is left to take: a dropped slot, or one
    // whose value already moved on (the start of the cycle among them).
    for (std::uint32_t at = new_id[s];; at = new_id[at]) {
      if (moved[at] || new_id[at] == kDroppedSlot) {
        values[at] = std::move(carry);
        break;
      }
      std::swap(carry, values[at]);
      moved[at] = true;
    }
  }
  values.resize(kept);
  values.shrink_to_fit();
}

/// The same for bits (which have no value to carry): gathered into a new array of kept bits.
inline void renumber_slots(std::vector<bool>& values, const std::vector<std::uint32_t>& new_id, bool fill) {
  if (values.empty()) return;
  std::size_t kept = 0;
  for (std::uint32_t id : new_id) kept += id != kDroppedSlot;
  std::vector<bool> out(kept, fill);
  for (std::uint32_t s = 0; s < values.size() && s < new_id.size(); ++s)
    if (new_id[s] != kDroppedSlot) out[new_id[s]] = values[s];
  values = std::move(out);
}

}  // namespace isopatch
