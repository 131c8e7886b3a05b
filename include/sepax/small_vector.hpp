// sepax/small_vector.hpp
//
// SmallVector<T, N>: a sequence with room for N elements inside the object
// and a heap array only beyond N ("spill"), so that the contact manifold's
// working sets (clipped polygon, candidate points, the reduction's tables)
// need no allocation in the common case.  The subset of std::vector the
// manifold code uses: size, empty, capacity, reserve, resize, assign,
// push_back, pop_back, clear, swap, insert at the end, iteration, indexing.
// Elements must be default-constructible and copyable (sepax's Vec3, ints,
// T values, contact records: all are).  The inline room is raw storage:
// only the elements held are constructed (a manifold's working sets are
// declared per query with room for 64 elements and mostly hold 4 to 8).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace sepax {

template <class T, std::size_t N>
class SmallVector {
 public:
  using value_type = T;
  using size_type = std::size_t;
  using iterator = T*;
  using const_iterator = const T*;
  static constexpr std::size_t inline_capacity = N;

  SmallVector() = default;
  SmallVector(std::size_t n, const T& v = T()) { assign(n, v); }
  SmallVector(std::initializer_list<T> il) {
    reserve(il.size());
    for (const T& v : il) push_back(v);
  }
  SmallVector(const SmallVector& o) { copy_from(o); }
  SmallVector(SmallVector&& o) noexcept { move_from(std::move(o)); }
  ~SmallVector() { clear(); }
  SmallVector& operator=(const SmallVector& o) {
    if (this != &o) {
      clear();
      copy_from(o);
    }
    return *this;
  }
  SmallVector& operator=(SmallVector&& o) noexcept {
    if (this != &o) {
      clear();
      heap_.reset();
      cap_ = N;
      move_from(std::move(o));
    }
    return *this;
  }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::size_t capacity() const { return cap_; }
  /// True when the elements live on the heap (more than N were ever held).
  bool spilled() const { return heap_ != nullptr; }

  T* data() { return heap_ ? heap_.get() : inline_data(); }
  const T* data() const { return heap_ ? heap_.get() : inline_data(); }
  T& operator[](std::size_t i) { return data()[i]; }
  const T& operator[](std::size_t i) const { return data()[i]; }
  T& front() { return data()[0]; }
  const T& front() const { return data()[0]; }
  T& back() { return data()[size_ - 1]; }
  const T& back() const { return data()[size_ - 1]; }
  iterator begin() { return data(); }
  iterator end() { return data() + size_; }
  const_iterator begin() const { return data(); }
  const_iterator end() const { return data() + size_; }

  void reserve(std::size_t n) {
    if (n <= cap_) return;
    std::unique_ptr<T[]> h(new T[n]);
    std::copy(begin(), end(), h.get());
    if (!heap_) destroy_inline(0, size_);
    heap_ = std::move(h);
    cap_ = n;
  }
  void clear() {
    if (!heap_) destroy_inline(0, size_);
    size_ = 0;
  }
  void push_back(const T& v) {
    if (size_ == cap_) {
      grow_and_push(v);
      return;
    }
    put(size_, v);
    ++size_;
  }
  void pop_back() {
    if (!heap_) destroy_inline(size_ - 1, size_);
    --size_;
  }
  void resize(std::size_t n, const T& v = T()) {
    reserve(n);
    for (std::size_t i = size_; i < n; ++i) put(i, v);
    if (n < size_ && !heap_) destroy_inline(n, size_);
    size_ = n;
  }
  void assign(std::size_t n, const T& v) {
    const T copy = v;  // v may live in this container
    clear();
    resize(n, copy);
  }
  /// Append [first, last) (insert at end() only).
  template <class It>
  void append(It first, It last) {
    for (; first != last; ++first) push_back(*first);
  }
  void swap(SmallVector& o) noexcept {
    SmallVector t(std::move(o));
    o = std::move(*this);
    *this = std::move(t);
  }

  friend bool operator==(const SmallVector& x, const SmallVector& y) {
    return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin());
  }

 private:
  // The inline elements [0, size_) are constructed (placement new) and the
  // rest of the inline storage is raw, so that an empty SmallVector costs no
  // construction of N elements; heap elements are all constructed (new T[]).
  T* inline_data() { return std::launder(reinterpret_cast<T*>(inline_)); }
  const T* inline_data() const { return std::launder(reinterpret_cast<const T*>(inline_)); }
  // element i (i < cap_, i == size_ or an element being appended) set to v
  void put(std::size_t i, const T& v) {
    if (heap_) {
      heap_[i] = v;
    } else {
      ::new (static_cast<void*>(inline_data() + i)) T(v);
    }
  }
  void destroy_inline(std::size_t from, std::size_t to) {
    if constexpr (!std::is_trivially_destructible_v<T>) {
      for (std::size_t i = from; i < to; ++i) inline_data()[i].~T();
    } else {
      (void)from, (void)to;
    }
  }
  // push_back when full (out of line: the common path stays small enough to inline)
  [[gnu::noinline]] void grow_and_push(const T& v) {
    const T copy = v;  // v may live in this container
    reserve(cap_ * 2);
    put(size_, copy);
    ++size_;
  }
  // *this is empty (size_ 0, inline unless o's heap is taken)
  void copy_from(const SmallVector& o) {
    reserve(o.size_);
    for (std::size_t i = 0; i < o.size_; ++i) put(i, o.data()[i]);
    size_ = o.size_;
  }
  void move_from(SmallVector&& o) {
    if (o.heap_) {
      heap_ = std::move(o.heap_);
      cap_ = o.cap_;
      size_ = o.size_;
    } else {
      for (std::size_t i = 0; i < o.size_; ++i) {
        ::new (static_cast<void*>(inline_data() + i)) T(std::move(o.inline_data()[i]));
      }
      size_ = o.size_;
      o.destroy_inline(0, o.size_);
    }
    o.heap_.reset();
    o.cap_ = N;
    o.size_ = 0;
  }

  alignas(T) unsigned char inline_[N * sizeof(T)];
  std::unique_ptr<T[]> heap_;
  std::size_t cap_ = N;
  std::size_t size_ = 0;
};

}  // namespace sepax
