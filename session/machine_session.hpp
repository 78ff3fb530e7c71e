// SPDX-License-Identifier: GPL-3.0-or-later
// MachineSession: the studio's only door to the machine. It owns the transport (the built-in
// simulated machine or a serial port), the MachineLink (protocol + clock) and answers the
// panels: connection, status, console, alarm/error banner, jog and tool commands. A job run is
// streamed by RunController through link(). Widgets show what the session reports; they never
// store machine state. No exception leaves a slot: failures come back as messages.
#pragma once

#include <QObject>
#include <QString>
#include <array>
#include <memory>
#include <optional>
#include <set>
#include <vector>

#include "core/kinematics/kinematics.hpp"
#include "drivers/protocol/grbl_protocol.hpp"
#include "drivers/jog/jog_settle.hpp"
#include "drivers/protocol/machine_link.hpp"
#include "drivers/check/machine_setup.hpp"
#include "drivers/sim/sim_machine.hpp"
#include "drivers/jog/jog.hpp"
#include "session/machine_ports.hpp"
#include "session/studio_inputs.hpp"

namespace fivebar {
class SimulatedTransport;
}
class QTimer;

namespace fivebar::session {

enum class ConsoleKind { Sent, Received, Info, Problem };

// The pen (tool) as far as the studio knows: set by the pen commands it sent and by the job's
// executed lines; unknown after connecting and after a reset.
enum class PenState { Unknown, Up, Down };

// What the banner shows: an alarm (code from the drivers' table), or an error answer to a line
// the user sent (console, jog, tool commands).
struct MachineProblem {
  enum class Kind { None, Alarm, Error };
  Kind kind = Kind::None;
  int code = 0;
  QString text;           // the drivers' explanation (what happened, what to do)
  bool needsReset = false;  // the board said "Reset to continue" ($X is ignored until then)
};

class MachineSession : public QObject,
                       public ConnectionPort,
                       public RecoveryPort,
                       public JogPort,
                       public BoardSettingsPort,
                       private grbl::ProtocolListener {
  Q_OBJECT
 public:
  static constexpr double kPollIntervalS = 0.2;  // 5 Hz status polling (GRBL's maximum)
  static constexpr int kTickMs = 10;             // protocol clock
  // "Connected" only once the board answered like GRBL (a status report) within this time.
  static constexpr int kConnectTimeoutMs = 4000;

  explicit MachineSession(const StudioInputs& inputs, QObject* parent = nullptr);
  ~MachineSession() override;

  // --- connection ---
  // The in-process simulated machine built from the document's profile. speedup: machine time
  // per wall-clock time. False with *error when the link cannot open. A link that opened is
  // "connecting" until the board's first status report (then connectionChanged(true)); without
  // one within kConnectTimeoutMs it is closed again and connectFailed says so.
  bool connectSimulated(double speedup, const sim::Fault& fault, QString* error) override;
  bool connectSerial(const QString& portPath, int baudRate, QString* error) override;
  void disconnectMachine() override;
  bool isConnected() const { return link_ != nullptr && answered_; }
  bool isConnecting() const { return link_ != nullptr && !answered_; }
  QString linkName() const;
  MachineLink* link() const { return link_.get(); }
  SimulatedTransport* simulatedTransport() const { return simulated_; }
  // The real machine the simulated motors drive (sim::SimConfig::trueMachine: its geometry and,
  // in its calibration section, the true zero offsets and backlash); nullopt: the document's
  // profile itself. Applied at once to a simulated machine already open (SimMachine::
  // setTrueMachine: the drawing so far stays) and to every later connectSimulated.
  void setSimulatedTrueMachine(std::optional<MachineProfile> trueMachine);
  const std::optional<MachineProfile>& simulatedTrueMachine() const { return simTrueMachine_; }
  // What the simulated machine's pen really drew (SimMachine::drawnTrace: one polyline per
  // pen-down run, machine frame, mm); empty when the simulated machine is not open.
  std::vector<std::vector<Vec2>> simulatedDrawnTrace() const;

  // --- state, as last reported by the board ---
  grbl::MachineState state() const;
  const grbl::StatusReport* lastStatus() const;  // nullptr before the first report
  // Continuous, rad; nullopt while the position is not known (poseKnown): a board that powered
  // up reports its last reference pose wherever the arms stand.
  std::optional<JointAngles> motorAngles() const;
  std::optional<Vec2> penMm() const;             // FK of motorAngles, machine frame
  // Whether the studio knows where the arms are (drivers/protocol/pose_trust.hpp): known after the
  // reference pose is set, homing, or a board found where this computer last saw it stand.
  bool poseKnown() const;
  grbl::PoseDoubt poseDoubt() const;
  // Why the position is not known and what to do, in the studio's words ("" when known).
  QString poseDoubtText() const;
  int bytesInFlight() const;
  const MachineProblem& problem() const { return problem_; }
  const MachineProfile& profile() const { return inputs_.profile(); }
  // Where a new jog starts: the end of the jog still in progress, else the reported angles.
  std::optional<JointAngles> jogStart() const override;
  bool jobActive() const { return jobActive_; }
  // True when no jog of ours may still be moving (its end confirmed by quiet status reports).
  bool jogSettled() const { return settle_.settled(); }
  // True when jogging and console commands may be sent now (connected, no job, not in alarm).
  bool canJog() const override;
  // The pen as the board reports it (drivers/protocol/pen_state.hpp: its spindle state or Z), not as the
  // last line sent.
  PenState penState() const { return pen_; }

  // --- the board's $ settings, read on connect (and again after a write) ---
  void readBoardSettings() override;
  std::unique_ptr<setup::SettingsSync> makeSettingsSync() override;
  bool boardSettingsKnown() const { return boardSettings_.has_value(); }
  bool readingBoardSettings() const;
  // The board's settings as last read (nullopt while unknown).
  const std::optional<setup::Settings>& boardSettings() const { return boardSettings_; }
  // The board's work offset (machine = work + WCO), X and Y in deg; nullopt before a status
  // report carried one.
  std::optional<std::array<double, 2>> workOffsetDeg() const;
  // The board's settings that differ from what the profile expects (empty while unknown).
  std::vector<setup::SettingDiff> settingDifferences() const;
  // The board's settings (as last read) differ from the profile where it changes how the
  // machine moves (drivers/stream/stream_session.hpp movingSettingDiffs): no jog until written.
  bool settingsStopMoves() const;
  // The expert's override for jogs, go-to and console moves: the differences are warned about
  // but do not refuse them (off again at disconnect). Start has its own ("Start anyway").
  void setIgnoreSettingDifferences(bool on);
  bool ignoreSettingDifferences() const { return ignoreSettings_; }
  // Why a jog or move cannot be sent now, in the user's words ("" when it can).
  QString moveRefusal() const;

  // --- the console's safety switch ---
  // Off (default): every console line goes through the motion check (drivers/check/motion_check)
  // from the board's reported pose; a refused line is not sent and lineRefused says why.
  // On: lines are sent unchecked (an expert's choice; the console shows a warning while on).
  void setUncheckedConsole(bool on);
  bool uncheckedConsole() const { return unchecked_; }

  // --- commands (each returns false and logs why when it cannot be sent) ---
  // A console line: checked (see setUncheckedConsole); false with *refusal when refused.
  bool sendLine(const QString& line, QString* refusal = nullptr);
  // A host-planned move (jog, go-to, home pose, frame). Refused (false, logged, lineRefused) when
  // the board's part of the motion check refuses any of its lines (see boardChecked).
  bool sendJog(const jog::JogPlan& plan) override;
  // The board's part of the one motion check (motion::checkBoardLines: the board's soft-limit
  // travel in machine coordinates, the lines the link refuses) on a plan read from jogStart().
  // A plan with a refused line is cut before it: Clipped when clip and a motion line is left (a
  // jog stops at the last target the board takes), else Blocked; the reason says why.
  jog::JogPlan boardChecked(jog::JogPlan plan, bool clip) const override;
  // A motion check or jog reason in the user's language, with the studio's words for the CLI's
  // commands in its advice.
  static QString studioText(const Message& reason);
  void cancelJog();
  void unlock() override;
  // $H with homing switches; otherwise ($X when in alarm and) the reference pose.
  void home() override;
  void setReferencePose() override;  // G10 L20 P0: "the machine now stands at the profile's home pose"
  // A checked pen-up move to the profile's home pose (the reference must be set); false with
  // *why when it cannot be planned or sent.
  bool goToHomePose(QString* why = nullptr) override;
  // The planned job's outline, traced pen up by checked moves (session/frame.hpp): canJog and a
  // planned job (StudioInputs::plannedJob). false with *why when it cannot be planned or sent.
  bool canFrame() const override;
  bool frameJob(QString* why = nullptr) override;
  void softReset() override;
  void feedHold();
  void cycleStart();
  // A feed or rapid override (GRBL real-time byte 0x90-0x97, never counted, accepted in any
  // state). The board caps the overridden rate at $110/$111, so it stays within the motors'
  // limits (drivers/protocol/overrides.hpp).
  void sendOverride(grbl::OverrideCommand command);
  // Feed and rapid override as the board last reported them (Ov:); nullopt while not known.
  std::optional<grbl::MotionOverrides> reportedOverrides() const;
  bool penUp() override;
  bool penDown() override;
  void dismissProblem() override;

  // RunController marks the time a job streams (the console hides its "ok"s, jog is refused).
  void setJobActive(bool active);

 signals:
  void connectionChanged(bool connected);
  void connectFailed(const QString& message);  // the board did not answer like GRBL
  void aboutToDisconnect();  // the link is still valid: stop using it
  void statusUpdated();      // a status report arrived
  void problemChanged();
  void consoleLine(const QString& text, fivebar::session::ConsoleKind kind);
  void jobActiveChanged(bool active);
  void lineRefused(const QString& reason);  // a console line or move the motion check refused
  void uncheckedConsoleChanged(bool on);
  void penStateChanged();
  void boardSettingsChanged();  // read (or failed); see settingDifferences()
  void poseKnownChanged();      // see poseKnown()
  void plannedJobChanged();     // the studio's planned job (see canFrame())

 private:
  bool openLink(std::unique_ptr<Transport> transport, QString* error);
  void onConnectTimeout();
  bool checkConsoleLine(const std::string& line, QString* refusal);
  bool enqueueUserLine(const std::string& line, bool log);
  bool sendPen(const std::vector<std::string>& lines);  // penUp / penDown
  void setProblem(MachineProblem problem);
  void setPenState(PenState pen);
  void teardown(const QString& reason);

  void onAck(const grbl::Ack& ack) override;
  void onStatus(const grbl::StatusReport& report) override;
  void onAlarm(int code, const std::vector<std::uint64_t>& lostIds) override;
  void onReset(const std::string& version, const std::vector<std::uint64_t>& lostIds,
               const std::vector<std::uint64_t>& dropped) override;
  void onLine(const grbl::ParsedLine& line) override;
  void onDisconnected(const std::string& reason) override;

  const StudioInputs& inputs_;
  std::unique_ptr<Transport> transport_;
  std::unique_ptr<MachineLink> link_;
  SimulatedTransport* simulated_ = nullptr;
  std::optional<MachineProfile> simTrueMachine_;
  std::set<std::uint64_t> userLines_;  // ids of lines sent by the user (errors go to the banner)
  // Jogs, cancels and new references until the reports confirm the machine stands still.
  jog::JogSettle settle_;
  MachineProblem problem_;
  bool answered_ = false;  // the board sent a status report since the link opened
  QString connectTarget_;  // "PORT at BAUD baud" for the timeout message
  QTimer* connectTimer_ = nullptr;
  bool unchecked_ = false;
  bool ignoreSettings_ = false;
  bool consoleAbsolute_ = true;  // G90/G91 as the console's lines left it
  PenState pen_ = PenState::Unknown;
  std::unique_ptr<setup::SettingsSync> settingsSync_;
  std::optional<setup::Settings> boardSettings_;
  bool jobActive_ = false;
  bool tearingDown_ = false;
};

}  // namespace fivebar::session
