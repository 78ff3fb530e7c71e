// SPDX-License-Identifier: GPL-3.0-or-later
// G-code: lines of at most 80 characters that parse back to the planned joint targets and feeds,
// the header names the profile and the $ settings, tool commands per tool kind, M0 for a pen
// change, rounding far below a motor step.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <sstream>

#include "core/output/gcode.hpp"
#include "core/planning/planner.hpp"
#include "gcode_text.hpp"
#include "gcode_oracle.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

using test::linesOf;
using test::wordsOf;

Drawing twoLayerDrawing() {
  Drawing d;
  d.layers.resize(2);
  d.layers[0].name = "black";
  d.layers[1].name = "red";
  d.layers[1].tool.pauseBefore = true;
  std::mt19937_64 rng = test::rng();
  std::uniform_real_distribution<double> x(0, 60), y(0, 40);
  for (int i = 0; i < 10; ++i) {
    Polyline pl;
    for (int k = 0; k < 6; ++k) pl.points.emplace_back(x(rng), y(rng));
    d.layers[static_cast<size_t>(i % 2)].paths.push_back(pl);
  }
  return d;
}

PlanResult plan(const MachineProfile& p) {
  PlanOptions o;
  o.atMm = Vec2(0, 170);
  return planJob(twoLayerDrawing(), p, o);
}

TEST(Gcode, LinesParseBackToTheTargetsAndFeeds) {
  const MachineProfile p = *preset("maker-plotter");
  const PlanResult r = plan(p);
  ASSERT_TRUE(r.ok()) << r.message;
  const std::string text = writeGcode(r.job, p);
  std::vector<const JobMove*> motions;
  for (const JobMove& m : r.job.moves)
    if (isMotion(m.kind)) motions.push_back(&m);
  size_t next = 0;
  double feed = -1;
  const double stepDeg = 1.0 / p.motors.stepsPerDeg1;
  for (const std::string& line : linesOf(text)) {
    EXPECT_LE(line.size(), 80u) << line;
    const auto w = wordsOf(line);
    if (w.count('F')) feed = w.at('F');
    if (!w.count('G') || w.at('G') != 1 || !w.count('X')) continue;
    ASSERT_LT(next, motions.size());
    const JobMove& m = *motions[next++];
    const double errX = std::abs(w.at('X') - degFromRad(m.target.theta1));
    const double errY = std::abs(w.at('Y') - degFromRad(m.target.theta2));
    EXPECT_LE(errX, 0.5e-4 + 1e-9);
    EXPECT_LE(errY, 0.5e-4 + 1e-9);
    EXPECT_LT(std::max(errX, errY), 0.01 * stepDeg);  // rounding is far below a step
    EXPECT_NEAR(feed, degFromRad(m.jointFeedRadPerS) * 60.0, 0.05 + 1e-9);
  }
  EXPECT_EQ(next, motions.size());
}

TEST(Gcode, HeaderNamesProfileAndSettings) {
  const MachineProfile p = *preset("maker-plotter");
  const std::string text = writeGcode(plan(p).job, p);
  for (const char* needle : {"profile: maker-plotter", "$100=35.5556", "$101=", "$110=9000.0",
                             "$111=", "$120=600.0", "$121=", "$11=", "$20=", "$130=", "$131=",
                             "\nG21 G90 G94\n", "\nM2\n"})
    EXPECT_NE(text.find(needle), std::string::npos) << needle;
  // No Cartesian rapids or arcs ever.
  for (const std::string& line : linesOf(text)) {
    std::istringstream in(line.substr(0, line.find(';')));
    for (std::string word; in >> word;) {
      if (word[0] != 'G') continue;
      const int g = std::stoi(word.substr(1));
      EXPECT_TRUE(g == 1 || g == 4 || g == 21 || g == 90 || g == 94) << line;
    }
  }
}

TEST(Gcode, PenServoLowersWithDwellAndPausesForAPenChange) {
  const MachineProfile p = *preset("maker-plotter");
  const std::string text = writeGcode(plan(p).job, p);
  EXPECT_NE(text.find("\nM3 S1000\nG4 P0.150\n"), std::string::npos);
  EXPECT_NE(text.find("\nM5\nG4 P0.150\n"), std::string::npos);
  EXPECT_NE(text.find("\nM0\n"), std::string::npos);
  // The pause comes after the pen is up and before the travel to the red layer.
  const size_t pause = text.find("\nM0\n");
  EXPECT_LT(text.rfind("\nM5\n", pause), pause);
  EXPECT_GT(text.find("\nM3 S1000\n", pause), pause);
}

