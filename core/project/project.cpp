// SPDX-License-Identifier: GPL-3.0-or-later
// The .fivebar project file. Contract: project.hpp; schema: docs/project-file.md.
#include "core/project/project.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/kinematics/units.hpp"
#include "core/machine/profile_json.hpp"
#include "core/planning/hatch.hpp"

namespace fivebar {
namespace {

using nlohmann::json;
using detail::ObjectReader;

json toolJson(const LayerToolSettings& t) {
  return {{"draw_speed_mm_per_s", t.drawSpeedMmPerS}, {"power", t.power}, {"pause_before", t.pauseBefore}};
}

void readTool(ObjectReader& layer, LayerToolSettings& t, std::vector<ValidationIssue>& issues) {
  const json* tj = layer.object("tool");
  if (!tj) return;
  ObjectReader r(*tj, layer.pathOf("tool"), issues);
  r.number("draw_speed_mm_per_s", t.drawSpeedMmPerS);
  r.number("power", t.power);
  r.boolean("pause_before", t.pauseBefore);
  r.finish();
  if (!(t.drawSpeedMmPerS >= 0.0) || !std::isfinite(t.drawSpeedMmPerS))
    issues.push_back({layer.pathOf("tool") + ".draw_speed_mm_per_s",
                      layer.pathOf("tool") + ".draw_speed_mm_per_s must be 0 (profile default) or positive"});
}

json fillJson(const ProjectLayer& l) {
  return {{"mode", toString(l.fill)},
          {"hatch_spacing_mm", l.hatch.spacingMm},
          {"hatch_angle_deg", degFromRad(l.hatch.angleRad)},
          {"crosshatch", l.hatch.crosshatch},
          {"hatch_outline", l.hatch.outline}};
}

void readFill(ObjectReader& layer, ProjectLayer& l, std::vector<ValidationIssue>& issues) {
  const json* fj = layer.object("fill");
  if (!fj) return;  // version 1: outline
  const std::string path = layer.pathOf("fill");
  ObjectReader r(*fj, path, issues);
  std::string mode = "outline";
  double angleDeg = degFromRad(l.hatch.angleRad);
  r.string("mode", mode, true);
  r.number("hatch_spacing_mm", l.hatch.spacingMm);
  r.number("hatch_angle_deg", angleDeg);
  r.boolean("crosshatch", l.hatch.crosshatch);
  r.boolean("hatch_outline", l.hatch.outline);
  r.finish();
  l.hatch.angleRad = radFromDeg(angleDeg);
  if (const auto m = fillModeFromString(mode)) l.fill = *m;
  else issues.push_back({path + ".mode", path + ".mode must be outline, hatch or none, got '" + mode + "'"});
  if (const std::string bad = validate(l.hatch); !bad.empty())
    issues.push_back({path + ".hatch_spacing_mm", path + ": " + bad});
}

void readPlacement(ObjectReader& root, Placement& p, std::vector<ValidationIssue>& issues) {
  const json* pj = root.object("placement", true);
  if (!pj) return;
  ObjectReader r(*pj, "placement", issues);
  double x = 0.0, y = 0.0, rotationDeg = 0.0;
  r.number("center_x_mm", x, true);
  r.number("center_y_mm", y, true);
  r.number("rotation_deg", rotationDeg);
  r.number("scale", p.scale, true);
  r.number("stretch_y", p.stretchY);
  r.finish();
  p.centerMm = Vec2(x, y);
  p.rotationRad = radFromDeg(rotationDeg);
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(rotationDeg))
    issues.push_back({"placement", "placement: centre and rotation must be finite numbers"});
  if (!(p.scale > 0.0) || !std::isfinite(p.scale))
    issues.push_back({"placement.scale", "placement.scale must be a positive number"});
  if (!(p.stretchY > 0.0) || !std::isfinite(p.stretchY))
    issues.push_back({"placement.stretch_y", "placement.stretch_y must be a positive number"});
}

void readLayers(const json& doc, std::vector<ProjectLayer>& out, std::vector<ValidationIssue>& issues) {
  const auto it = doc.find("layers");
  if (it == doc.end()) return;
  if (!it->is_array()) {
    issues.push_back({"layers", "layers must be an array"});
    return;
  }
  for (std::size_t i = 0; i < it->size(); ++i) {
    const std::string path = "layers[" + std::to_string(i) + "]";
    ObjectReader r((*it)[i], path, issues);
    ProjectLayer l;
    r.string("id", l.id, true);
    r.string("name", l.name);
    r.boolean("visible", l.visible);
    readTool(r, l.tool, issues);
    readFill(r, l, issues);
    r.finish();
    out.push_back(std::move(l));
  }
}

void readMachine(ObjectReader& root, const std::string& sourceName, Project& p,
                 std::vector<ValidationIssue>& issues) {
  const json* mj = root.object("machine", true);
  if (!mj) return;
  ProfileLoad load = profileFromJson(mj->dump(), sourceName);
  for (ValidationIssue& issue : load.issues) {
    issue.field = "machine." + issue.field;
    issue.message = FB_TR("Profile", "machine: %1").arg(issue.message);
    issues.push_back(std::move(issue));
  }
  if (load.profile) p.profile = *load.profile;
}

}  // namespace

