// sepax/small_vector.hpp
//
// SmallVector<T, N>: a sequence with room for N elements inside the object
// and a heap array only beyond N ("spill"), so that the contact manifold's
// working sets (clipped polygon, candidate points, the reduction's tables)
// need no allocation in the common case.  The subset of std::vector the
// manifold code uses: size, empty, capacity, reserve, resize, assign,
// push_back, pop_back, clear, swap, insert at the end, iteration, indexing.
// Elements must be default-constructible and copyable (sepax's Vec3, ints,
// T values, contact records: all are).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <initializer_list>
#include <memory>
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
  SmallVector& operator=(const SmallVector& o) {
    if (this != &o) {
      size_ = 0;
      copy_from(o);
    }
    return *this;
  }
  SmallVector& operator=(SmallVector&& o) noexcept {
    if (this != &o) {
      heap_.reset();
      cap_ = N;
      size_ = 0;
      move_from(std::move(o));
    }
    return *this;
  }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::size_t capacity() const { return cap_; }
  /// True when the elements live on the heap (more than N were ever held).
  bool spilled() const { return heap_ != nullptr; }

  T* data() { return heap_ ? heap_.get() : inline_.data(); }
  const T* data() const { return heap_ ? heap_.get() : inline_.data(); }
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
    heap_ = std::move(h);
    cap_ = n;
  }
  void clear() { size_ = 0; }
  void push_back(const T& v) {
    if (size_ == cap_) {
      const T copy = v;  // v may live in this container
      reserve(cap_ * 2);
      data()[size_++] = copy;
      return;
    }
    data()[size_++] = v;
  }
  void pop_back() { --size_; }
  void resize(std::size_t n, const T& v = T()) {
    reserve(n);
    for (std::size_t i = size_; i < n; ++i) data()[i] = v;
    size_ = n;
  }
  void assign(std::size_t n, const T& v) {
    size_ = 0;
    resize(n, v);
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
  void copy_from(const SmallVector& o) {
    reserve(o.size_);
    std::copy(o.begin(), o.end(), data());
    size_ = o.size_;
  }
  void move_from(SmallVector&& o) {
    if (o.heap_) {
      heap_ = std::move(o.heap_);
      cap_ = o.cap_;
      size_ = o.size_;
    } else {
      std::copy(o.begin(), o.end(), inline_.data());
      size_ = o.size_;
    }
    o.heap_.reset();
    o.cap_ = N;
    o.size_ = 0;
  }

  std::array<T, N> inline_{};
  std::unique_ptr<T[]> heap_;
  std::size_t cap_ = N;
  std::size_t size_ = 0;
};

}  // namespace sepax
