// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/output/gcode.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <future>
#include <stdexcept>
#include <string_view>

#include "core/output/fixed_decimal.hpp"
#include "core/support/memory_hint.hpp"
#include "core/support/parallel.hpp"
#include "core/kinematics/units.hpp"


namespace fivebar {
namespace {

// The text of one number kept for comparison (the last F and S sent), without allocation.
// Anything longer than kCapacity cannot fit in a G-code line anyway; it is kept truncated with
// `overflow` set so that the line carrying it fails.
struct NumberText {
  static constexpr size_t kCapacity = 96;
  char text[kCapacity];
  size_t size = 0;  // 0: no number (e.g. no F sent yet)
  bool overflow = false;

  void assign(std::string_view s) {
    size = std::min(s.size(), kCapacity);
    overflow = s.size() > kCapacity;
    std::memcpy(text, s.data(), size);
  }
  void format(double value, int decimals) {
    if (char* end = writeFixedDecimal(value, decimals, text)) {
      size = static_cast<size_t>(end - text);
      overflow = false;
    } else {
      assign(fixedDecimal(value, decimals));
    }
  }
  // Same text (an overflowed number never compares equal: its line throws before reuse). A plain
  // loop over the few characters, without an early exit whose position would be a coin toss.
  bool sameAs(const NumberText& o) const {
    if (size != o.size || overflow || o.overflow) return false;
    unsigned differences = 0;
    for (size_t i = 0; i < size; ++i)
      differences |= static_cast<unsigned char>(text[i] ^ o.text[i]);
    return differences == 0;
  }
};

// One output line under construction in a fixed buffer. A line longer than GRBL's 80 characters
// is a broken invariant (logic_error naming its first 40 characters); a comment is cut at 80.
class Line {
 public:
  Line& operator<<(std::string_view s) {
    const size_t n = std::min(kCapacity - size_, s.size());
    std::memcpy(buf_ + size_, s.data(), n);
    size_ += n;
    overflow_ = overflow_ || n < s.size();
    return *this;
  }
  Line& operator<<(const NumberText& t) {
    overflow_ = overflow_ || t.overflow;
    return *this << std::string_view(t.text, t.size);
  }
  Line& operator<<(int value) {
    char digits[16];
    const char* end = std::to_chars(digits, digits + sizeof digits, value).ptr;
    return *this << std::string_view(digits, static_cast<size_t>(end - digits));
  }
  // fixedDecimal(value, decimals), written in place when the fast path applies.
  Line& number(double value, int decimals) {
    if (kCapacity - size_ < kFixedDecimalRoom) {  // the line is far too long already
      overflow_ = true;
      return *this;
    }
    if (char* end = writeFixedDecimal(value, decimals, buf_ + size_)) {
      size_ = static_cast<size_t>(end - buf_);
      return *this;
    }
    return *this << fixedDecimal(value, decimals);
  }
  // Appends the line and its '\n' to `out`.
  void commitTo(std::string& out) {
    if (overflow_ || size_ > static_cast<size_t>(kGcodeMaxLineLength))
      throw std::logic_error("G-code line longer than 80 characters: " +
                             std::string(buf_, std::min<size_t>(size_, 40)));
    buf_[size_] = '\n';
    out.append(buf_, size_ + 1);
  }
  void commitCommentTo(std::string& out) {
    size_ = std::min(size_, static_cast<size_t>(kGcodeMaxLineLength));
    overflow_ = false;
    commitTo(out);
  }

