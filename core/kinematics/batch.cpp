// SPDX-License-Identifier: GPL-3.0-or-later
// Batch kinematics (batch.hpp). Symbols follow docs/kinematics.md: motor Mi at (mx, 0), driving
// link ai, floating link bi, chord M->P of length d, elbow angle alpha at the motor.
//
// How the loops stay fast:
//  - one flat loop per kernel over i, no early exits, no libm calls: every branch is a select,
//    so GCC vectorises the loop (this file is compiled with -O3 -fno-math-errno, see
//    core/CMakeLists.txt);
//  - the kernel bodies are always_inline and instantiated three times, for AVX-512, AVX2+FMA and
//    the baseline ISA; the best one is picked once with __builtin_cpu_supports;
//  - large batches are split across two threads (BatchOptions).
#include "core/kinematics/batch.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <system_error>
#include <thread>
#include <vector>

#include "core/kinematics/kinematics.hpp"

#if defined(__GNUC__)
#define FIVEBAR_INLINE inline __attribute__((always_inline))
#else
#define FIVEBAR_INLINE inline
#endif

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define FIVEBAR_X86_DISPATCH 1
#endif

namespace fivebar {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kHalfPi = kPi / 2.0;
constexpr double kQuarterPi = kPi / 4.0;
// Same as kinematics.cpp: below this chord length (mm) the direction of a leg is undefined.
constexpr double kMinChordMm = 1e-12;

// ---- polynomial elementary functions (select-only, vectorisable) ----------------------------

// Polynomial c[0] z^(N-1) + ... + c[N-1] by Horner's rule (fully unrolled: N is a constant).
template <std::size_t N>
FIVEBAR_INLINE double horner(double z, const std::array<double, N>& c) {
  double r = c[0];
  for (std::size_t i = 1; i < N; ++i) r = r * z + c[i];
  return r;
}

// atan(t) for t in [-0.42, 0.66]: Cephes rational approximation (S. Moshier),
// atan(t) = t + t z P(z) / Q(z) with z = t^2, relative error about 1e-16. Used after range
// reduction only.
constexpr std::array<double, 5> kAtanP{-8.750608600031904122785e-1, -1.615753718733365076637e1,
                                       -7.500855792314704667340e1, -1.228866684490136173410e2,
                                       -6.485021904942025371773e1};
constexpr std::array<double, 6> kAtanQ{1.0,
                                       2.485846490142306297962e1,
                                       1.650270098316988542046e2,
                                       4.328810604912902668951e2,
                                       4.853903996359136964868e2,
                                       1.945506571482613964425e2};
FIVEBAR_INLINE double atanReduced(double t) {
  const double z = t * t;
  return t + t * z * horner(z, kAtanP) / horner(z, kAtanQ);
}

// atan2(y, x) in (-pi, pi], absolute error below 1e-15 rad; atan2(0, 0) = 0.
FIVEBAR_INLINE double atan2Poly(double y, double x) {
  const double ax = std::fabs(x), ay = std::fabs(y);
  const double hi = ax > ay ? ax : ay;
  const double lo = ax > ay ? ay : ax;
  // Ratio lo/hi in [0, 1]; above 0.66 use atan(r) = pi/4 + atan((r - 1) / (r + 1)).
  const bool upper = lo > 0.66 * hi;
  const double num = upper ? lo - hi : lo;
  const double den = upper ? lo + hi : hi;
  const double safeDen = den > 0.0 ? den : 1.0;
  double r = atanReduced(num / safeDen) + (upper ? kQuarterPi : 0.0);
  r = ay > ax ? kHalfPi - r : r;
  r = x < 0.0 ? kPi - r : r;
  return y < 0.0 ? -r : r;
}

// Taylor coefficients of (sin(r) - r) / r^3 and (cos(r) - 1) / r^2 in z = r^2, highest first.
constexpr std::array<double, 8> kSinTaylor{
    1.0 / 355687428096000.0, -1.0 / 1307674368000.0, 1.0 / 6227020800.0, -1.0 / 39916800.0,
    1.0 / 362880.0,          -1.0 / 5040.0,          1.0 / 120.0,        -1.0 / 6.0};
constexpr std::array<double, 9> kCosTaylor{
    -1.0 / 6402373705728000.0, 1.0 / 20922789888000.0, -1.0 / 87178291200.0,
    1.0 / 479001600.0,         -1.0 / 3628800.0,       1.0 / 40320.0,
    -1.0 / 720.0,              1.0 / 24.0,             -0.5};

// sin and cos of any |theta| < 1e5 rad. Cody-Waite reduction by pi/2 (the first constant has
// 33 significant bits, so q * kPio2Hi is exact for |q| < 2^20), then Taylor series to degree
// 17/18 on |r| <= pi/4, whose truncation error is below 1e-18.
struct SinCos {
  double s;
  double c;
};
FIVEBAR_INLINE SinCos sinCosPoly(double theta) {
  constexpr double kPio2Hi = 1.57079632673412561417e+00;
  constexpr double kPio2Lo = 6.07710050650619224932e-11;
  constexpr double kRoundMagic = 6755399441055744.0;  // 1.5 * 2^52: x + magic - magic rounds x
  const double q = (theta * (2.0 / kPi) + kRoundMagic) - kRoundMagic;
  const double r = (theta - q * kPio2Hi) - q * kPio2Lo;
  const double z = r * r;
  const double sr = r + r * z * horner(z, kSinTaylor);
  const double cr = 1.0 + z * horner(z, kCosTaylor);
  // Quadrant m = q mod 4 in {0, 1, 2, 3}, in floating point (no integer conversion, and no
  // floor(), which baseline x86-64 cannot vectorise): floor(q / 4) is the nearest integer to
  // (q - 1.5) / 4, whose fraction is never one half.
  const double m = q - 4.0 * (((q - 1.5) * 0.25 + kRoundMagic) - kRoundMagic);
  const bool odd = (m == 1.0) | (m == 3.0);
  const double s = odd ? cr : sr;
  const double c = odd ? sr : cr;
  return {m >= 2.0 ? -s : s, ((m == 1.0) | (m == 2.0)) ? -c : c};
}

// ---- inverse kinematics ---------------------------------------------------------------------

// One leg's constants: motor at (mx, 0), links a, b, reach band, and the elbow side.
struct LegConstants {
  double mx = 0.0;
  double a = 0.0;
  double b = 0.0;
  double outerMax = 0.0;  // a + b + kReachToleranceMm
  double innerMin = 0.0;  // |a - b| - kReachToleranceMm
  double side = 1.0;      // +1: elbow counter-clockwise of the chord M->P, -1: clockwise
};

LegConstants legConstants(double mx, double a, double b, bool counterClockwise) {
  return {mx, a, b, a + b + kReachToleranceMm, std::abs(a - b) - kReachToleranceMm,
          counterClockwise ? 1.0 : -1.0};
}

// Motor angle of one leg reaching (x, y), or NaN. With C = a^2 + d^2 - b^2 = 2 a d cos(alpha)
// and S = 2 a d sin(alpha) = sqrt((b-a+d)(b+a-d)(a+d-b)(a+d+b)) (product form: exact near the
// reach boundary, where acos of a rounded cosine would lose half the digits), the elbow
// direction is C * (dx, dy) + side * S * (-dy, dx), and theta is its atan2.
FIVEBAR_INLINE double legAngle(const LegConstants& k, double x, double y) {
  const double dx = x - k.mx, dy = y;
  const double d = std::sqrt(dx * dx + dy * dy);
  const bool reachable = (d <= k.outerMax) & (d >= k.innerMin) & (d >= kMinChordMm);
  const double C = k.a * k.a + d * d - k.b * k.b;
  const double S2 = (k.b - k.a + d) * (k.b + k.a - d) * (k.a + d - k.b) * (k.a + d + k.b);
  const double S = k.side * std::sqrt(S2 > 0.0 ? S2 : 0.0);
  const double theta = atan2Poly(C * dy + S * dx, C * dx - S * dy);
  return reachable ? theta : kNaN;
}

struct IkConstants {
  LegConstants leg1;
  LegConstants leg2;
};

// ok[i] = 1 where v[i] is a number, 0 where NaN. A separate loop: GCC does not vectorise a
// loop that mixes 64-bit lanes with byte stores under a mask.
FIVEBAR_INLINE void flagNumbers(const double* __restrict v, std::size_t begin, std::size_t end,
                                std::uint8_t* __restrict ok) {
  for (std::size_t i = begin; i < end; ++i) ok[i] = static_cast<std::uint8_t>(v[i] == v[i]);
}

// Points per block: the flag pass re-reads the block while it is still in L1.
constexpr std::size_t kBlock = 512;

FIVEBAR_INLINE void ikLoop(const IkConstants& k, const double* __restrict x,
                           const double* __restrict y, std::size_t begin, std::size_t end,
                           double* __restrict theta1, double* __restrict theta2,
                           std::uint8_t* __restrict ok) {
  for (std::size_t block = begin; block < end; block += kBlock) {
    const std::size_t blockEnd = end - block > kBlock ? block + kBlock : end;
    for (std::size_t i = block; i < blockEnd; ++i) {
      const double t1 = legAngle(k.leg1, x[i], y[i]);
      const double t2 = legAngle(k.leg2, x[i], y[i]);
      // NaN in either leg makes both NaN: t - t is exactly 0 for a number, NaN for NaN.
      theta1[i] = t1 + (t2 - t2);
      theta2[i] = t2 + (t1 - t1);
    }
    flagNumbers(theta1, block, blockEnd, ok);
  }
}

// ---- forward kinematics ---------------------------------------------------------------------

struct FkConstants {
  double halfW = 0.0;
  double a1 = 0.0, a2 = 0.0;
  double sumB = 0.0;           // b1 + b2
  double diffB = 0.0;          // b1 - b2
  double b1b1MinusB2b2 = 0.0;  // b1^2 - b2^2
  double closeMax = 0.0;       // b1 + b2 + kReachToleranceMm
  double closeMin = 0.0;       // |b1 - b2| - kReachToleranceMm
  double side = 1.0;           // +1: P left of R1->R2 (assembly '+')
};

// Circle intersection as in forward(): with r = R2 - R1, d = |r|, P = R1 + (along/d) r +
// side (h/d) perp(r), along/d = (b1^2 - b2^2 + d^2) / (2 d^2) and h/d from the half-chord product
// form sqrt((b1+b2-d)(b1+b2+d)(d-b1+b2)(d+b1-b2)) / (2 d^2).
FIVEBAR_INLINE void fkPoint(const FkConstants& k, double theta1, double theta2, double& px,
                            double& py) {
  const SinCos q1 = sinCosPoly(theta1), q2 = sinCosPoly(theta2);
  const double R1x = -k.halfW + k.a1 * q1.c, R1y = k.a1 * q1.s;
  const double R2x = k.halfW + k.a2 * q2.c, R2y = k.a2 * q2.s;
  const double rx = R2x - R1x, ry = R2y - R1y;
  const double d2 = rx * rx + ry * ry;
  const double d = std::sqrt(d2);
  const bool closes = (d >= kMinChordMm) & (d <= k.closeMax) & (d >= k.closeMin);
  const double inv = 0.5 / (d2 > 0.0 ? d2 : 1.0);
  const double alongOverD = (k.b1b1MinusB2b2 + d2) * inv;
  const double fourD2H2 = (k.sumB - d) * (k.sumB + d) * (d - k.diffB) * (d + k.diffB);
  const double hOverD = k.side * std::sqrt(fourD2H2 > 0.0 ? fourD2H2 : 0.0) * inv;
  px = closes ? R1x + alongOverD * rx - hOverD * ry : kNaN;
  py = closes ? R1y + alongOverD * ry + hOverD * rx : kNaN;
}

FIVEBAR_INLINE void fkLoop(const FkConstants& k, const double* __restrict theta1,
                           const double* __restrict theta2, std::size_t begin, std::size_t end,
                           double* __restrict x, double* __restrict y,
                           std::uint8_t* __restrict ok) {
  for (std::size_t block = begin; block < end; block += kBlock) {
    const std::size_t blockEnd = end - block > kBlock ? block + kBlock : end;
    for (std::size_t i = block; i < blockEnd; ++i) fkPoint(k, theta1[i], theta2[i], x[i], y[i]);
    flagNumbers(x, block, blockEnd, ok);
  }
}

// ---- ISA variants and dispatch --------------------------------------------------------------

using IkKernel = void (*)(const IkConstants&, const double*, const double*, std::size_t,
                          std::size_t, double*, double*, std::uint8_t*);
using FkKernel = void (*)(const FkConstants&, const double*, const double*, std::size_t,
                          std::size_t, double*, double*, std::uint8_t*);

void ikGeneric(const IkConstants& k, const double* x, const double* y, std::size_t b,
               std::size_t e, double* t1, double* t2, std::uint8_t* ok) {
  ikLoop(k, x, y, b, e, t1, t2, ok);
}
void fkGeneric(const FkConstants& k, const double* t1, const double* t2, std::size_t b,
               std::size_t e, double* x, double* y, std::uint8_t* ok) {
  fkLoop(k, t1, t2, b, e, x, y, ok);
}

#if defined(FIVEBAR_X86_DISPATCH)
#define FIVEBAR_AVX2 __attribute__((target("avx2,fma")))
#define FIVEBAR_AVX512 \
  __attribute__((target("avx512f,avx512dq,avx512vl,avx512bw,avx2,fma,prefer-vector-width=512")))

FIVEBAR_AVX2 void ikAvx2(const IkConstants& k, const double* x, const double* y, std::size_t b,
                         std::size_t e, double* t1, double* t2, std::uint8_t* ok) {
  ikLoop(k, x, y, b, e, t1, t2, ok);
}
FIVEBAR_AVX2 void fkAvx2(const FkConstants& k, const double* t1, const double* t2, std::size_t b,
                         std::size_t e, double* x, double* y, std::uint8_t* ok) {
  fkLoop(k, t1, t2, b, e, x, y, ok);
}
FIVEBAR_AVX512 void ikAvx512(const IkConstants& k, const double* x, const double* y,
                             std::size_t b, std::size_t e, double* t1, double* t2,
                             std::uint8_t* ok) {
  ikLoop(k, x, y, b, e, t1, t2, ok);
}
FIVEBAR_AVX512 void fkAvx512(const FkConstants& k, const double* t1, const double* t2,
                             std::size_t b, std::size_t e, double* x, double* y,
                             std::uint8_t* ok) {
  fkLoop(k, t1, t2, b, e, x, y, ok);
}
#endif

// The best variant this CPU supports (never Auto).
BatchKernel detectBest() {
#if defined(FIVEBAR_X86_DISPATCH)
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
      __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw"))
    return BatchKernel::Avx512;
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return BatchKernel::Avx2;
#endif
  return BatchKernel::Generic;
}

BatchKernel bestKernel() {
  static const BatchKernel best = detectBest();
  return best;
}

// The variant that runs for a request: itself when supported, else the best one.
BatchKernel resolve(BatchKernel requested) {
  return requested != BatchKernel::Auto && batchKernelSupported(requested) ? requested
                                                                           : bestKernel();
}

IkKernel ikKernel(BatchKernel requested) {
  switch (resolve(requested)) {
#if defined(FIVEBAR_X86_DISPATCH)
    case BatchKernel::Avx512: return ikAvx512;
    case BatchKernel::Avx2: return ikAvx2;
#endif
    default: return ikGeneric;
  }
}

FkKernel fkKernel(BatchKernel requested) {
  switch (resolve(requested)) {
#if defined(FIVEBAR_X86_DISPATCH)
    case BatchKernel::Avx512: return fkAvx512;
    case BatchKernel::Avx2: return fkAvx2;
#endif
    default: return fkGeneric;
  }
}

// Runs kernel over [0, n), split into at most options.maxThreads contiguous chunks of at least
// options.minPointsPerThread points; the caller's thread takes the first chunk. Falls back to
// fewer threads if one cannot be started.
template <class Kernel, class Constants>
void runSplit(Kernel kernel, const Constants& k, const double* in1, const double* in2,
              std::size_t n, double* out1, double* out2, std::uint8_t* ok,
              const BatchOptions& options) {
  const std::size_t perThread = options.minPointsPerThread > 0 ? options.minPointsPerThread : 1;
  std::size_t chunks = std::min<std::size_t>(options.maxThreads, n / perThread);
  if (chunks < 2) {
    kernel(k, in1, in2, 0, n, out1, out2, ok);
    return;
  }
  const std::size_t chunk = (n + chunks - 1) / chunks;
  std::vector<std::thread> helpers;
  helpers.reserve(chunks);
  std::size_t begin = chunk;  // [0, chunk) stays on this thread
  try {
    for (; begin < n; begin += chunk)
      helpers.emplace_back(kernel, std::cref(k), in1, in2, begin, std::min(n, begin + chunk),
                           out1, out2, ok);
  } catch (const std::system_error&) {
    // Too few threads available: run what was not handed out here.
    kernel(k, in1, in2, begin, n, out1, out2, ok);
  }
  kernel(k, in1, in2, 0, chunk, out1, out2, ok);
  for (std::thread& t : helpers) t.join();
}

}  // namespace

