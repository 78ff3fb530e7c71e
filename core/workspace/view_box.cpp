// SPDX-License-Identifier: GPL-3.0-or-later
// Boxes a view of the machine shows. Contract: view_box.hpp.
#include "core/workspace/view_box.hpp"

#include <algorithm>

#include "core/kinematics/kinematics.hpp"

namespace fivebar {
namespace {

void include(BoxMm& box, const Vec2& p, double r = 0.0) {
  box.min = box.min.cwiseMin(p - Vec2(r, r));
  box.max = box.max.cwiseMax(p + Vec2(r, r));
}

}  // namespace

BoxMm drawingViewBoxMm(const Geometry& g, WorkingMode mode, const std::array<Vec2, 4>& cornersMm,
                       double marginMm) {
  BoxMm box{cornersMm[0], cornersMm[0]};
  for (const Vec2& c : cornersMm) include(box, c);
  // The motors too, so the drawing is seen in relation to the machine.
  include(box, Vec2(-g.w / 2.0 - 20.0, -20.0));
  include(box, Vec2(g.w / 2.0 + 20.0, 0.0));
  const BoxMm drawing = box;
  const Vec2 mid = 0.5 * (drawing.min + drawing.max);
  const double l = drawing.min.x(), r = drawing.max.x(), b = drawing.min.y(), t = drawing.max.y();
  for (const Vec2& c : {Vec2(l, t), Vec2(r, t), Vec2(l, b), Vec2(r, b), Vec2(mid.x(), t), Vec2(mid.x(), b),
                        Vec2(l, mid.y()), Vec2(r, mid.y())}) {
    const IkResult ik = inverse(g, c, mode);
    if (!ik.ok()) continue;
    include(box, elbow1(g, ik.angles.theta1), 8.0);
    include(box, elbow2(g, ik.angles.theta2), 8.0);
  }
  include(box, box.min, marginMm);
  include(box, box.max, marginMm);
  return box;
}

BoxMm machineViewBoxMm(const Geometry& g) {
  const double reach = std::max(g.a1 + g.b1, g.a2 + g.b2);
  return {Vec2(-g.w / 2.0 - reach * 0.8, -30.0), Vec2(g.w / 2.0 + reach * 0.8, reach + 10.0)};
}

}  // namespace fivebar