 private:
  static constexpr size_t kCapacity = 128;  // > 80 + '\n', and >= 40 + kFixedDecimalRoom
  char buf_[kCapacity + kFixedDecimalRoom];
  size_t size_ = 0;
  bool overflow_ = false;
};

// Jobs smaller than this are written by one thread: a thread costs more than it saves.
constexpr size_t kMinMovesToSplit = 20000;

// Moves per piece of the streaming writer (about 1.5 MB of text).
constexpr size_t kMovesPerPiece = 50000;

// Bytes to reserve: generous for the usual line lengths; an unusual job only reallocates.
size_t expectedSize(const PlannedJob& job) {
  return 4096 + 48 * job.moves.size() + 40 * job.strokes.size();
}

bool jointLimitsSet(const JointLimits& l) {
  return l.theta1Max - l.theta1Min < JointLimits::kDefaultSpan &&
         l.theta2Max - l.theta2Min < JointLimits::kDefaultSpan;
}

struct Setting {
  int number;
  std::string value;
  const char* meaning;
};

std::vector<Setting> settingsOf(const MachineProfile& p) {
  const MotorSettings& m = p.motors;
  const bool laser = p.tool.kind == ToolKind::Laser;
  const bool limits = jointLimitsSet(p.limits);
  const double maxS = std::max({p.tool.penDownS, p.tool.penUpS, p.tool.laserPowerS, 1.0});
  std::vector<Setting> s = {
      {11, fixedDecimal(m.junctionDeviationDeg, 4), "junction deviation, deg"},
      {20, p.hasHomingSwitches && limits ? "1" : "0", "soft limits"},
      {21, "0", "hard limits"},
      {22, p.hasHomingSwitches ? "1" : "0", "homing cycle"},
      {30, fixedDecimal(maxS, 0), "max S"},
      {31, "0", "min S"},
      {32, laser ? "1" : "0", "laser mode"},
      {100, fixedDecimal(m.stepsPerDeg1, 4), "motor 1 steps/deg"},
      {101, fixedDecimal(m.stepsPerDeg2, 4), "motor 2 steps/deg"},
      {110, fixedDecimal(degFromRad(m.maxSpeedRadPerS1) * 60.0, 1), "motor 1 max rate, deg/min"},
      {111, fixedDecimal(degFromRad(m.maxSpeedRadPerS2) * 60.0, 1), "motor 2 max rate, deg/min"},
      {120, fixedDecimal(degFromRad(m.maxAccelRadPerS2_1), 1), "motor 1 acceleration, deg/s^2"},
      {121, fixedDecimal(degFromRad(m.maxAccelRadPerS2_2), 1), "motor 2 acceleration, deg/s^2"},
  };
  if (p.tool.kind == ToolKind::ZAxis)
    s.push_back({112, fixedDecimal(p.tool.zFeedMmPerMin, 1), "Z max rate, mm/min"});
  if (limits) {
    s.push_back({130, fixedDecimal(degFromRad(p.limits.theta1Max - p.limits.theta1Min), 3),
                 "motor 1 travel, deg"});
    s.push_back({131, fixedDecimal(degFromRad(p.limits.theta2Max - p.limits.theta2Min), 3),
                 "motor 2 travel, deg"});
  }
  std::sort(s.begin(), s.end(), [](const Setting& a, const Setting& b) { return a.number < b.number; });
  return s;
}

// "$100=35.5556" (built with += : GCC 12 warns falsely on "literal" + std::string&&).
std::string settingText(const Setting& s) {
  std::string text = "$";
  text += std::to_string(s.number);
  text += '=';
  text += s.value;
  return text;
}

// Writes the G-code of a run of moves into `out`. One writer does the whole job, or each of two
// threads one half (see writeGcode).
class Writer {
 public:
  Writer(const PlannedJob& job, const MachineProfile& p, const GcodeOptions& o, std::string& out)
      : job_(job), p_(p), o_(o), out_(out) {
    lastS_->assign("0");
  }

  void header() {
    comment("FiveBar Studio job for GRBL 1.1, host-side kinematics");
    comment("X = theta1 deg, Y = theta2 deg (continuous), F = joint rate deg/min");
    comment("profile: " + job_.profileName);
    comment("working mode " + std::string(toString(job_.mode)) + ", assembly " +
            std::string(toString(job_.assembly)));
    const JointAngles start = commandedFromKinematic(p_.calibration, job_.start);
    comment("start pose X" + fixedDecimal(degFromRad(start.theta1), o_.angleDecimals) + " Y" +
            fixedDecimal(degFromRad(start.theta2), o_.angleDecimals));
    if (p_.calibration)
      comment("calibrated: X, Y are commanded angles = kinematic - zero offset (" +
              fixedDecimal(degFromRad(p_.calibration->zeroOffsetRad1), 4) + ", " +
              fixedDecimal(degFromRad(p_.calibration->zeroOffsetRad2), 4) + " deg)");
    comment("estimated time " + fixedDecimal(job_.summary.estimatedTimeS, 1) + " s, " +
            std::to_string(job_.summary.segments) + " drawing segments");
    comment("expects these GRBL settings:");
    for (const Setting& s : settingsOf(p_)) comment(settingText(s) + " (" + s.meaning + ")");
    (Line() << "G21 G90 G94").commitTo(out_);
    if (p_.tool.kind == ToolKind::Laser) (Line() << "M4 S0").commitTo(out_);
  }

