// SPDX-License-Identifier: GPL-3.0-or-later
#include "pose_trust.hpp"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

namespace fivebar::grbl {
namespace {

using nlohmann::json;

const char* standingName(BoardRecord::Standing s) {
  switch (s) {
    case BoardRecord::Standing::AtRest: return "at-rest";
    case BoardRecord::Standing::Moving: return "moving";
    case BoardRecord::Standing::Lost: return "lost";
  }
  return "lost";
}

const char* doubtName(PoseDoubt d) {
  switch (d) {
    case PoseDoubt::None: return "none";
    case PoseDoubt::NotYetRead: return "not-yet-read";
    case PoseDoubt::NotReferenced: return "not-referenced";
    case PoseDoubt::PositionChanged: return "position-changed";
    case PoseDoubt::ResetInMotion: return "reset-in-motion";
    case PoseDoubt::HomingFailed: return "homing-failed";
    case PoseDoubt::RunInterrupted: return "run-interrupted";
    case PoseDoubt::Disconnected: return "disconnected";
  }
  return "none";
}

PoseDoubt doubtFromName(const std::string& s) {
  for (PoseDoubt d : {PoseDoubt::NotReferenced, PoseDoubt::PositionChanged, PoseDoubt::ResetInMotion,
                      PoseDoubt::HomingFailed, PoseDoubt::RunInterrupted, PoseDoubt::Disconnected})
    if (s == doubtName(d)) return d;
  return PoseDoubt::NotReferenced;
}

json readAll(const std::string& path) {
  QFile file(QString::fromStdString(path));
  if (!file.open(QIODevice::ReadOnly)) return json::object();
  const QByteArray bytes = file.readAll();
  json j = json::parse(bytes.constData(), bytes.constData() + bytes.size(), nullptr, false);
  return j.is_object() ? j : json::object();
}

bool same(const std::array<double, 2>& a, const std::array<double, 2>& b) {
  return std::abs(a[0] - b[0]) <= PoseTrust::kSamePositionDeg &&
         std::abs(a[1] - b[1]) <= PoseTrust::kSamePositionDeg;
}

}  // namespace

const char* toString(PoseDoubt d) {
  switch (d) {
    case PoseDoubt::None: return "known";
    case PoseDoubt::NotYetRead: return "not read yet";
    case PoseDoubt::NotReferenced: return "never referenced from this computer";
    case PoseDoubt::PositionChanged: return "power cut or reset";
    case PoseDoubt::ResetInMotion: return "reset or sudden stop while moving";
    case PoseDoubt::HomingFailed: return "homing did not complete";
    case PoseDoubt::RunInterrupted: return "lost sight of the machine while it moved";
    case PoseDoubt::Disconnected: return "disconnected";
  }
  return "unknown";
}

std::string boardRecordPath() {
  std::string dir;
  if (const char* s = std::getenv("FIVEBAR_STATE_DIR"); s && *s) dir = s;
  else if (const char* x = std::getenv("XDG_STATE_HOME"); x && *x) dir = std::string(x) + "/fivebar";
  else dir = QDir::homePath().toStdString() + "/.local/state/fivebar";
  return dir + "/boards.json";
}

std::optional<BoardRecord> loadBoardRecord(const std::string& boardKey) {
  if (boardKey.empty()) return std::nullopt;
  const json all = readAll(boardRecordPath());
  const auto it = all.find(boardKey);
  if (it == all.end() || !it->is_object()) return std::nullopt;
  try {
    BoardRecord r;
    const std::string standing = it->value("standing", "lost");
    r.standing = standing == "at-rest"  ? BoardRecord::Standing::AtRest
                 : standing == "moving" ? BoardRecord::Standing::Moving
                                        : BoardRecord::Standing::Lost;
    const auto m = it->at("machineDeg"), w = it->at("wcoDeg");
    r.machineDeg = {m.at(0).get<double>(), m.at(1).get<double>()};
    r.wcoDeg = {w.at(0).get<double>(), w.at(1).get<double>()};
    if (r.standing == BoardRecord::Standing::Lost) r.lostBecause = doubtFromName(it->value("lostBecause", ""));
    return r;
  } catch (const json::exception&) {
    return std::nullopt;  // a damaged entry vouches for nothing
  }
}

std::string saveBoardRecord(const std::string& boardKey, const BoardRecord& record) {
  if (boardKey.empty()) return {};
  const std::string path = boardRecordPath();
  const QString qpath = QString::fromStdString(path);
  QDir().mkpath(QFileInfo(qpath).absolutePath());
  json all = readAll(path);
  json entry = {{"standing", standingName(record.standing)},
                {"machineDeg", {record.machineDeg[0], record.machineDeg[1]}},
                {"wcoDeg", {record.wcoDeg[0], record.wcoDeg[1]}}};
  if (record.standing == BoardRecord::Standing::Lost) entry["lostBecause"] = doubtName(record.lostBecause);
  all[boardKey] = entry;
  const std::string text = all.dump(2) + "\n";
  QSaveFile file(qpath);
  if (!file.open(QIODevice::WriteOnly)) return "cannot write " + path + ": " + file.errorString().toStdString();
  file.write(text.data(), qint64(text.size()));
  if (!file.commit()) return "cannot write " + path + ": " + file.errorString().toStdString();
  return {};
}

PoseTrust::PoseTrust(GrblProtocol& protocol, std::string boardKey)
    : protocol_(protocol), key_(std::move(boardKey)), saved_(loadBoardRecord(key_)) {
  protocol_.addListener(this);
}

PoseTrust::~PoseTrust() { protocol_.removeListener(this); }

void PoseTrust::setDoubt(PoseDoubt d) {
  if (doubt_ == d) return;
  doubt_ = d;
  if (d != PoseDoubt::None && d != PoseDoubt::NotYetRead && d != PoseDoubt::Disconnected)
    record(BoardRecord::Standing::Lost);
  if (changed) changed();
}

void PoseTrust::record(BoardRecord::Standing standing) {
  BoardRecord r;
  r.standing = standing;
  if (const auto m = protocol_.machinePositionDeg()) r.machineDeg = {m->x(), m->y()};
  else if (saved_) r.machineDeg = saved_->machineDeg;
  if (const auto& w = protocol_.workOffset()) r.wcoDeg = {w->x(), w->y()};
  else if (saved_) r.wcoDeg = saved_->wcoDeg;
  if (standing == BoardRecord::Standing::Lost) r.lostBecause = doubt_;
  if (saved_ && saved_->standing == r.standing && same(saved_->machineDeg, r.machineDeg) &&
      same(saved_->wcoDeg, r.wcoDeg) && saved_->lostBecause == r.lostBecause)
    return;  // nothing new
  saved_ = r;
  saveProblem_ = saveBoardRecord(key_, r);
}

bool PoseTrust::atRestNow(const StatusReport& report) const {
  switch (report.state) {
    case MachineState::Idle:
    case MachineState::Alarm:
    case MachineState::Check:
    case MachineState::Sleep: return true;
    case MachineState::Hold:
    case MachineState::Door: return report.subState == 0;
    default: return false;
  }
}

void PoseTrust::confirmed() {
  confirmPending_ = true;
  afterReset_ = false;
}

void PoseTrust::aboutToMove() {
  if (known()) record(BoardRecord::Standing::Moving);
}

void PoseTrust::onAck(const Ack& ack) {
  if (ack.ok() && (ack.line == "$H" || ack.line == "$h")) confirmed();
  // "$#" gave the work offset the last report lacked: judge that report now.
  if (ack.ok() && ack.line == "$#" && protocol_.statusReportsSeen() > 0) onStatus(protocol_.lastStatus());
}

void PoseTrust::onStatus(const StatusReport& report) {
  const auto m = protocol_.machinePositionDeg();
  const bool rest = atRestNow(report);
  const bool placed = m.has_value() && protocol_.workOffset().has_value();
  const std::optional<std::array<double, 2>> here =
      m ? std::optional<std::array<double, 2>>(std::array<double, 2>{m->x(), m->y()}) : std::nullopt;
  if (confirmPending_ && rest && placed) {
    confirmPending_ = false;
    assessed_ = true;
    doubt_ = PoseDoubt::NotYetRead;  // so that setDoubt reports the change
    setDoubt(PoseDoubt::None);
    record(BoardRecord::Standing::AtRest);
  } else if (!assessed_) {
    if (!rest) {
      assessed_ = true;  // moving when the host arrives: moved by something the host did not watch
      setDoubt(PoseDoubt::RunInterrupted);
    } else if (placed) {
      assessed_ = true;
      const std::array<double, 2> wco{protocol_.workOffset()->x(), protocol_.workOffset()->y()};
      if (!saved_) setDoubt(PoseDoubt::NotReferenced);
      else if (saved_->standing == BoardRecord::Standing::Lost) setDoubt(saved_->lostBecause);
      else if (saved_->standing == BoardRecord::Standing::Moving) setDoubt(PoseDoubt::RunInterrupted);
      else if (!same(saved_->machineDeg, *here) || !same(saved_->wcoDeg, wco)) setDoubt(PoseDoubt::PositionChanged);
      else setDoubt(PoseDoubt::None);
    }
  } else if (afterReset_ && here) {
    afterReset_ = false;
    if (lastMachineDeg_ && !same(*lastMachineDeg_, *here)) setDoubt(PoseDoubt::PositionChanged);
  }
  if (known() && placed) {
    if (!rest) {
      if (!lastMoving_) record(BoardRecord::Standing::Moving);
    } else if (protocol_.idleLink()) {
      // At rest with nothing of ours in flight or queued: not a job that starved for a moment.
      record(BoardRecord::Standing::AtRest);
    }
  }
  if (here && !afterReset_) lastMachineDeg_ = here;
  lastMoving_ = !rest;
}

void PoseTrust::onAlarm(int code, const std::vector<std::uint64_t>&) {
  // GRBL's own words: ALARM:1 (hard limit) and ALARM:3 (reset while in motion) say the machine
  // position is likely lost; ALARM:6-9 end a homing cycle that moved without finishing.
  if (code == 1 || code == 3) setDoubt(PoseDoubt::ResetInMotion);
  else if (code >= 6 && code <= 9) setDoubt(PoseDoubt::HomingFailed);
  confirmPending_ = false;
}

void PoseTrust::onReset(const std::string&, const std::vector<std::uint64_t>&,
                        const std::vector<std::uint64_t>&) {
  if (lastMoving_) setDoubt(PoseDoubt::ResetInMotion);
  afterReset_ = true;  // the next report must stand where the last one did
}

void PoseTrust::onDisconnected(const std::string&) {
  confirmPending_ = false;
  setDoubt(PoseDoubt::Disconnected);
}

}  // namespace fivebar::grbl
