#pragma once
// An allocator whose containers leave new elements of trivial types uninitialised (default-initialised),
// so that std::vector::resize of a large array does not write it on one thread before a parallel pass
// writes every element anyway: the first write of each page (a page fault) then happens on the thread
// that fills it. Elements constructed with a value are constructed as usual.

#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace isopatch {

template <class T, class Base = std::allocator<T>>
class DefaultInitAllocator : public Base {
 public:
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U, typename std::allocator_traits<Base>::template rebind_alloc<U>>;
  };
  using Base::Base;

  /// Default-initialises (for trivial T: leaves the memory as it is).
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    std::allocator_traits<Base>::construct(static_cast<Base&>(*this), p, std::forward<Args>(args)...);
  }
};

/// A vector whose resize(n) leaves trivial elements uninitialised: every element must be written before
/// it is read.
template <class T>
using UninitialisedVector = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace isopatch
