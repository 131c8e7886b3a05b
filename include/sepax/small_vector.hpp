// sepax/small_vector.hpp
//
// SmallVector<T, N>: a sequence with room for N elements inside the object
// and a heap array only beyond N ("spill"), so that the contact manifold's
// working sets (clipped polygon, candidate points, the reduction's tables)
// need no allocation in the common case.  The subset of std::vector the
// manifold code uses: size, empty, capacity, reserve, resize, assign,
// push_back, pop_back, clear, swap, insert at the end, iteration, indexing.
// Elements must be default-constructible and copyable (sepax's Vec3, ints,
// T values, contact records: all are).  Only the elements held are
// constructed, inline or on the heap (a manifold's working sets are
// declared per query with room for 64 elements and mostly hold 4 to 8).
//
// The vector keeps a pointer to its elements (data_: the inline storage, or
// the heap array once spilled), so that an access is one load and an index,
// without a choice between the two storages; a copy or move of an inline
// vector points the destination at its own inline storage, and a move of a
// spilled one hands the heap array over and points the source back at its
// inline storage.
#pragma once

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace sepax {

template <class T, std::size_t N>
class SmallVector {
  static_assert(N > 0, "SmallVector needs room for at least one inline element");

 public:
  /// The element type.
  using value_type = T;
  /// The type of sizes and indices.
  using size_type = std::size_t;
  /// A mutable iterator (a pointer into the elements).
  using iterator = T*;
  /// A read-only iterator (a pointer into the elements).
  using const_iterator = const T*;
  /// Elements held without a heap array, count.
  static constexpr std::size_t inline_capacity = N;

  /// Empty, inline.
  SmallVector() = default;
  /// n copies of v.
  SmallVector(std::size_t n, const T& v = T()) { assign(n, v); }
  /// The elements of il, in order.
  SmallVector(std::initializer_list<T> il) {
    reserve(il.size());
    for (const T& v : il) push_back(v);
  }
  /// A copy of o's elements (inline when they fit, whatever o's storage).
  SmallVector(const SmallVector& o) { copy_from(o); }
  /// o's elements: o's heap array taken over when o spilled, else moved
  /// into this vector's inline storage; o is left empty and inline.
  SmallVector(SmallVector&& o) noexcept { move_from(std::move(o)); }
  /// Destroys the elements and frees the heap array, if any.
  ~SmallVector() { release(); }
  /// A copy of o's elements (this vector's heap array kept when it holds them).
  SmallVector& operator=(const SmallVector& o) {
    if (this != &o) {
      clear();
      copy_from(o);
    }
    return *this;
  }
  /// o's elements as the move constructor takes them; this vector's own
  /// elements and heap array released first.
  SmallVector& operator=(SmallVector&& o) noexcept {
    if (this != &o) {
      release();
      move_from(std::move(o));
    }
    return *this;
  }

  /// Elements held, count.
  std::size_t size() const { return size_; }
  /// True when no element is held.
  bool empty() const { return size_ == 0; }
  /// Elements held without reallocating, count.
  std::size_t capacity() const { return cap_; }
  /// True when the elements live on the heap (more than N were ever held).
  bool spilled() const { return data_ != inline_data(); }

  /// The first element (inline storage or heap array).
  T* data() { return data_; }
  /// The first element (inline storage or heap array).
  const T* data() const { return data_; }
  /// Element i (i < size()).
  T& operator[](std::size_t i) { return data_[i]; }
  /// Element i (i < size()).
  const T& operator[](std::size_t i) const { return data_[i]; }
  /// The first element (size() > 0).
  T& front() { return data_[0]; }
  /// The first element (size() > 0).
  const T& front() const { return data_[0]; }
  /// The last element (size() > 0).
  T& back() { return data_[size_ - 1]; }
  /// The last element (size() > 0).
  const T& back() const { return data_[size_ - 1]; }
  /// The first element.
  iterator begin() { return data_; }
  /// Past the last element.
  iterator end() { return data_ + size_; }
  /// The first element.
  const_iterator begin() const { return data_; }
  /// Past the last element.
  const_iterator end() const { return data_ + size_; }

  /// Room for n elements (a heap array of n when n exceeds the capacity).
  void reserve(std::size_t n) {
    if (n > cap_) reallocate(n);
  }
  /// Holds no element (the storage stays).
  void clear() {
    destroy(0, size_);
    size_ = 0;
  }
  /// Appends v.
  void push_back(const T& v) {
    if (size_ == cap_) {
      grow_and_push(v);
      return;
    }
    ::new (static_cast<void*>(data_ + size_)) T(v);
    ++size_;
  }
  /// Removes the last element (size() > 0).
  void pop_back() {
    --size_;
    destroy(size_, size_ + 1);
  }
  /// n elements: the first min(n, size()) kept, the rest T() (no T built
  /// when n <= size(), as where a polygon is welded to fewer vertices).
  void resize(std::size_t n) {
    reserve(n);
    for (std::size_t i = size_; i < n; ++i) ::new (static_cast<void*>(data_ + i)) T();
    if (n < size_) destroy(n, size_);
    size_ = n;
  }
  /// n elements: the first min(n, size()) kept, the rest copies of v.
  void resize(std::size_t n, const T& v) {
    reserve(n);
    for (std::size_t i = size_; i < n; ++i) ::new (static_cast<void*>(data_ + i)) T(v);
    if (n < size_) destroy(n, size_);
    size_ = n;
  }
  /// n copies of v.
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
  /// Exchanges the elements of this vector and o (each inline or spilled).
  void swap(SmallVector& o) noexcept {
    SmallVector t(std::move(o));
    o = std::move(*this);
    *this = std::move(t);
  }

  /// Same size and equal elements in order.
  friend bool operator==(const SmallVector& x, const SmallVector& y) {
    return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin());
  }

 private:
  /// The inline storage as elements (raw beyond size() while inline).
  T* inline_data() { return reinterpret_cast<T*>(inline_); }
  /// The inline storage as elements (raw beyond size() while inline).
  const T* inline_data() const { return reinterpret_cast<const T*>(inline_); }
  /// Destroys the elements [from, to).
  void destroy(std::size_t from, std::size_t to) {
    if constexpr (!std::is_trivially_destructible_v<T>) {
      std::destroy(data_ + from, data_ + to);
    } else {
      (void)from, (void)to;
    }
  }
  /// Moves the elements to a new heap array of n > capacity() elements
  /// (only size() of them constructed) and frees the old one, if any.
  void reallocate(std::size_t n) {
    std::allocator<T> alloc;
    T* h = alloc.allocate(n);
    try {
      if constexpr (std::is_nothrow_move_constructible_v<T>) {
        std::uninitialized_move(data_, data_ + size_, h);
      } else {
        std::uninitialized_copy(data_, data_ + size_, h);
      }
    } catch (...) {
      alloc.deallocate(h, n);
      throw;
    }
    destroy(0, size_);
    if (spilled()) alloc.deallocate(data_, cap_);
    data_ = h;
    cap_ = n;
  }
  /// push_back when full (out of line: the common path stays small enough to inline).
  [[gnu::noinline]] void grow_and_push(const T& v) {
    const T copy = v;  // v may live in this container
    reserve(cap_ * 2);
    ::new (static_cast<void*>(data_ + size_)) T(copy);
    ++size_;
  }
  /// Destroys the elements, frees the heap array, if any: empty and inline.
  void release() {
    clear();
    if (spilled()) std::allocator<T>().deallocate(data_, cap_);
    data_ = inline_data();
    cap_ = N;
  }
  /// o's elements copied into this vector (empty: size_ 0).
  void copy_from(const SmallVector& o) {
    reserve(o.size_);
    std::uninitialized_copy(o.data_, o.data_ + o.size_, data_);
    size_ = o.size_;
  }
  /// o's elements into this vector (empty and inline): o's heap array
  /// taken over, or o's inline elements moved into this inline storage;
  /// o left empty and inline.
  void move_from(SmallVector&& o) {
    if (o.spilled()) {
      data_ = o.data_;
      cap_ = o.cap_;
      size_ = o.size_;
      o.data_ = o.inline_data();
      o.cap_ = N;
      o.size_ = 0;
    } else {
      std::uninitialized_move(o.data_, o.data_ + o.size_, data_);
      size_ = o.size_;
      o.clear();
    }
  }

  /// Room for N elements; those in [0, size_) constructed while inline.
  alignas(T) unsigned char inline_[N * sizeof(T)];
  /// The elements: inline_ or a heap array of cap_ (std::allocator<T>).
  T* data_ = inline_data();
  /// Elements the storage data_ points to has room for, count.
  std::size_t cap_ = N;
  /// Elements held (constructed at data_[0, size_)), count.
  std::size_t size_ = 0;
};

}  // namespace sepax