void inverseBatch(const Geometry& g, WorkingMode mode, const double* x, const double* y,
                  std::size_t n, double* theta1, double* theta2, std::uint8_t* ok,
                  const BatchOptions& options) {
  if (n == 0) return;
  // Arm 1 '+' puts R1 counter-clockwise of M1->P; arm 2 '+' puts R2 clockwise of M2->P.
  const IkConstants k{
      legConstants(-0.5 * g.w, g.a1, g.b1, arm1Sign(mode) == ArmSign::Plus),
      legConstants(0.5 * g.w, g.a2, g.b2, arm2Sign(mode) == ArmSign::Minus)};
  runSplit(ikKernel(options.kernel), k, x, y, n, theta1, theta2, ok, options);
}

void forwardBatch(const Geometry& g, AssemblyMode mode, const double* theta1,
                  const double* theta2, std::size_t n, double* x, double* y, std::uint8_t* ok,
                  const BatchOptions& options) {
  if (n == 0) return;
  FkConstants k;
  k.halfW = 0.5 * g.w;
  k.a1 = g.a1;
  k.a2 = g.a2;
  k.sumB = g.b1 + g.b2;
  k.diffB = g.b1 - g.b2;
  k.b1b1MinusB2b2 = g.b1 * g.b1 - g.b2 * g.b2;
  k.closeMax = g.b1 + g.b2 + kReachToleranceMm;
  k.closeMin = std::abs(g.b1 - g.b2) - kReachToleranceMm;
  k.side = mode == AssemblyMode::Plus ? 1.0 : -1.0;
  runSplit(fkKernel(options.kernel), k, theta1, theta2, n, x, y, ok, options);
}

bool batchKernelSupported(BatchKernel kernel) {
  switch (kernel) {
    case BatchKernel::Auto:
    case BatchKernel::Generic: return true;
    case BatchKernel::Avx2:
      return bestKernel() == BatchKernel::Avx2 || bestKernel() == BatchKernel::Avx512;
    case BatchKernel::Avx512: return bestKernel() == BatchKernel::Avx512;
  }
  return false;
}

std::string_view toString(BatchKernel kernel) {
  switch (kernel) {
    case BatchKernel::Auto: return "auto";
    case BatchKernel::Generic: return "generic";
    case BatchKernel::Avx2: return "avx2+fma";
    case BatchKernel::Avx512: return "avx512";
  }
  return "auto";
}

std::string_view batchKernelName() { return toString(bestKernel()); }

}  // namespace fivebar