TEST(Gcode, LaserCarriesPowerOnDrawMovesOnly) {
  MachineProfile p = *preset("maker-plotter");
  p.tool.kind = ToolKind::Laser;
  p.tool.laserPowerS = 700;
  const PlanResult r = plan(p);
  ASSERT_TRUE(r.ok());
  const std::string text = writeGcode(r.job, p);
  EXPECT_NE(text.find("$32=1"), std::string::npos);
  EXPECT_NE(text.find("\nM4 S0\n"), std::string::npos);
  EXPECT_EQ(text.find("G4"), std::string::npos);  // no dwells for a laser
  std::vector<const JobMove*> motions;
  for (const JobMove& m : r.job.moves)
    if (isMotion(m.kind)) motions.push_back(&m);
  size_t next = 0;
  double s = 0;
  for (const std::string& line : linesOf(text)) {
    const auto w = wordsOf(line);
    if (w.count('S')) s = w.at('S');
    if (!w.count('X')) continue;
    const JobMove& m = *motions[next++];
    EXPECT_EQ(s, m.kind == JobMoveKind::Draw ? 700.0 : 0.0) << line;
  }
}

TEST(Gcode, ZAxisPenMovesZ) {
  MachineProfile p = *preset("maker-plotter");
  p.tool.kind = ToolKind::ZAxis;
  p.tool.zUpMm = 4;
  p.tool.zDownMm = -0.5;
  const std::string text = writeGcode(plan(p).job, p);
  EXPECT_NE(text.find("\nG1 Z-0.500 F600.0\n"), std::string::npos);
  EXPECT_NE(text.find("\nG1 Z4.000 F600.0\n"), std::string::npos);
  // After a Z move the next XY move states its own F again.
  const size_t z = text.find("\nG1 Z-0.500");
  const size_t xy = text.find("\nG1 X", z);
  const std::string line = text.substr(xy + 1, text.find('\n', xy + 1) - xy - 1);
  EXPECT_NE(line.find(" F"), std::string::npos) << line;
}

TEST(Gcode, GrblSettingsAreDollarLines) {
  const MachineProfile p = *preset("hoang2015");
  const auto lines = linesOf(grblSettings(p));
  ASSERT_GE(lines.size(), 10u);
  for (const std::string& l : lines) {
    ASSERT_EQ(l[0], '$');
    const size_t eq = l.find('=');
    ASSERT_NE(eq, std::string::npos);
    EXPECT_NO_THROW((void)std::stod(l.substr(eq + 1))) << l;
  }
  EXPECT_NE(grblSettings(p).find("$110=36000.0\n"), std::string::npos);
  EXPECT_NE(grblSettings(p).find("$120=3000.0\n"), std::string::npos);
}


// --- Byte identity with the reference writer (gcode_oracle.hpp) on seeded random jobs ---

// Numbers of every kind the formatter meets: ordinary, tiny (some round to "-0.0000"), close to
// a rounding tie in decimal (x.xxxx5 is not exact in binary), integers, huge (past the fast
// path's range), and rarely not finite.
double awkwardNumber(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
  const double sign = u(rng) < 0.5 ? -1.0 : 1.0;
  const double pick = u(rng);
  if (pick < 0.40) return scale * s(rng);
  if (pick < 0.50) return sign * 6e-5 * u(rng);
  if (pick < 0.55) return sign * 1e-9 * u(rng);
  if (pick < 0.65)  // k + 0.5 scaled to 1 .. 6 decimals: x.xxxx5
    return sign * (std::floor(u(rng) * 1e7) + 0.5) * std::pow(10.0, -1 - static_cast<int>(u(rng) * 6));
  if (pick < 0.72) return sign * std::floor(u(rng) * 2000.0);
  if (pick < 0.80) return sign * std::pow(10.0, 4.0 + 11.0 * u(rng));
  if (pick < 0.85) return sign * std::pow(10.0, 14.5 + 3.0 * u(rng));
  if (pick < 0.88) return sign * std::pow(10.0, 18.0 + 60.0 * u(rng));
  if (pick < 0.90) return 0.0 * sign;
  if (pick < 0.905) return std::numeric_limits<double>::quiet_NaN();
  if (pick < 0.91) return sign * std::numeric_limits<double>::infinity();
  // Exact binary ties at 0..3 decimals (k + 1/2, k/2^n): half-even rounding.
  return sign * (std::floor(u(rng) * 100.0) + std::ldexp(1.0, -1 - static_cast<int>(u(rng) * 5)));
}

