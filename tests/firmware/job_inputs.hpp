// SPDX-License-Identifier: GPL-3.0-or-later
// The studio's inputs for the session firmware tests: the maker plotter and a planned job of
// three nested squares (24, 18, 12 mm) that the test can move, as the studio's preview does.
#pragma once

#include <gtest/gtest.h>

#include <optional>

#include "core/planning/planner.hpp"
#include "session/studio_inputs.hpp"

namespace fivebar::test {

// A planned job the inputs can swap (the drawing moved), as the studio's preview does.
class JobInputs : public session::StudioInputs {
 public:
  explicit JobInputs(MachineProfile profile) : profile_(std::move(profile)) {}
  const MachineProfile& profile() const override { return profile_; }
  QString drawingFileName() const override { return QStringLiteral("square.svg"); }
  const PlannedJob* plannedJob() const override { return job_ ? &*job_ : nullptr; }
  void plan(const Vec2& atMm) {
    Layer l;
    l.id = l.name = "ink";
    for (int k = 0; k < 3; ++k) {
      const double h = 12.0 - 3.0 * k;
      l.paths.push_back({{{-h, -h}, {h, -h}, {h, h}, {-h, h}, {-h, -h}}, true});
    }
    Drawing d;
    d.widthMm = d.heightMm = 24.0;
    d.layers.push_back(l);
    PlanOptions o;
    o.atMm = atMm;
    o.toleranceMm = 0.05;
    const PlanResult r = planJob(d, profile_, o);
    ASSERT_TRUE(r.ok()) << r.message;
    job_ = r.job;
    emit plannedJobChanged();
    emit jobChanged();
  }

 private:
  MachineProfile profile_;
  std::optional<PlannedJob> job_;
};

}  // namespace fivebar::test
