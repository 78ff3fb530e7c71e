// SPDX-License-Identifier: GPL-3.0-or-later
// Test support for the drivers: a deterministic in-process link (GrblProtocol <-> SimMachine
// with a stepped clock), job generation inside a preset's workspace, stroke comparison.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/kinematics/kinematics.hpp"
#include "core/machine/profile.hpp"
#include "core/kinematics/units.hpp"
#include "drivers/stream/gcode_job.hpp"
#include "drivers/protocol/grbl_protocol.hpp"
#include "drivers/sim/sim_machine.hpp"
#include "test_support.hpp"

namespace fivebar::test {

using Point2 = std::array<double, 2>;
using Strokes = std::vector<std::vector<Point2>>;

inline MachineProfile testProfile() {
  auto p = preset("maker-plotter");
  EXPECT_TRUE(p.has_value());
  return p.value_or(MachineProfile{});
}

// Protocol and simulated machine joined by byte queues; time advances only in step().
struct SimLink {
  // A board set up for the profile (fivebar setup --write) and referenced at its home pose, as
  // a user leaves it; tests of the factory-fresh board build their own SimConfig.
  explicit SimLink(const MachineProfile& profile, sim::Fault fault = {}, bool instant = false)
      : SimLink(userBoard(profile, fault, instant)) {}
  static sim::SimConfig userBoard(const MachineProfile& profile, sim::Fault fault, bool instant) {
    sim::SimConfig config;
    config.profile = profile;
    config.fault = fault;
    config.instant = instant;
    config.setUp = true;
    config.referenced = true;
    return config;
  }
  explicit SimLink(const sim::SimConfig& config)
      : sim(config),
        protocol([this](std::string_view b) { toSim.append(b); }) {
    protocol.receive(sim.takeOutput());
  }
  // Delivers pending bytes both ways and advances machine time by dtS.
  void step(double dtS) {
    const std::string in = std::move(toSim);
    toSim.clear();
    allSent += in;
    sim.receive(in);
    sim.advance(dtS);
    nowS += dtS;
    protocol.receive(sim.takeOutput());
    if (sim.linkDropped()) protocol.disconnected("simulated link dropped");
    protocol.tick(nowS);
  }
  // Steps until pred() holds or maxS of machine time pass; returns pred().
  template <class Pred>
  bool runUntil(Pred pred, double maxS, double dtS = 0.002) {
    for (double t = 0; t < maxS; t += dtS) {
      if (pred()) return true;
      step(dtS);
    }
    return pred();
  }
  sim::SimMachine sim;
  grbl::GrblProtocol protocol;
  std::string toSim;
  std::string allSent;
  double nowS = 0.0;
};

// Random strokes (joint angles, deg) near the profile's home pose, inside its workspace
// (reached by inverse kinematics in the default working mode).
inline Strokes randomStrokes(const MachineProfile& p, std::mt19937_64& rng, int strokes,
                             int pointsPerStroke, double radiusMm) {
  const FkResult home = forward(p.geometry, p.homeAngles, p.assembly);
  EXPECT_TRUE(home.ok());
  std::uniform_real_distribution<double> u(-radiusMm, radiusMm);
  Strokes out;
  for (int s = 0; s < strokes; ++s) {
    std::vector<Point2> stroke;
    for (int i = 0; i < pointsPerStroke; ++i) {
      const Vec2 xy = home.p + Vec2(u(rng), u(rng));
      const IkResult ik = inverse(p.geometry, xy, p.defaultMode);
      EXPECT_TRUE(ik.ok());
      stroke.push_back({degFromRad(unwrapNear(ik.angles.theta1, p.homeAngles.theta1)),
                        degFromRad(unwrapNear(ik.angles.theta2, p.homeAngles.theta2))});
    }
    out.push_back(stroke);
  }
  return out;
}

inline std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

// A job drawing the strokes: pen-up travel, pen down, G1 per point, pen up. Ends at the last
// point of the last stroke.
inline std::string jobText(const MachineProfile& p, const Strokes& strokes, double feedDegPerMin) {
  std::string g = "; test job\nG21 G90\n";
  for (const std::string& s : stream::penUpCommands(p.tool)) g += s + "\n";
  for (size_t i = 0; i < strokes.size(); ++i) {
    g += "; stroke " + std::to_string(i) + "\n";
    g += "G0 X" + fmt(strokes[i][0][0]) + " Y" + fmt(strokes[i][0][1]) + "\n";
    for (const std::string& s : stream::penDownCommands(p.tool)) g += s + "\n";
    for (size_t k = 1; k < strokes[i].size(); ++k)
      g += "G1 X" + fmt(strokes[i][k][0]) + " Y" + fmt(strokes[i][k][1]) + " F" +
           fmt(feedDegPerMin) + "\n";
    for (const std::string& s : stream::penUpCommands(p.tool)) g += s + "\n";
  }
  return g;
}

// Segments of strokes, endpoints rounded to 0.01 deg (G-code has 1e-4, the board reports 1e-3).
using Segment = std::array<double, 4>;
inline std::vector<Segment> segmentsOf(const Strokes& strokes) {
  std::vector<Segment> out;
  const auto r = [](double v) { return std::round(v * 100.0) / 100.0; };
  for (const auto& s : strokes)
    for (size_t i = 1; i < s.size(); ++i)
      if (s[i] != s[i - 1]) out.push_back({r(s[i - 1][0]), r(s[i - 1][1]), r(s[i][0]), r(s[i][1])});
  return out;
}

// Distance (deg) from p to the segment a-b in the joint plane.
inline double distanceToSegment(const Point2& p, const Point2& a, const Point2& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

// Every job segment was drawn completely by some drawn segment (same ends within tolDeg),
// and every drawn segment lies on a job segment (both ends within tolDeg of it).
inline void expectStrokesCover(const Strokes& job, const Strokes& drawn, double tolDeg) {
  const auto near = [tolDeg](const Point2& a, const Point2& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1]) <= tolDeg;
  };
  for (size_t s = 0; s < job.size(); ++s)
    for (size_t i = 1; i < job[s].size(); ++i) {
      bool found = false;
      for (const auto& d : drawn)
        for (size_t k = 1; k < d.size() && !found; ++k)
          found = near(d[k - 1], job[s][i - 1]) && near(d[k], job[s][i]);
      EXPECT_TRUE(found) << "job stroke " << s << " segment " << i << " was not drawn";
    }
  for (size_t s = 0; s < drawn.size(); ++s)
    for (size_t k = 1; k < drawn[s].size(); ++k) {
      bool onJob = false;
      for (const auto& j : job)
        for (size_t i = 1; i < j.size() && !onJob; ++i)
          onJob = distanceToSegment(drawn[s][k - 1], j[i - 1], j[i]) <= tolDeg &&
                  distanceToSegment(drawn[s][k], j[i - 1], j[i]) <= tolDeg;
      EXPECT_TRUE(onJob) << "drawn stroke " << s << " segment " << k << " is not on the job";
    }
}

}  // namespace fivebar::test
