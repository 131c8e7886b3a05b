#include <catch2/catch.hpp>

#include <cstdint>
#include <string>
#include <utility>

#include <sepax/small_vector.hpp>

using namespace sepax;

namespace {

/// Live Counted objects, count (constructions minus destructions).
int g_live = 0;

/// An element that counts its live instances and whose destructor clears
/// its value, so that a read of a destroyed element shows.
struct Counted {
  /// The value held (-1 once destroyed).
  int value = 0;
  /// Value 0.
  Counted() { ++g_live; }
  /// Value v.
  Counted(int v) : value(v) { ++g_live; }
  /// A copy of o's value.
  Counted(const Counted& o) : value(o.value) { ++g_live; }
  /// o's value.
  Counted& operator=(const Counted& o) = default;
  /// Clears the value.
  ~Counted() {
    value = -1;
    --g_live;
  }
  /// Same value.
  friend bool operator==(const Counted& a, const Counted& b) { return a.value == b.value; }
};

/// True when v's elements are inside v's own object (its inline storage).
template <class V>
bool points_inline(const V& v) {
  const auto p = reinterpret_cast<std::uintptr_t>(v.data());
  const auto lo = reinterpret_cast<std::uintptr_t>(&v);
  return p >= lo && p < lo + sizeof(V);
}

/// 0, 1, ..., n-1 (plus `offset`).
template <class V>
V iota(int n, int offset = 0) {
  V v;
  for (int i = 0; i < n; ++i) v.push_back(i + offset);
  return v;
}

/// v holds offset, offset+1, ..., offset+n-1, read through data(),
/// indexing and iteration.
template <class V>
bool holds(const V& v, int n, int offset = 0) {
  if (v.size() != static_cast<std::size_t>(n)) return false;
  int k = offset;
  for (const auto& e : v) {
    if (!(e == decltype(v[0])(k))) return false;
    ++k;
  }
  for (int i = 0; i < n; ++i) {
    if (!(v[static_cast<std::size_t>(i)] == decltype(v[0])(i + offset))) return false;
    if (!(v.data()[i] == decltype(v[0])(i + offset))) return false;
  }
  return true;
}

using IV = SmallVector<int, 4>;
using CV = SmallVector<Counted, 4>;

}  // namespace

TEST_CASE("SmallVector: inline up to N, then spilled to the heap", "[small_vector]") {
  IV v;
  CHECK(v.empty());
  CHECK(v.capacity() == 4);
  CHECK(points_inline(v));
  for (int i = 0; i < 4; ++i) v.push_back(i);
  CHECK_FALSE(v.spilled());
  CHECK(points_inline(v));
  v.push_back(4);
  CHECK(v.spilled());
  CHECK_FALSE(points_inline(v));
  CHECK(v.capacity() >= 5);
  CHECK(holds(v, 5));
  v.pop_back();
  CHECK(holds(v, 4));
  v.resize(9, 7);
  CHECK(v.size() == 9);
  CHECK(v.back() == 7);
  v.assign(3, 2);
  CHECK(v == IV{2, 2, 2});
  v.clear();
  CHECK(v.empty());
  CHECK(v.spilled());  // the heap array stays
}

TEST_CASE("SmallVector: push_back of its own element while growing", "[small_vector]") {
  IV v = iota<IV>(4);
  v.push_back(v[1]);
  CHECK(v.back() == 1);
  v.assign(6, v[4]);
  CHECK(v == IV{1, 1, 1, 1, 1, 1});
}

TEST_CASE("SmallVector: copies point at their own storage", "[small_vector]") {
  for (const int n : {0, 3, 4, 5, 11}) {
    CAPTURE(n);
    IV a = iota<IV>(n);
    IV b(a);
    CHECK(holds(b, n));
    CHECK(points_inline(b) == (n <= 4));
    if (n > 0) {
      CHECK(b.data() != a.data());
      b[0] = 100;  // a write to the copy leaves the source as it was
      CHECK(a[0] == 0);
    }
    IV c = iota<IV>(7, 50);  // spilled destination, enough room: keeps its heap array
    c = a;
    CHECK(holds(c, n));
    CHECK(c.spilled());
    IV d = iota<IV>(2, 50);  // inline destination
    d = a;
    CHECK(holds(d, n));
    CHECK(points_inline(d) == (n <= 4));
    a = iota<IV>(n, 30);  // the copies do not share a's storage
    CHECK(holds(b, n) == (n == 0));
    CHECK(holds(c, n));
    CHECK(holds(d, n));
  }
}

