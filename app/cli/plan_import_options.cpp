// SPDX-License-Identifier: GPL-3.0-or-later
#include "plan_import_options.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <numbers>

#include "core/kinematics/units.hpp"
#include "core/text/hershey_font.hpp"


namespace fivebar::cli {

const char* const kPlanImportHelp =
    "  --max-points N            refuse drawings with more than N points after flattening and\n"
    "                            hatching (default 2000000): a guard against runaway files\n"
    "  --fill outline|hatch|none filled shapes: their outline (default), hatch lines, or not at\n"
    "                            all (shapes that are also stroked keep their stroke)\n"
    "  --hatch-spacing MM        distance between hatch lines, drawing mm (default 0.5)\n"
    "  --hatch-angle DEG         direction of the hatch lines, counter-clockwise (default 45)\n"
    "  --crosshatch              a second set of hatch lines at 90 deg to the first\n"
    "  --no-hatch-outline        hatch fill-only shapes without drawing their outline\n"
    "  --dashes dashed|solid     dashed strokes: their dashes, pen up between (default), or\n"
    "                            drawn whole\n"
    "  --text-font NAME          redraw SVG <text> in this single-stroke Hershey font (see\n"
    "                            'fivebar text --list-fonts') instead of its outlines\n"
    "  Import warnings (dropped images, unsupported features, path data errors) go to stderr.\n";

std::set<std::string> withImportValuedOptions(std::set<std::string> valued) {
  valued.insert({"--max-points", "--fill", "--hatch-spacing", "--hatch-angle", "--dashes", "--text-font"});
  return valued;
}

std::set<std::string> withImportFlags(std::set<std::string> flags) {
  flags.insert({"--crosshatch", "--no-hatch-outline"});
  return flags;
}

namespace {

double numberOption(const Options& o, const std::string& name, double fallback) {
  const auto text = o.value(name);
  if (!text) return fallback;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text->c_str(), &end);
  if (text->empty() || *end != '\0' || errno != 0 || !std::isfinite(v))
    throw UsageError(name + " needs a number, got '" + *text + "'");
  return v;
}

}  // namespace

PlanImportSettings planImportSettingsFrom(const Options& o) {
  PlanImportSettings s;
  if (const auto text = o.value("--max-points")) {
    char* end = nullptr;
    errno = 0;
    const unsigned long long n = std::strtoull(text->c_str(), &end, 10);
    if (text->empty() || (*text)[0] == '-' || *end != '\0' || errno != 0 || n == 0)
      throw UsageError("--max-points needs a positive whole number, got '" + *text + "'");
    s.maxPoints = static_cast<std::size_t>(n);
  }
  if (const auto mode = o.value("--fill")) {
    const auto fill = fillModeFromString(*mode);
    if (!fill) throw UsageError("--fill must be outline, hatch or none, got '" + *mode + "'");
    s.fill = *fill;
  }
  if (const auto dashes = o.value("--dashes")) {
    if (*dashes != "dashed" && *dashes != "solid")
      throw UsageError("--dashes must be dashed or solid, got '" + *dashes + "'");
    s.solidDashes = *dashes == "solid";
  }
  if (const auto font = o.value("--text-font")) {
    const text::FontLoad load = text::loadFont(*font);
    if (!load.font) throw UsageError("--text-font: " + text::toString(load.error));
    s.textFont = *font;
  }
  s.hatch.spacingMm = numberOption(o, "--hatch-spacing", 0.5);
  s.hatch.angleRad = radFromDeg(numberOption(o, "--hatch-angle", 45.0));  // as the studio converts
  s.hatch.crosshatch = o.flag("--crosshatch");
  s.hatch.outline = !o.flag("--no-hatch-outline");
  if (const std::string bad = validate(s.hatch); !bad.empty()) throw UsageError("--hatch-spacing: " + bad);
  const bool hatchOptions = o.value("--hatch-spacing") || o.value("--hatch-angle") ||
                            s.hatch.crosshatch || !s.hatch.outline;
  if (hatchOptions && s.fill != FillMode::Hatch)
    throw UsageError("--hatch-spacing, --hatch-angle, --crosshatch and --no-hatch-outline need --fill hatch");
  return s;
}

std::size_t pointCount(const Drawing& drawing) {
  std::size_t n = 0;
  for (const Layer& layer : drawing.layers)
    if (layer.visible)
      for (const Polyline& line : filledPaths(layer)) n += line.points.size();
  return n;
}

bool withinPointBudget(const std::string& file, const Drawing& drawing, const PlanImportSettings& settings) {
  const std::size_t points = pointCount(drawing);
  if (points <= settings.maxPoints) return true;
  std::cerr << "fivebar plan: " << file << ": the drawing has " << points << " points after flattening"
            << (settings.fill == FillMode::Hatch ? " and hatching" : "") << ", more than the budget of "
            << settings.maxPoints << " (a runaway file?); nothing planned. Raise it with --max-points "
            << points << " if the drawing is meant to be this big\n";
  return false;
}

}  // namespace fivebar::cli
