// SPDX-License-Identifier: GPL-3.0-or-later
// Batch inverse and forward kinematics on structure-of-arrays buffers: the same mathematics as
// inverse() / forward() in kinematics.hpp (derivation: docs/kinematics.md), written as
// branch-free loops that the compiler vectorises, with polynomial atan2 / sin / cos instead of
// libm calls and an optional split across two threads. For workspace maps, path previews and
// other jobs that convert millions of points; single points keep using the exact scalar API.
//
// Accuracy contract (tested in tests/core/batch_test.cpp): the same ok/not-ok verdict as the
// scalar API (except for points within rounding of the kReachToleranceMm band edge), every
// angle within kBatchAngleToleranceRad of inverse(), and every point within
// kBatchPositionToleranceMm of forward() wherever the type II margin exceeds 1e-3 rad (closer
// in, forward kinematics itself is ill-conditioned, docs/kinematics.md section 8).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/kinematics/geometry.hpp"
#include "core/kinematics/modes.hpp"

namespace fivebar {

// Largest difference (rad, modulo 2 pi) between a batch angle and the scalar inverse().
inline constexpr double kBatchAngleToleranceRad = 1e-7;
// Largest distance (mm) between a batch end-effector and the scalar forward(), for machines of
// up to about a metre.
inline constexpr double kBatchPositionToleranceMm = 1e-7;

// Which compiled variant of the loops runs. Auto picks the best one this CPU supports; the
// others exist so that tests and benchmarks can exercise and compare every variant.
enum class BatchKernel { Auto, Generic, Avx2, Avx512 };

struct BatchOptions {
  // Threads used for one call (the caller's thread counts as one). 1 = never spawn a thread.
  unsigned maxThreads = 2;
  // Below this many points per thread the call stays on the caller's thread: spawning a thread
  // costs tens of microseconds.
  std::size_t minPointsPerThread = std::size_t{1} << 16;
  // A variant the CPU does not support (batchKernelSupported) runs as Auto instead.
  BatchKernel kernel = BatchKernel::Auto;
};

// Inverse kinematics of n points in one working mode.
//   x[i], y[i]: end-effector in mm, machine frame.
//   theta1[i], theta2[i]: motor angles in rad, in (-pi, pi], when ok[i] == 1;
//   NaN and ok[i] == 0 when either leg cannot reach the point (same reach rule and
//   kReachToleranceMm as inverseArm1/2) or the point lies on a motor axis.
// Input and output arrays must not overlap. n == 0 is allowed (null pointers then too).
void inverseBatch(const Geometry& g, WorkingMode mode, const double* x, const double* y,
                  std::size_t n, double* theta1, double* theta2, std::uint8_t* ok,
                  const BatchOptions& options = {});

// Forward kinematics of n motor-angle pairs in one assembly mode.
//   theta1[i], theta2[i]: rad, any value with |theta| < 1e5 (unwrapped angles are fine).
//   x[i], y[i]: end-effector in mm when ok[i] == 1; NaN and ok[i] == 0 when the floating links
//   cannot close the loop or the elbows coincide (FkStatus CannotClose / Degenerate).
// Input and output arrays must not overlap.
void forwardBatch(const Geometry& g, AssemblyMode mode, const double* theta1, const double* theta2,
                  std::size_t n, double* x, double* y, std::uint8_t* ok,
                  const BatchOptions& options = {});

// Whether this CPU (and build) can run the variant. Auto and Generic always can.
bool batchKernelSupported(BatchKernel kernel);
// "auto", "generic", "avx2+fma", "avx512".
std::string_view toString(BatchKernel kernel);
// The variant Auto resolves to on this machine, by name: "avx512", "avx2+fma" or "generic".
std::string_view batchKernelName();

}  // namespace fivebar
