// (P3) exact separations from points and their exact comparison, against the
// same formulas evaluated with mpq_class and sepax::compare<mpq_class>.
#include <catch2/catch.hpp>

#include <random>

#include <sepax/robust/number_types.hpp>
#include <sepax/robust/separation_compare.hpp>
#include <sepax/separation.hpp>

using namespace sepax;
using namespace sepax::robust;

namespace {

Vec3<mpq_class> q(const Vec3<double>& v) {
  return Vec3<mpq_class>(mpq_class(v[0]), mpq_class(v[1]), mpq_class(v[2]));
}

Separation<mpq_class> face_oracle(const Vec3<double>& p0, const Vec3<double>& p1, const Vec3<double>& p2,
                                  const Vec3<double>& p) {
  const Vec3<mpq_class> n = cross(Vec3<mpq_class>(q(p1) - q(p0)), Vec3<mpq_class>(q(p2) - q(p0)));
  return {dot(n, Vec3<mpq_class>(q(p) - q(p0))), dot(n, n)};
}

Vec3<double> rnd(std::mt19937_64& rng, double scale, bool grid) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> g(-4, 4);
  if (grid) return Vec3<double>(g(rng), g(rng), g(rng)) * scale;
  return Vec3<double>(u(rng), u(rng), u(rng)) * scale;
}

}  // namespace

TEST_CASE("compare_exact matches sepax::compare on rationals", "[separation]") {
  std::mt19937_64 rng(13);
  int equal = 0, total = 0;
  for (double scale : {1.0, 1e-100, 1e100}) {
    for (int i = 0; i < 3000; ++i) {
      const bool grid = i % 2 == 0;  // integer grids produce exact ties
      Vec3<double> p[8];
      for (auto& v : p) v = rnd(rng, scale, grid);
      const auto fa = face_separation_poly(p[0], p[1], p[2], p[3]);
      const auto fb = face_separation_poly(p[4], p[5], p[6], p[7]);
      const auto oa = face_oracle(p[0], p[1], p[2], p[3]);
      const auto ob = face_oracle(p[4], p[5], p[6], p[7]);
      if (sgn(oa.norm2) == 0 || sgn(ob.norm2) == 0) continue;
      const int want = sepax::compare(oa, ob);
      REQUIRE(compare_exact(fa, fb) == want);
      REQUIRE(compare_exact(fb, fa) == -want);
      REQUIRE(compare_exact(fa, fa) == 0);
      // edge-pair separations, both orientations
      const int sigma = i % 3 == 0 ? -1 : 1;
      const auto ea = edge_separation_poly(p[0], p[1], p[2], p[3], p[4], p[5], sigma);
      const Vec3<mpq_class> n = cross(Vec3<mpq_class>(q(p[1]) - q(p[0])), Vec3<mpq_class>(q(p[3]) - q(p[2])));
      Separation<mpq_class> oe{dot(n, Vec3<mpq_class>(q(p[5]) - q(p[4]))), dot(n, n)};
      if (sigma < 0) oe.num = -oe.num;
      if (sgn(oe.norm2) != 0) REQUIRE(compare_exact(ea, fa) == sepax::compare(oe, oa));
      ++total;
      equal += want == 0;
    }
  }
  CHECK(equal > 0);  // exact ties were exercised
  CHECK(equal < total);
}

TEST_CASE("compare_exact: same separation at different scales is a tie", "[separation]") {
  // The face (0,0,0),(1,0,0),(0,1,0) and the same face scaled by 3 give
  // different N but the same height for p = (0,0,2).
  const Vec3<double> o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), x3(3, 0, 0), y3(0, 3, 0), p(0, 0, 2);
  CHECK(compare_exact(face_separation_poly(o, x, y, p), face_separation_poly(o, x3, y3, p)) == 0);
  CHECK(compare_exact(face_separation_poly(o, x, y, p),
                      face_separation_poly(o, x3, y3, Vec3<double>(0, 0, 2.0000000000000004))) == -1);
  CHECK(compare_exact(face_separation_poly(o, x, y, Vec3<double>(0, 0, -1)),
                      face_separation_poly(o, x3, y3, Vec3<double>(0, 0, -1.0000000000000002))) == 1);
}

