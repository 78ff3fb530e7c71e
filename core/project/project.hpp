// SPDX-License-Identifier: GPL-3.0-or-later
// A saved studio project (.fivebar): versioned JSON holding the drawing itself (the SVG text, so
// that a project moves between computers), its placement, layer order, visibility and tools, the
// working mode, the tolerance and the machine profile. Schema: docs/project-file.md. The SVG is
// imported by the caller (Qt); this model only stores and validates.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/kinematics/modes.hpp"
#include "core/machine/profile.hpp"
#include "core/planning/drawing.hpp"
#include "core/planning/placement.hpp"
#include "core/planning/planner.hpp"

namespace fivebar {

// Version 2 adds each layer's fill; version 1 files load with outline fills.
inline constexpr int kProjectFormatVersion = 2;
inline constexpr const char* kProjectFormatName = "fivebar-project";

// The user's settings of one layer, matched to the imported drawing by Layer::id.
struct ProjectLayer {
  std::string id;
  std::string name;  // informative; the drawing's own name wins on load
  bool visible = true;
  LayerToolSettings tool;
  FillMode fill = FillMode::Outline;  // how its filled shapes are drawn (format version 2)
  HatchSettings hatch;
};

struct Project {
  std::string drawingName;             // the file the drawing was imported from (base name)
  std::string drawingSvg;              // its SVG text
  double flatteningToleranceMm = 0.0;  // the import tolerance the drawing was flattened with
  bool solidDashes = false;            // dashed strokes drawn whole ("dashes": "solid"; default dashed)
  std::string textFont;                // <text> redrawn in this Hershey font ("text_font"); empty: outlines
  Placement placement;
  std::vector<ProjectLayer> layers;    // in plotting order
  std::optional<WorkingMode> mode;     // nullopt: Auto
  double toleranceMm = 0.1;
  MachineProfile profile;
};

struct ProjectLoad {
  std::optional<Project> project;
  std::vector<ValidationIssue> issues;  // field paths like "placement.scale", "machine.geometry.a1"
};

std::string projectToJson(const Project& project);
// sourceName names the file in messages (JSON syntax errors give its line and column).
ProjectLoad projectFromJson(const std::string& text, const std::string& sourceName);

// The layer settings of a drawing, in its order.
std::vector<ProjectLayer> layerStatesOf(const Drawing& drawing);
// Puts the drawing's layers in the order of `states` (matched by id; layers the project does not
// name follow in their own order) and applies visibility and tools.
void applyLayerStates(Drawing& drawing, const std::vector<ProjectLayer>& states);

// The planner options of the project: its mode, tolerance and fixed placement.
PlanOptions planOptionsOf(const Project& project);

}  // namespace fivebar
