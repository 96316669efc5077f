// Direct tests of CGAL/Surface_voronoi_diagram/internal/exact_predicates.h: the filtered
// signs against an exact rational oracle computed here, on random inputs and on inputs made
// to defeat double arithmetic (exact zeros, near-zeros where the naive double sign is wrong,
// huge and tiny magnitudes, the (1, 1, 1) row), plus antisymmetry under row swaps.
#include <catch2/catch.hpp>

#include <CGAL/Surface_voronoi_diagram/internal/exact_predicates.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_exact_predicates {

namespace {

namespace SVI = CGAL::Surface_voronoi::internal;
typedef CGAL::Exact_rational Ep_q;

// A double in [-1, 1) with 53 random bits, from the raw engine output (portable).
double ep_unit(std::mt19937_64& rng)
{
  return std::ldexp(double(rng() >> 11), -52) - 1.0;
}

// A double with a random sign, mantissa and a binary exponent in [-spread, spread].
double ep_any(std::mt19937_64& rng, int spread)
{
  const int e = int(rng() % std::uint64_t(2 * spread + 1)) - spread;
  return std::ldexp(ep_unit(rng), e);
}

// A multiple of 2^-bits in [0, 1): every sum and difference of two of them is exact.
double ep_dyadic(std::mt19937_64& rng, int bits)
{
  return std::ldexp(double(rng() >> (64 - bits)), -bits);
}

int ep_sign(const Ep_q& x) { return (x > 0) - (x < 0); }

int ep_oracle2(double a1, double a2, double b1, double b2, double c1, double c2, double d1, double d2)
{
  const Ep_q A = Ep_q(a1) - Ep_q(a2), B = Ep_q(b1) - Ep_q(b2), C = Ep_q(c1) - Ep_q(c2), D = Ep_q(d1) - Ep_q(d2);
  return ep_sign(A * D - B * C);
}

// the naive double evaluation, to show that an input really defeats double arithmetic
int ep_naive2(double a1, double a2, double b1, double b2, double c1, double c2, double d1, double d2)
{
  const double det = (a1 - a2) * (d1 - d2) - (b1 - b2) * (c1 - c2);
  return (det > 0) - (det < 0);
}

typedef std::array<double, 3> Ep_row;

struct Ep_rows
{
  Ep_row p0, q0, p1, q1, p2, q2;
  bool unit_row;   // third row (1, 1, 1) instead of p2 - q2
};

int ep_oracle3(const Ep_rows& r)
{
  Ep_q m[3][3];
  for(int k = 0; k < 3; ++k)
  {
    m[0][k] = Ep_q(r.p0[k]) - Ep_q(r.q0[k]);
    m[1][k] = Ep_q(r.p1[k]) - Ep_q(r.q1[k]);
    m[2][k] = r.unit_row ? Ep_q(1) : Ep_q(r.p2[k]) - Ep_q(r.q2[k]);
  }
  // expansion along the second column, unlike the library's first-row expansion
  const Ep_q det = -m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                   + m[1][1] * (m[0][0] * m[2][2] - m[0][2] * m[2][0])
                   - m[2][1] * (m[0][0] * m[1][2] - m[0][2] * m[1][0]);
  return ep_sign(det);
}

int ep_naive3(const Ep_rows& r)
{
  double m[3][3];
  for(int k = 0; k < 3; ++k)
  {
    m[0][k] = r.p0[k] - r.q0[k];
    m[1][k] = r.p1[k] - r.q1[k];
    m[2][k] = r.unit_row ? 1.0 : r.p2[k] - r.q2[k];
  }
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                     + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return (det > 0) - (det < 0);
}

int ep_library3(const Ep_rows& r, int order)
{
  const SVI::Difference_row r0 = { r.p0.data(), r.q0.data() }, r1 = { r.p1.data(), r.q1.data() };
  const SVI::Difference_row r2 = { r.p2.data(), r.q2.data() };
  const SVI::Difference_row* third = r.unit_row ? nullptr : &r2;
  switch(order)
  {
  case 0: return SVI::sign_of_det3_of_differences(r0, r1, third);
  case 1: return SVI::sign_of_det3_of_differences(r1, r0, third);   // rows 0 and 1 swapped
  default: return SVI::sign_of_det3_of_differences(r0, r2, &r1);   // rows 1 and 2 swapped
  }
}

// checks det2 against the oracle and its antisymmetry (rows swapped, columns swapped)
void ep_check2(double a1, double a2, double b1, double b2, double c1, double c2, double d1, double d2)
{
  const int expected = ep_oracle2(a1, a2, b1, b2, c1, c2, d1, d2);
  INFO("det2 input " << a1 << " " << a2 << " " << b1 << " " << b2 << " " << c1 << " " << c2 << " " << d1 << " " << d2);
  CHECK(SVI::sign_of_det2_of_differences(a1, a2, b1, b2, c1, c2, d1, d2) == expected);
  CHECK(SVI::sign_of_det2_of_differences(c1, c2, d1, d2, a1, a2, b1, b2) == -expected);
  CHECK(SVI::sign_of_det2_of_differences(b1, b2, a1, a2, d1, d2, c1, c2) == -expected);
}

void ep_check3(const Ep_rows& r)
{
  const int expected = ep_oracle3(r);
  CHECK(ep_library3(r, 0) == expected);
  CHECK(ep_library3(r, 1) == -expected);
  if(!r.unit_row) CHECK(ep_library3(r, 2) == -expected);
}

Ep_row ep_random_row(std::mt19937_64& rng, int spread)
{
  return {{ ep_any(rng, spread), ep_any(rng, spread), ep_any(rng, spread) }};
}

} // namespace