namespace {

// compare_interval on two face separations (the kernel's stage 2).
template <class F>
int interval_faces(const Vec3<F>* a, const Vec3<F>* b) {
  return compare_interval([&] { return face_separation_poly<IntervalFloat>(a[0], a[1], a[2], a[3]); },
                          [&] { return face_separation_poly<IntervalFloat>(b[0], b[1], b[2], b[3]); });
}

}  // namespace

TEST_CASE("compare_interval decides only what compare_exact decides, and decides near ties of floats",
          "[separation]") {
  std::mt19937_64 rng(29);
  int decided = 0, undecided = 0, total = 0;
  for (double scale : {1.0, 1e-30, 1e30, 1e-100, 1e100}) {
    for (int i = 0; i < 2000; ++i) {
      const bool grid = i % 2 == 0;
      Vec3<double> p[8];
      for (auto& v : p) v = rnd(rng, scale, grid);
      if (i % 4 == 1) p[7] = p[3] + Vec3<double>(0, 0, p[3][2] * 0x1p-40);  // near tie
      const auto fa = face_separation_poly(p[0], p[1], p[2], p[3]);
      const auto fb = face_separation_poly(p[4], p[5], p[6], p[7]);
      if (exact_sign(fa.norm2) == 0 || exact_sign(fb.norm2) == 0) continue;
      ++total;
      const int s = interval_faces(p, p + 4);
      if (s == kUncertain) {
        ++undecided;
        continue;
      }
      ++decided;
      REQUIRE(s == compare_exact(fa, fb));
      // the edge-pair form, both orientations, against the exact stage
      const int sigma = i % 3 == 0 ? -1 : 1;
      const int e = compare_interval(
          [&] { return edge_separation_poly<IntervalFloat>(p[0], p[1], p[2], p[3], p[4], p[5], sigma); },
          [&] { return face_separation_poly<IntervalFloat>(p[4], p[5], p[6], p[7]); });
      const auto ee = edge_separation_poly(p[0], p[1], p[2], p[3], p[4], p[5], sigma);
      if (e != kUncertain && exact_sign(ee.norm2) != 0) REQUIRE(e == compare_exact(ee, fb));
    }
  }
  CHECK(decided > total / 2);  // the common case: separated by the enclosures
  CHECK(undecided > 0);        // ties and overflow (1e100^10) go on to the exact stage

  // Float inputs one float ulp apart: the kernel's float filter cannot order
  // them (its bound is about 1e-5 of the size), the enclosures can.
  const Vec3<float> f1[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25f, 0.5f, 2}};
  const Vec3<float> f2[4] = {{0, 0, 0}, {3, 0, 0}, {0, 3, 0}, {0.5f, 0.25f, std::nextafter(2.0f, 3.0f)}};
  CHECK(interval_faces(f1, f2) == -1);
  CHECK(interval_faces(f2, f1) == 1);
  // An exact tie (different faces, the same height) whose polynomials are
  // exact in double: every interval is a point, and the point [0, 0] is the
  // exact 0 of compare_exact.
  const Vec3<float> f3[4] = {{0, 0, 0}, {3, 0, 0}, {0, 3, 0}, {0.5f, 0.25f, 2}};
  CHECK(interval_faces(f1, f3) == 0);
  CHECK(compare_exact(face_separation_poly(f1[0], f1[1], f1[2], f1[3]),
                      face_separation_poly(f3[0], f3[1], f3[2], f3[3])) == 0);
  // Overflow: enclosures become infinite, the stage does not decide.
  const Vec3<float> big[4] = {{0, 0, 0}, {3e37f, 0, 0}, {0, 3e37f, 0}, {1, 1, 3e37f}};
  const Vec3<float> big2[4] = {{0, 0, 0}, {3e37f, 0, 0}, {0, 3e37f, 0}, {1, 1, 2e37f}};
  CHECK(interval_faces(big, big2) == kUncertain);
  CHECK(compare_exact(face_separation_poly(big[0], big[1], big[2], big[3]),
                      face_separation_poly(big2[0], big2[1], big2[2], big2[3])) == 1);
}