PlannedJob randomJob(std::mt19937_64& rng, bool awkward, int moves) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto number = [&](double scale) {
    return awkward ? awkwardNumber(rng, scale) : scale * (2.0 * u(rng) - 1.0);
  };
  PlannedJob job;
  job.profileName = u(rng) < 0.3 ? std::string(120, 'p') : "random";
  job.start = {radFromDeg(number(360.0)), radFromDeg(number(360.0))};
  job.summary.estimatedTimeS = number(1e4);
  job.summary.segments = static_cast<int>(u(rng) * 1e6);
  double feedRadPerS = radFromDeg(30.0);
  int stroke = -1;
  for (int i = 0; i < moves; ++i) {
    JobMove m;
    m.kind = static_cast<JobMoveKind>(std::min(5, static_cast<int>(u(rng) * 6.0)));
    if (u(rng) < 0.6) m.kind = JobMoveKind::Draw;
    m.target = {radFromDeg(number(720.0)), radFromDeg(number(720.0))};
    const double f = u(rng);
    if (f < 0.25) feedRadPerS = radFromDeg(number(200.0));    // new feed
    else if (f < 0.35) feedRadPerS *= 1.0 + 1e-12;           // same text, different value
    m.jointFeedRadPerS = feedRadPerS;
    m.dwellS = u(rng) < 0.3 ? 0.0 : number(1.0);
    m.toolValue = number(1000.0);
    if (m.kind == JobMoveKind::Travel && u(rng) < 0.7) {
      if (stroke < 0 || u(rng) < 0.8) {
        PlannedStroke s;
        s.layerIndex = static_cast<int>(u(rng) * 5);
        s.pathIndex = static_cast<int>(u(rng) * 1e5);
        job.strokes.push_back(s);
        stroke = static_cast<int>(job.strokes.size()) - 1;
      }
      m.strokeIndex = stroke;
    } else if (m.kind == JobMoveKind::Draw) {
      m.strokeIndex = stroke;
    }
    job.moves.push_back(m);
  }
  return job;
}

MachineProfile randomProfile(std::mt19937_64& rng, ToolKind tool) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  MachineProfile p = *preset("maker-plotter");
  p.tool.kind = tool;
  p.tool.penUpS = u(rng) < 0.5 ? 0.0 : std::floor(u(rng) * 400.0);
  p.tool.zFeedMmPerMin = u(rng) < 0.2 ? 1e-7 : 100.0 + 900.0 * u(rng);
  p.tool.laserPowerS = 1000.0 * u(rng);
  p.hasHomingSwitches = u(rng) < 0.5;
  if (u(rng) < 0.5) p.limits = JointLimits{-2.0, 3.0 * u(rng), -1.5, 2.5 * u(rng)};
  p.motors.junctionDeviationDeg = 0.05 * u(rng);
  return p;
}

// The text, or the exception message prefixed with "throws: ".
template <class Write>
std::string textOrError(Write write) {
  try {
    return write();
  } catch (const std::exception& e) {
    return std::string("throws: ") + e.what();
  }
}

// First differing line of two texts, for a readable failure.
std::string firstDifference(const std::string& a, const std::string& b) {
  const auto la = linesOf(a), lb = linesOf(b);
  for (size_t i = 0; i < std::min(la.size(), lb.size()); ++i)
    if (la[i] != lb[i]) return "line " + std::to_string(i + 1) + ": '" + la[i] + "' vs '" + lb[i] + "'";
  return "line counts " + std::to_string(la.size()) + " vs " + std::to_string(lb.size());
}

