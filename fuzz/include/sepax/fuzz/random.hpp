// sepax/fuzz/random.hpp
//
// The fuzzer's random numbers, fully specified so that a seed gives the same
// cases on every platform and standard library (std::uniform_*_distribution
// and std::normal_distribution are implementation-defined; std::hash too).
//
//   Rng::next()          splitmix64 (Steele, Lea, Flood 2014): state += golden
//                        gamma, then the variant-13 finaliser.  64 bits.
//   uniform_int(a, b)    a + (x mod n) for n = b - a + 1, drawing x again while
//                        it falls in the incomplete last block of n values
//                        (x >= 2^64 - (2^64 mod n)): unbiased.
//   uniform01()          (next() >> 11) * 2^-53: the 2^53 doubles k 2^-53 in
//                        [0, 1), each with probability 2^-53.
//   uniform(a, b)        a + (b - a) * uniform01(), in double arithmetic
//                        (IEEE, round to nearest: the same on every platform).
// Derived values (log-uniform numbers, directions) also use std::log,
// std::exp, std::cos, std::sin; those come from the C library's libm and are
// identical wherever the same libm is used (libstdc++ and libc++ on glibc).
#pragma once

#include <cstdint>
#include <string_view>

namespace sepax::fuzz {

struct Rng {
  std::uint64_t state;
  explicit Rng(std::uint64_t seed) : state(seed) {}

  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// Uniform integer in [a, b] (a <= b), unbiased.
  int uniform_int(int a, int b) {
    const std::uint64_t n = static_cast<std::uint64_t>(static_cast<std::int64_t>(b) - a) + 1;
    const std::uint64_t limit = 0 - (0 - n) % n;  // 2^64 - (2^64 mod n), as 0 when n divides 2^64
    std::uint64_t x = next();
    while (limit != 0 && x >= limit) x = next();
    return static_cast<int>(a + static_cast<std::int64_t>(x % n));
  }
  /// Uniform double in [0, 1): k 2^-53 for a uniform 53-bit k.
  double uniform01() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  /// a + (b - a) u for u = uniform01().
  double uniform(double a, double b) { return a + (b - a) * uniform01(); }
};

/// The seed of case `index` of a campaign with seed `campaign_seed`: a pure
/// function of the two, so a campaign is the same cases whatever the number of
/// workers that run it (splitmix64's finaliser over a mix of both).
inline std::uint64_t case_seed(std::uint64_t campaign_seed, std::uint64_t index) {
  Rng r(campaign_seed * 0xD1B54A32D192ED03ull ^ index);
  return r.next();
}

/// FNV-1a (64 bit) of a family name: a portable replacement for std::hash.
inline std::uint64_t name_hash(std::string_view s) {
  std::uint64_t h = 0xCBF29CE484222325ull;
  for (const char ch : s) {
    h ^= static_cast<unsigned char>(ch);
    h *= 0x100000001B3ull;
  }
  return h;
}

}  // namespace sepax::fuzz