  // Takes up the state the moves before `begin` leave when written: the last F and S sent, the
  // laser power, the last stroke commented. Reads back only to the moves that set them.
  void resumeAt(size_t begin) {
    const std::vector<JobMove>& moves = job_.moves;
    for (size_t k = begin; o_.strokeComments && k-- > 0;) {
      if (moves[k].kind == JobMoveKind::Travel && moves[k].strokeIndex >= 0) {
        commentedStroke_ = moves[k].strokeIndex;
        break;
      }
    }
    bool zMoveSince = false;  // a Z move clears the modal F
    for (size_t k = begin; k-- > 0;) {
      const JobMove& m = moves[k];
      if (isMotion(m.kind)) {
        if (!zMoveSince) lastFeed_->format(feedDegPerMin(m), o_.feedDecimals);
        if (p_.tool.kind == ToolKind::Laser && m.kind == JobMoveKind::Draw)
          lastS_->format(laserPowerBefore(k), 0);
        break;
      }
      zMoveSince = zMoveSince || (p_.tool.kind == ToolKind::ZAxis && isToolMove(m.kind));
    }
    laserPower_ = laserPowerBefore(begin);
  }

  void moves(size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) move(job_.moves[i]);
  }

  void trailer() {
    if (p_.tool.kind != ToolKind::ZAxis) (Line() << "M5").commitTo(out_);
    (Line() << "M2").commitTo(out_);
  }

 private:
  static bool isToolMove(JobMoveKind kind) {
    return kind == JobMoveKind::PenUp || kind == JobMoveKind::PenDown;
  }
  static double feedDegPerMin(const JobMove& m) { return degFromRad(m.jointFeedRadPerS) * 60.0; }
  // The laser power set by the last tool move before `end` (0 when none).
  double laserPowerBefore(size_t end) const {
    for (size_t k = end; k-- > 0;) {
      const JobMove& m = job_.moves[k];
      if (isToolMove(m.kind)) return m.kind == JobMoveKind::PenDown ? m.toolValue : 0.0;
    }
    return 0.0;
  }

  void comment(std::string_view text) { (Line() << "; " << text).commitCommentTo(out_); }

  void move(const JobMove& m) {
    switch (m.kind) {
      case JobMoveKind::Draw:
      case JobMoveKind::Travel: motion(m); break;
      case JobMoveKind::PenDown: tool(m, true); break;
      case JobMoveKind::PenUp: tool(m, false); break;
      case JobMoveKind::Dwell: dwell(m.dwellS); break;
      case JobMoveKind::Pause:
        comment("pause: change the tool, then resume (cycle start)");
        (Line() << "M0").commitTo(out_);
        break;
    }
  }

  void dwell(double seconds) {
    (Line() << "G4 P").number(seconds, 3).commitTo(out_);
  }

  // "G1 X<theta1 deg> Y<theta2 deg>", then F and (laser) S only when their text changes.
  void motion(const JobMove& m) {
    if (o_.strokeComments && m.kind == JobMoveKind::Travel && m.strokeIndex >= 0 &&
        m.strokeIndex != commentedStroke_) {
      const PlannedStroke& s = job_.strokes[static_cast<size_t>(m.strokeIndex)];
      (Line() << "; stroke " << m.strokeIndex << " layer " << s.layerIndex << " path "
              << s.pathIndex)
          .commitCommentTo(out_);
      commentedStroke_ = m.strokeIndex;
    }
    Line line;
    // The plan holds kinematic angles; GRBL counts commanded ones (docs/calibration.md).
    const JointAngles target = commandedFromKinematic(p_.calibration, m.target);
    (line << "G1 X").number(degFromRad(target.theta1), o_.angleDecimals);
    (line << " Y").number(degFromRad(target.theta2), o_.angleDecimals);
    scratch_->format(feedDegPerMin(m), o_.feedDecimals);
    if (!scratch_->sameAs(*lastFeed_)) {
      line << " F" << *scratch_;
      std::swap(lastFeed_, scratch_);
    }
    if (p_.tool.kind == ToolKind::Laser) {
      if (m.kind == JobMoveKind::Draw)
        scratch_->format(laserPower_, 0);
      else
        scratch_->assign("0");
      if (!scratch_->sameAs(*lastS_)) {
        line << " S" << *scratch_;
        std::swap(lastS_, scratch_);
      }
    }
    line.commitTo(out_);
  }