TEST(Gcode, ByteIdenticalToReferenceWriterOnRandomJobs) {
  std::mt19937_64 rng = test::rng();
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int compared = 0, thrown = 0;
  for (int trial = 0; trial < 96; ++trial) {
    const ToolKind tool = static_cast<ToolKind>(trial % 3);
    const MachineProfile p = randomProfile(rng, tool);
    GcodeOptions o;
    if (trial % 4 == 1) { o.angleDecimals = 0; o.feedDecimals = 0; }
    if (trial % 4 == 2) { o.angleDecimals = static_cast<int>(u(rng) * 10); o.feedDecimals = 3; }
    o.strokeComments = trial % 5 != 4;
    // Mostly awkward numbers in short jobs (each big value makes the line too long, as it should);
    // every third trial an ordinary job long enough to show the whole layout.
    const bool awkward = trial % 3 != 0;
    const PlannedJob job = randomJob(rng, awkward, awkward ? 6 : 3000);
    const std::string expected = textOrError([&] { return oracle::writeGcode(job, p, o); });
    const std::string actual = textOrError([&] { return writeGcode(job, p, o); });
    ASSERT_TRUE(actual == expected) << "trial " << trial << ", " << firstDifference(actual, expected);
    ++compared;
    thrown += expected.rfind("throws: ", 0) == 0 ? 1 : 0;
  }
  EXPECT_GT(thrown, 0);              // some jobs had lines too long
  EXPECT_LT(thrown, compared - 20);  // and most were written
}

// Jobs of 20000 moves or more are written in two halves (on two threads); the second half must
// pick up the state the first leaves: the last F and S sent, the laser power, the last stroke
// commented. Sizes vary so that the cut falls after every kind of move.
TEST(Gcode, LargeJobsWrittenInTwoHalvesAreByteIdenticalToTheReference) {
  std::mt19937_64 rng = test::rng();
  for (int trial = 0; trial < 18; ++trial) {
    const ToolKind tool = static_cast<ToolKind>(trial % 3);
    const MachineProfile p = randomProfile(rng, tool);
    GcodeOptions o;
    o.strokeComments = trial % 4 != 3;
    o.feedDecimals = trial % 5 == 2 ? 0 : 1;  // coarse F: many repeats across the cut
    PlannedJob job = randomJob(rng, false, 20000 + 3 * trial);
    const std::string expected = textOrError([&] { return oracle::writeGcode(job, p, o); });
    const std::string actual = textOrError([&] { return writeGcode(job, p, o); });
    ASSERT_TRUE(actual == expected) << "trial " << trial << ", " << firstDifference(actual, expected);
  }
}

TEST(Gcode, StreamedPiecesMakeTheSameTextAsTheOneString) {
  std::mt19937_64 rng = test::rng();
  for (int trial = 0; trial < 6; ++trial) {
    const ToolKind tool = static_cast<ToolKind>(trial % 3);
    const MachineProfile p = randomProfile(rng, tool);
    GcodeOptions o;
    o.strokeComments = trial % 2 == 0;
    // Several pieces (an odd number in some trials), and a small job of one piece.
    PlannedJob job = randomJob(rng, false, trial == 5 ? 500 : 120000 + 25000 * trial);
    const std::string expected = oracle::writeGcode(job, p, o);
    std::string streamed;
    int pieces = 0;
    writeGcode(job, p, [&](std::string_view piece) { streamed += piece, ++pieces; }, o);
    ASSERT_TRUE(streamed == expected) << "trial " << trial << ", " << firstDifference(streamed, expected);
    if (trial < 5) {
      EXPECT_GT(pieces, 2);
    }
  }
}

// A laser job cut in the middle of a stroke and one cut just before a travel: the S word must
// carry on (not be sent again, and be reset to S0 for the travel) across the cut.
TEST(Gcode, LargeLaserJobCarriesThePowerAcrossTheCut) {
  MachineProfile p = *preset("maker-plotter");
  p.tool.kind = ToolKind::Laser;
  for (size_t strokeMoves : {size_t{27}, size_t{7}}) {  // the cut (move 15000): a draw, a travel
    PlannedJob job;
    for (size_t i = 0; job.moves.size() < 30000; ++i) {
      JobMove m;
      m.kind = i % strokeMoves == 0 ? JobMoveKind::PenDown
               : i % strokeMoves == strokeMoves - 2 ? JobMoveKind::PenUp
               : i % strokeMoves == strokeMoves - 1 ? JobMoveKind::Travel
                                                    : JobMoveKind::Draw;
      m.toolValue = 100.0 + static_cast<double>(i / strokeMoves);
      m.target = {1e-3 * static_cast<double>(i), 2e-3 * static_cast<double>(i)};
      m.jointFeedRadPerS = 1.0;
      job.moves.push_back(m);
    }
    const std::string expected = oracle::writeGcode(job, p, {});
    const std::string actual = writeGcode(job, p);
    ASSERT_TRUE(actual == expected) << strokeMoves << ": " << firstDifference(actual, expected);
  }
}