TEST_CASE("det2 of differences agrees with exact rationals on random inputs", "[exact_predicates]")
{
  std::mt19937_64 rng(20260101);
  for(int n = 0; n < 4000; ++n)
  {
    // differences of nearby numbers (cancellation) as well as of unrelated ones
    const double base = ep_any(rng, 30);
    auto near = [&] { return base + ep_any(rng, 4) * std::ldexp(1., -int(rng() % 50)); };
    ep_check2(near(), near(), near(), near(), near(), near(), near(), near());
    ep_check2(ep_any(rng, 8), ep_any(rng, 8), ep_any(rng, 8), ep_any(rng, 8), ep_any(rng, 8), ep_any(rng, 8),
              ep_any(rng, 8), ep_any(rng, 8));
  }
}

TEST_CASE("det2 of differences: exact zeros built from representable values", "[exact_predicates]")
{
  std::mt19937_64 rng(7);
  int naive_nonzero = 0;
  for(int n = 0; n < 3000; ++n)
  {
    // B = 3A and D = 3C exactly (50-bit numbers times 3 are doubles), so A*D - B*C = 0,
    // while the roundings of A and 3A (C and 3C) differ and the double result need not be 0.
    const double a1 = ep_dyadic(rng, 49) * 2, a2 = std::ldexp(ep_dyadic(rng, 50), -10);
    const double c1 = ep_dyadic(rng, 50), c2 = -ep_dyadic(rng, 50) * 0.5;
    REQUIRE(ep_oracle2(a1, a2, 3 * a1, 3 * a2, c1, c2, 3 * c1, 3 * c2) == 0);
    naive_nonzero += ep_naive2(a1, a2, 3 * a1, 3 * a2, c1, c2, 3 * c1, 3 * c2) != 0;
    ep_check2(a1, a2, 3 * a1, 3 * a2, c1, c2, 3 * c1, 3 * c2);
    // the same point twice: A = C and B = D
    ep_check2(a1, a2, c1, c2, a1, a2, c1, c2);
  }
  // the construction must really produce zeros that double arithmetic gets wrong
  CHECK(naive_nonzero > 100);
}