  void tool(const JobMove& m, bool down) {
    switch (p_.tool.kind) {
      case ToolKind::PenServo:
        if (down || p_.tool.penUpS > 0.0) {
          (Line() << "M3 S").number(down ? m.toolValue : p_.tool.penUpS, 0).commitTo(out_);
        } else {
          (Line() << "M5").commitTo(out_);
        }
        if (m.dwellS > 0.0) dwell(m.dwellS);
        break;
      case ToolKind::ZAxis: {
        Line line;
        (line << "G1 Z").number(m.toolValue, 3);
        (line << " F").number(p_.tool.zFeedMmPerMin, 1);
        line.commitTo(out_);
        lastFeed_->size = 0;  // F is modal: the next XY move sets its own again
        break;
      }
      case ToolKind::Laser:
        laserPower_ = down ? m.toolValue : 0.0;  // carried by the S word of the next G1
        break;
    }
  }

  const PlannedJob& job_;
  const MachineProfile& p_;
  const GcodeOptions& o_;
  std::string& out_;
  // The last F and S texts sent, and a scratch number; swapped as pointers, never copied.
  NumberText texts_[3];
  NumberText* lastFeed_ = &texts_[0];
  NumberText* lastS_ = &texts_[1];
  NumberText* scratch_ = &texts_[2];
  double laserPower_ = 0.0;
  int commentedStroke_ = -1;
};

}  // namespace

std::string grblSettings(const MachineProfile& profile) {
  std::string text;
  for (const Setting& s : settingsOf(profile))
    text += settingText(s) + "\n";
  return text;
}

std::string writeGcode(const PlannedJob& job, const MachineProfile& profile,
                       const GcodeOptions& options) {
  // Large jobs are written in two halves on up to two threads, the second half picking up the
  // state the first leaves; the text is the same for any thread count. On an error (a line too
  // long), the first one in the text is thrown, as a sequential writer would.
  const size_t n = job.moves.size();
  const size_t parts = n >= kMinMovesToSplit ? 2 : 1;
  std::vector<std::string> texts(parts);
  parallelFor(parts, planningThreads(), [&](size_t k) {
    const size_t begin = n * k / parts, end = n * (k + 1) / parts;
    std::string& out = texts[k];
    out.reserve(k == 0 ? expectedSize(job) : expectedSize(job) * (end - begin) / n);
    adviseHugePages(out.data(), out.capacity());
    Writer w(job, profile, options, out);
    if (k == 0) w.header();
    else w.resumeAt(begin);
    w.moves(begin, end);
    if (k + 1 == parts) w.trailer();
  });
  for (size_t k = 1; k < parts; ++k) texts[0] += texts[k];
  return std::move(texts[0]);
}

void writeGcode(const PlannedJob& job, const MachineProfile& profile,
                const std::function<void(std::string_view)>& sink, const GcodeOptions& options) {
  // Blocks of moves, written two at a time (each picking up the state the moves before it
  // leave) while the calling thread hands the previous two to the sink, in order: the same text
  // as the one-string writer.
  const size_t n = job.moves.size();
  const size_t blocks = std::max<size_t>(1, (n + kMovesPerPiece - 1) / kMovesPerPiece);
  const int threads = n >= kMinMovesToSplit ? planningThreads() : 1;
  std::string texts[2][2];  // two pairs: one being written, one being handed over
  auto writePair = [&](size_t first, std::string* out) {
    const size_t count = std::min<size_t>(2, blocks - first);
    parallelFor(count, threads, [&](size_t k) {
      const size_t b = first + k, begin = n * b / blocks, end = n * (b + 1) / blocks;
      out[k].clear();
      Writer w(job, profile, options, out[k]);
      if (b == 0) w.header();
      else w.resumeAt(begin);
      w.moves(begin, end);
      if (b + 1 == blocks) w.trailer();
    });
  };
  writePair(0, texts[0]);
  for (size_t first = 0, pair = 0; first < blocks; first += 2, pair ^= 1) {
    std::future<void> next;
    if (first + 2 < blocks)
      next = std::async(std::launch::async, writePair, first + 2, texts[pair ^ 1]);
    for (size_t k = 0; k < std::min<size_t>(2, blocks - first); ++k) sink(texts[pair][k]);
    if (next.valid()) next.get();
  }
}

}  // namespace fivebar