TEST(Gcode, LargeJobReportsTheFirstLineTooLongLikeTheReference) {
  std::mt19937_64 rng = test::rng();
  const MachineProfile p = *preset("maker-plotter");
  PlannedJob job = randomJob(rng, false, 30000);
  for (size_t at : {size_t{25000}, size_t{12000}}) {
    job.moves[at].kind = JobMoveKind::Draw;
    job.moves[at].target.theta1 = 1e70 + static_cast<double>(at);
    const std::string expected = textOrError([&] { return oracle::writeGcode(job, p, {}); });
    const std::string actual = textOrError([&] { return writeGcode(job, p); });
    EXPECT_EQ(expected.rfind("throws: G-code line longer than 80 characters", 0), 0u) << at;
    EXPECT_EQ(actual, expected) << at;
  }
}

// Every awkward number alone (one G1 line each, so a too-long line only spoils its own job).
TEST(Gcode, EveryAwkwardNumberFormatsLikeTheReference) {
  std::mt19937_64 rng = test::rng();
  MachineProfile servo = *preset("maker-plotter");
  MachineProfile z = servo, laser = servo;
  z.tool.kind = ToolKind::ZAxis;
  laser.tool.kind = ToolKind::Laser;
  for (int i = 0; i < 4000; ++i) {
    PlannedJob job;
    JobMove m;
    m.kind = JobMoveKind::Draw;
    m.target = {radFromDeg(awkwardNumber(rng, 720.0)), radFromDeg(awkwardNumber(rng, 720.0))};
    m.jointFeedRadPerS = radFromDeg(awkwardNumber(rng, 300.0));
    JobMove down;
    down.kind = JobMoveKind::PenDown;
    down.toolValue = awkwardNumber(rng, 1000.0);
    down.dwellS = awkwardNumber(rng, 1.0);
    JobMove dwell;
    dwell.kind = JobMoveKind::Dwell;
    dwell.dwellS = awkwardNumber(rng, 1.0);
    job.moves = {down, m, dwell};
    GcodeOptions o;
    o.angleDecimals = i % 10;
    o.feedDecimals = (i / 10) % 4;
    for (const MachineProfile* p : {&servo, &z, &laser}) {
      const std::string expected = textOrError([&] { return oracle::writeGcode(job, *p, o); });
      const std::string actual = textOrError([&] { return writeGcode(job, *p, o); });
      ASSERT_TRUE(actual == expected) << "case " << i << ", " << firstDifference(actual, expected);
    }
  }
}

TEST(Gcode, RoundingIsHalfEvenOnExactTiesAndNeverNegativeZero) {
  MachineProfile p = *preset("maker-plotter");
  p.tool.kind = ToolKind::ZAxis;
  PlannedJob job;
  for (double z : {0.0625, 0.1875, -0.0625, -0.0004, -0.0, 1.0005, 2.0005}) {
    JobMove m;
    m.kind = JobMoveKind::PenDown;
    m.toolValue = z;
    job.moves.push_back(m);
  }
  const std::string text = writeGcode(job, p);
  // 0.0625 and 0.1875 are exact in binary: ties to even. The doubles nearest 1.0005 and 2.0005
  // are 1.000499999999999944... and 2.000500000000000166... (Python: decimal.Decimal(1.0005)).
  for (const char* needle : {"\nG1 Z0.062 F", "\nG1 Z0.188 F", "\nG1 Z-0.062 F", "\nG1 Z0.000 F",
                             "\nG1 Z1.000 F", "\nG1 Z2.001 F"})
    EXPECT_NE(text.find(needle), std::string::npos) << needle;
  EXPECT_EQ(text.find("-0.000"), std::string::npos);
}

TEST(Gcode, LineTooLongForGrblIsABrokenInvariantWithTheLineInTheMessage) {
  const MachineProfile p = *preset("maker-plotter");
  PlannedJob job;
  JobMove m;
  m.target = {1e70, 0.0};  // rad: X = 1e70 * 180 / pi = 5.7295779513...e71 deg, 72 digits
  m.jointFeedRadPerS = 1.0;
  job.moves = {m};
  try {
    (void)writeGcode(job, p);
    FAIL() << "no exception";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("longer than 80 characters: G1 X572957795130"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fivebar