std::string projectToJson(const Project& p) {
  json layers = json::array();
  for (const ProjectLayer& l : p.layers)
    layers.push_back({{"id", l.id}, {"name", l.name}, {"visible", l.visible}, {"tool", toolJson(l.tool)},
                      {"fill", fillJson(l)}});
  json doc = {
      {"format", kProjectFormatName},
      {"version", kProjectFormatVersion},
      {"drawing", {{"name", p.drawingName},
                   {"flattening_tolerance_mm", p.flatteningToleranceMm},
                   {"dashes", p.solidDashes ? "solid" : "dashed"},
                   {"svg", p.drawingSvg}}},
      {"placement", {{"center_x_mm", p.placement.centerMm.x()},
                     {"center_y_mm", p.placement.centerMm.y()},
                     {"rotation_deg", degFromRad(p.placement.rotationRad)},
                     {"scale", p.placement.scale},
                     {"stretch_y", p.placement.stretchY}}},
      {"layers", layers},
      {"mode", p.mode ? std::string(toString(*p.mode)) : std::string("auto")},
      {"tolerance_mm", p.toleranceMm},
      {"machine", json::parse(toJson(p.profile))},
  };
  if (!p.textFont.empty()) doc["drawing"]["text_font"] = p.textFont;  // absent: outlines
  return doc.dump(2) + "\n";
}

ProjectLoad projectFromJson(const std::string& text, const std::string& sourceName) {
  ProjectLoad out;
  json doc;
  if (const auto error = detail::parseJsonText(text, doc)) {
    const detail::TextPosition pos = error->position;
    out.issues.push_back({"json", sourceName + ":" + std::to_string(pos.line) + ":" +
                                      std::to_string(pos.column) + ": not a project file (invalid JSON)"});
    return out;
  }
  if (!doc.is_object()) {
    out.issues.push_back({"json", sourceName + ": a project must be a JSON object ({...})"});
    return out;
  }
  json rest = doc;  // everything but the layers array, read by the strict object reader
  rest.erase("layers");
  ObjectReader root(rest, "", out.issues);
  std::string format;
  int version = 0;
  root.string("format", format, true);
  root.integer("version", version, true);
  if (!out.issues.empty()) return out;
  if (format != kProjectFormatName) {
    out.issues.push_back({"format", "format must be \"" + std::string(kProjectFormatName) + "\", got \"" + format + "\""});
    return out;
  }
  if (version < 1 || version > kProjectFormatVersion) {
    out.issues.push_back({"version", "version " + std::to_string(version) + " is not supported (this build reads 1 to " +
                                         std::to_string(kProjectFormatVersion) + ")"});
    return out;
  }
  Project p;
  if (const json* dj = root.object("drawing", true)) {
    ObjectReader d(*dj, "drawing", out.issues);
    d.string("name", p.drawingName);
    d.number("flattening_tolerance_mm", p.flatteningToleranceMm, true);
    d.string("svg", p.drawingSvg, true);
    std::string dashes = "dashed";
    d.string("dashes", dashes);
    d.string("text_font", p.textFont);
    d.finish();
    if (dashes != "dashed" && dashes != "solid")
      out.issues.push_back({"drawing.dashes", "drawing.dashes must be \"dashed\" or \"solid\", not \"" + dashes + "\""});
    p.solidDashes = dashes == "solid";
    if (!(p.flatteningToleranceMm > 0.0) || !std::isfinite(p.flatteningToleranceMm))
      out.issues.push_back({"drawing.flattening_tolerance_mm", "drawing.flattening_tolerance_mm must be positive"});
  }
  readPlacement(root, p.placement, out.issues);
  readLayers(doc, p.layers, out.issues);
  std::string mode = "auto";
  root.string("mode", mode);
  if (mode != "auto") {
    p.mode = parseWorkingMode(mode);
    if (!p.mode) out.issues.push_back({"mode", "mode must be auto, ++, +-, -+ or --, got \"" + mode + "\""});
  }
  root.number("tolerance_mm", p.toleranceMm);
  if (!(p.toleranceMm > 0.0) || !std::isfinite(p.toleranceMm))
    out.issues.push_back({"tolerance_mm", "tolerance_mm must be positive"});
  readMachine(root, sourceName, p, out.issues);
  root.finish();
  if (out.issues.empty()) out.project = std::move(p);
  return out;
}

std::vector<ProjectLayer> layerStatesOf(const Drawing& drawing) {
  std::vector<ProjectLayer> out;
  for (const Layer& l : drawing.layers) out.push_back({l.id, l.name, l.visible, l.tool, l.fill, l.hatch});
  return out;
}

void applyLayerStates(Drawing& drawing, const std::vector<ProjectLayer>& states) {
  std::vector<Layer> ordered;
  std::vector<bool> used(drawing.layers.size(), false);
  for (const ProjectLayer& s : states)
    for (std::size_t i = 0; i < drawing.layers.size(); ++i)
      if (!used[i] && drawing.layers[i].id == s.id) {
        used[i] = true;
        Layer l = std::move(drawing.layers[i]);
        l.visible = s.visible;
        l.tool = s.tool;
        l.fill = s.fill;
        l.hatch = s.hatch;
        ordered.push_back(std::move(l));
        break;
      }
  for (std::size_t i = 0; i < drawing.layers.size(); ++i)
    if (!used[i]) ordered.push_back(std::move(drawing.layers[i]));
  drawing.layers = std::move(ordered);
}

PlanOptions planOptionsOf(const Project& project) {
  PlanOptions o;
  o.mode = project.mode;
  o.toleranceMm = project.toleranceMm;
  setFixedPlacement(o, project.placement);
  return o;
}

}  // namespace fivebar
