// G-code: lines of at most 80 characters that parse back to the planned joint targets and feeds,
// the header names the profile and the $ settings, tool commands per tool kind, M0 for a pen
// change, rounding far below a motor step.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <sstream>

#include "core/gcode.hpp"
#include "core/planner.hpp"
#include "test_support.hpp"

namespace fivebar {
namespace {

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

// Words of a G-code line ("G1 X1.5 Y-2" -> {G:1, X:1.5, Y:-2}); comments dropped.
std::map<char, double> wordsOf(const std::string& line) {
  std::map<char, double> w;
  std::istringstream in(line.substr(0, line.find(';')));
  for (std::string word; in >> word;) w[word[0]] = std::stod(word.substr(1));
  return w;
}

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

}  // namespace
}  // namespace fivebar