TEST_CASE("det2 of differences: near-zeros whose double sign is wrong fall back to exact", "[exact_predicates]")
{
  // hand-made: A = 1 + 2^-60 rounds to 1, so A*D - B*C evaluates to 0 in double; exactly it is 2^-60
  const double tiny = std::ldexp(1., -60);
  REQUIRE(ep_naive2(1., -tiny, 1., 0., 1., 0., 1., 0.) == 0);
  REQUIRE(ep_oracle2(1., -tiny, 1., 0., 1., 0., 1., 0.) == 1);
  ep_check2(1., -tiny, 1., 0., 1., 0., 1., 0.);

  // searched: D chosen so that A*D - B*C is within rounding of 0; keep those where double lies
  std::mt19937_64 rng(99);
  int wrong_sign = 0, wrong_zero = 0;
  for(int n = 0; n < 20000; ++n)
  {
    const double a1 = ep_any(rng, 20), a2 = a1 * (1 + ep_unit(rng) * 1e-3), b1 = ep_any(rng, 20), b2 = ep_any(rng, 20);
    const double c1 = ep_any(rng, 20), c2 = c1 * (1 + ep_unit(rng) * 1e-6), d2 = ep_any(rng, 20);
    const double A = a1 - a2;
    if(A == 0) continue;
    const double d1 = d2 + (b1 - b2) * (c1 - c2) / A;
    const int naive = ep_naive2(a1, a2, b1, b2, c1, c2, d1, d2);
    const int exact = ep_oracle2(a1, a2, b1, b2, c1, c2, d1, d2);
    wrong_sign += (naive * exact < 0);
    wrong_zero += (naive != 0 && exact == 0) || (naive == 0 && exact != 0);
    ep_check2(a1, a2, b1, b2, c1, c2, d1, d2);
  }
  CHECK(wrong_sign > 100);
  CHECK(wrong_zero + wrong_sign > 100);
}