TEST_CASE("SmallVector: moves re-point destination and source", "[small_vector]") {
  for (const int n : {0, 3, 4, 5, 11}) {
    CAPTURE(n);
    IV a = iota<IV>(n);
    const int* heap = a.data();
    IV b(std::move(a));
    CHECK(holds(b, n));
    if (n > 4) {
      CHECK(b.data() == heap);  // the heap array handed over
    } else {
      CHECK(points_inline(b));  // not at a's inline storage
    }
    CHECK(a.empty());  // moved from: empty and inline
    CHECK(points_inline(a));
    CHECK(a.capacity() == 4);
    a.push_back(42);  // the source is usable and does not alias b
    CHECK(a[0] == 42);
    CHECK(holds(b, n));

    IV c = iota<IV>(9, 50);  // spilled destination: its heap array released
    c = std::move(b);
    CHECK(holds(c, n));
    CHECK(points_inline(c) == (n <= 4));
    CHECK(b.empty());
    CHECK(points_inline(b));
    IV d = iota<IV>(2, 50);  // inline destination
    d = std::move(c);
    CHECK(holds(d, n));
    CHECK(points_inline(d) == (n <= 4));
    c.push_back(1);
    CHECK(holds(d, n));
  }
}

TEST_CASE("SmallVector: a moved inline vector outlives its source", "[small_vector]") {
  auto* a = new IV(iota<IV>(3));
  IV b(std::move(*a));
  delete a;  // b must not read a's inline storage
  CHECK(holds(b, 3));
  b.push_back(3);
  b.push_back(4);  // spills: copies from b's own inline storage
  CHECK(holds(b, 5));
}

TEST_CASE("SmallVector: swap of inline and spilled vectors", "[small_vector]") {
  const int sizes[] = {0, 2, 4, 6, 13};
  for (const int n : sizes) {
    for (const int m : sizes) {
      CAPTURE(n, m);
      IV a = iota<IV>(n);
      IV b = iota<IV>(m, 100);
      a.swap(b);
      CHECK(holds(a, m, 100));
      CHECK(holds(b, n));
      CHECK(points_inline(a) == (m <= 4));
      CHECK(points_inline(b) == (n <= 4));
      a.push_back(-1);
      b.push_back(-2);
      CHECK(a.back() == -1);
      CHECK(b.back() == -2);
      CHECK(a.size() == static_cast<std::size_t>(m + 1));
      CHECK(b.size() == static_cast<std::size_t>(n + 1));
      a.swap(a);  // self-swap keeps the elements
      CHECK(a.size() == static_cast<std::size_t>(m + 1));
      CHECK(a.back() == -1);
    }
  }
}

TEST_CASE("SmallVector: self-assignment keeps the elements", "[small_vector]") {
  for (const int n : {0, 3, 4, 9}) {
    CAPTURE(n);
    IV a = iota<IV>(n);
    IV& same = a;
    a = same;
    CHECK(holds(a, n));
    a = std::move(same);
    CHECK(holds(a, n));
    CHECK(points_inline(a) == (n <= 4));
  }
}

TEST_CASE("SmallVector: every element constructed is destroyed once", "[small_vector]") {
  g_live = 0;
  {
    CV a;
    for (int i = 0; i < 3; ++i) a.push_back(i);
    CHECK(g_live == 3);
    CV b = a;
    CHECK(g_live == 6);
    CV c = std::move(a);
    CHECK(g_live == 6);  // a's inline elements moved and destroyed
    CHECK(holds(c, 3));
    for (int i = 3; i < 9; ++i) c.push_back(i);
    CHECK(g_live == 9 + 3);  // only the elements held: none beyond size() on the heap
    CV d = std::move(c);     // the heap array handed over: no element touched
    CHECK(g_live == 9 + 3);
    CHECK(holds(d, 9));
    d.resize(2);
    CHECK(g_live == 2 + 3);
    d.swap(b);
    CHECK(holds(d, 3));
    CHECK(holds(b, 2));
    CHECK(g_live == 5);
    b.pop_back();
    CHECK(g_live == 4);
    b = d;
    CHECK(g_live == 6);
    d.clear();
    CHECK(g_live == 3);
  }
  CHECK(g_live == 0);
}

TEST_CASE("SmallVector: elements that point into themselves survive moves", "[small_vector]") {
  // short std::strings keep their characters inside the object
  using SV = SmallVector<std::string, 2>;
  SV a;
  a.push_back("x");
  a.push_back("y");
  SV b(std::move(a));
  a.push_back("z");
  CHECK(b[0] == "x");
  CHECK(b[1] == "y");
  b.push_back("w");  // spills: the strings move to the heap array
  SV c;
  c.push_back("v");
  c.swap(b);
  CHECK(c.size() == 3);
  CHECK(c[0] == "x");
  CHECK(c[2] == "w");
  CHECK(b.size() == 1);
  CHECK(b[0] == "v");
  CHECK(a[0] == "z");
}
