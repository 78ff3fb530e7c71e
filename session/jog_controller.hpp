// SPDX-License-Identifier: GPL-3.0-or-later
// Jog logic behind the jog panel and the keyboard, without widgets: a tap is one step, holding
// starts a continuous jog streamed as short checked "$J=" moves (a few planner blocks ahead, so
// the machine never runs far past the release), and releasing cancels it with 0x85. Every move is
// planned by drivers/jog (checked sub-moves) and sent through MachineSession.
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <optional>

#include "drivers/jog/jog.hpp"
#include "session/machine_session.hpp"

namespace fivebar::session {

// One jog direction: a unit XY direction (Cartesian) or one motor and a sign.
struct JogDirection {
  enum class Kind { Cartesian, Motor };
  Kind kind = Kind::Cartesian;
  Vec2 xy = Vec2::Zero();  // Cartesian: direction (need not be unit)
  int motor = 1;           // Motor: 1 or 2
  int sign = 1;            // Motor: +1 counter-clockwise, -1 clockwise
  static JogDirection cartesian(double dx, double dy) { return {Kind::Cartesian, Vec2(dx, dy), 1, 1}; }
  static JogDirection motorJog(int motor, int sign) { return {Kind::Motor, Vec2::Zero(), motor, sign}; }
};

class JogController : public QObject {
  Q_OBJECT
 public:
  static constexpr int kHoldThresholdMs = 300;  // held longer than this: continuous jog
  static constexpr int kStreamPeriodMs = 40;    // how often the continuous stream is topped up
  static constexpr double kChunkS = 0.15;       // motion time per continuous chunk
  static constexpr std::size_t kLinesAhead = 3; // jog lines kept in flight while streaming
  // Motion planned ahead of the reported position (s at jog speed): bounds the run-on after a
  // release, since GRBL acknowledges a jog line when it enters the planner, not when it is done.
  static constexpr double kLeadS = 0.3;
  static constexpr double kMotorSpeedDegPerS = 20.0;

  explicit JogController(MachineSession& session, QObject* parent = nullptr);

  // Step: mm for Cartesian jogs, degrees for motor jogs.
  void setStep(double step) { step_ = step; }
  double step() const { return step_; }
  void setSpeedMmPerS(double speed) { speedMmPerS_ = speed; }
  double speedMmPerS() const { return speedMmPerS_; }
  bool streaming() const { return streaming_.has_value(); }

  // One step jog; false (and message()) when refused.
  bool jogStep(const JogDirection& direction);
  // Button / key pressed and released: a short press is one step, a long one a continuous jog.
  void press(const JogDirection& direction);
  void release();

 signals:
  void message(const QString& text);  // what happened: clipped, refused (empty: all fine)

 private:
  // The jog from where a new jog starts, cut at the board's soft limits (MachineSession::boardChecked).
  jog::JogPlan plan(const JogDirection& direction, double amount) const;
  jog::JogPlan plannedFrom(const JointAngles& start, const JogDirection& direction, double amount) const;
  void topUp();
  // Seconds of motion between the reported position and the end of what was sent.
  double leadS(const JogDirection& direction) const;
  void report(const jog::JogPlan& plan);

  MachineSession& session_;
  double step_ = 1.0;
  double speedMmPerS_ = 20.0;
  std::optional<JogDirection> pressed_;
  std::optional<JogDirection> streaming_;
  QElapsedTimer pressClock_;
  QTimer holdTimer_;
  QTimer streamTimer_;
};

}  // namespace fivebar::session