TEST_CASE("det2 of differences: huge and tiny magnitudes", "[exact_predicates]")
{
  std::mt19937_64 rng(5);
  // products near the top of the range (overflow to infinity must not decide) and near the
  // bottom of the normal range; ties at such scales too
  for(int e : { -500, -480, -250, 250, 500, 511, 530, 600 })
    for(int n = 0; n < 500; ++n)
    {
      double v[8];
      for(double& x : v) x = std::ldexp(ep_unit(rng), e);
      ep_check2(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
      ep_check2(v[0], v[1], v[2], v[3], v[0], v[1], v[2], v[3]);
    }
  // mixed scales: one huge difference against one tiny one
  ep_check2(1e300, -1e300, 1e-300, 0., 1e-300, 0., 1e300, 1e299);
  ep_check2(1e300, 1e300, 1e-300, 0., 1e-300, 0., 1e300, 1e299);
}

TEST_CASE("det2 of differences: products that underflow do not defeat the filter", "[exact_predicates]")
{
  // Built by a search over tiny inputs: A = a1 - a2 is rounded up, so fl(A)*D lands above a
  // rounding boundary of the subnormal grid that the exact A*D stays below, and B*C lies
  // between the two. Double gives fl(A*D) - fl(B*C) = +1 subnormal unit while the error bound,
  // a relative one, underflows to 0; the exact sign is -1.
  const double a1 = 0x1.2aaaaaaaaaaabp-534, a2 = 0x1.aaaaaaaaaaaabp-588;
  const double b1 = 0x1.45d1745d1745dp-536, c1 = 0x1.6p-537, d1 = 0x1.8p-539;
  REQUIRE(ep_oracle2(a1, a2, b1, 0., c1, 0., d1, 0.) == -1);
  REQUIRE(ep_naive2(a1, a2, b1, 0., c1, 0., d1, 0.) == 1);
  CHECK(SVI::sign_of_det2_of_differences(a1, a2, b1, 0., c1, 0., d1, 0.) == -1);
}

TEST_CASE("det3 of differences agrees with exact rationals on random inputs", "[exact_predicates]")
{
  std::mt19937_64 rng(31337);
  for(int n = 0; n < 3000; ++n)
  {
    Ep_rows r{ ep_random_row(rng, 6), ep_random_row(rng, 6), ep_random_row(rng, 6), ep_random_row(rng, 6),
               ep_random_row(rng, 6), ep_random_row(rng, 6), n % 2 == 0 };
    ep_check3(r);
  }
}

TEST_CASE("det3 of differences: exact zeros and the (1,1,1) row", "[exact_predicates]")
{
  std::mt19937_64 rng(11);
  int naive_nonzero = 0;
  for(int n = 0; n < 2000; ++n)
  {
    Ep_rows r{};
    for(int k = 0; k < 3; ++k)
    {
      r.p0[k] = ep_dyadic(rng, 40) * 3 - 1.5; r.q0[k] = ep_dyadic(rng, 40);
      r.p2[k] = ep_dyadic(rng, 40); r.q2[k] = ep_dyadic(rng, 40) - 0.5;
    }
    // row 1 = row 0 + (1, 1, 1): dependent on the unit row
    for(int k = 0; k < 3; ++k) { r.p1[k] = r.p0[k] + 1; r.q1[k] = r.q0[k]; }
    r.unit_row = true;
    REQUIRE(ep_oracle3(r) == 0);
    naive_nonzero += ep_naive3(r) != 0;
    ep_check3(r);
    // row 2 = row 0 + row 1 (sums of 40-bit dyadics are exact)
    for(int k = 0; k < 3; ++k)
    {
      r.p1[k] = ep_dyadic(rng, 40) * 5; r.q1[k] = ep_dyadic(rng, 40) * 0.25;
      r.p2[k] = r.p0[k] + r.p1[k]; r.q2[k] = r.q0[k] + r.q1[k];
    }
    r.unit_row = false;
    REQUIRE(ep_oracle3(r) == 0);
    naive_nonzero += ep_naive3(r) != 0;
    ep_check3(r);
  }
  CHECK(naive_nonzero > 50);
}

TEST_CASE("det3 of differences: near-zeros whose double sign is wrong fall back to exact", "[exact_predicates]")
{
  std::mt19937_64 rng(2024);
  int wrong_sign = 0;
  for(int n = 0; n < 20000; ++n)
  {
    Ep_rows r{ ep_random_row(rng, 10), ep_random_row(rng, 10), ep_random_row(rng, 10), ep_random_row(rng, 10),
               {}, {}, n % 2 == 1 };
    const double alpha = ep_any(rng, 3), beta = ep_any(rng, 3);
    if(r.unit_row)
    {
      // row 1 := alpha * row 0 + beta * (1, 1, 1), rounded
      for(int k = 0; k < 3; ++k) r.p1[k] = r.q1[k] + alpha * (r.p0[k] - r.q0[k]) + beta;
    }
    else
    {
      // row 2 := alpha * row 0 + beta * row 1, rounded
      for(int k = 0; k < 3; ++k)
      {
        r.q2[k] = ep_any(rng, 10);
        r.p2[k] = r.q2[k] + alpha * (r.p0[k] - r.q0[k]) + beta * (r.p1[k] - r.q1[k]);
      }
    }
    const int naive = ep_naive3(r), exact = ep_oracle3(r);
    wrong_sign += naive * exact < 0;
    ep_check3(r);
  }
  CHECK(wrong_sign > 100);
}

TEST_CASE("det3 of differences: huge and tiny magnitudes", "[exact_predicates]")
{
  std::mt19937_64 rng(8);
  for(int e : { -330, -300, -150, 150, 300, 340, 400 })
    for(int n = 0; n < 300; ++n)
    {
      Ep_rows r{};
      for(Ep_row* row : { &r.p0, &r.q0, &r.p1, &r.q1, &r.p2, &r.q2 })
        for(double& x : *row) x = std::ldexp(ep_unit(rng), e);
      r.unit_row = (n % 3 == 0);
      ep_check3(r);
      r.p1 = r.p0; r.q1 = r.q0;   // two equal rows: an exact zero at every scale
      ep_check3(r);
    }
}

} // namespace svd_test_exact_predicates
