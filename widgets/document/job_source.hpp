// Where a job's drawing comes from, the same for the studio (window and --export-gcode) and for
// `fivebar plan`: an SVG file or a .fivebar project, imported through the SVG worker from its
// bytes (a temporary file), placed by core's autoPlacement when no placement is given, and
// planned by core's planJob, imported again more finely when the planner asks for it. Two
// callers that use these functions get byte-identical G-code for the same input.
#pragma once

#include <QByteArray>
#include <QString>
#include <atomic>
#include <optional>
#include <string>

#include "core/machine/profile.hpp"
#include "core/planning/auto_placement.hpp"
#include "core/planning/hatch.hpp"
#include "core/planning/planner.hpp"
#include "core/project/project.hpp"

namespace fivebar::widgets {

struct DrawingSource {
  QByteArray svg;  // the SVG text
  QString name;    // file name, for messages and the project
  // How filled shapes are drawn (core/planning/hatch.hpp): every layer of an import of this source
  // gets it as its fill (Layer::fill; a project's layers then take their saved fills).
  FillMode fill = FillMode::Outline;
  HatchSettings hatch;
  // Points after flattening an import of this source may produce (0 = no limit): the import
  // stops reading as soon as the count passes it and fails naming the budget (every import of
  // the source, the finer re-import too). kDefaultMaxPoints (drawing.hpp) is the usual budget.
  std::size_t maxPoints = 0;
  bool solidDashes = false;  // dashed strokes drawn whole (svg::DashMode::Solid)
  // SVG <text> redrawn in this Hershey single-stroke font (svg::ImportOptions::textFont;
  // docs/text.md); empty: the outlines of the text's own font.
  std::string textFont;
};

// True when `error` came from an import stopped by DrawingSource::maxPoints.
bool isPointBudgetError(const std::string& error);

// Imports SVG text flattened within toleranceMm (work mm); the result carries that tolerance
// (Drawing::flatteningToleranceMm) and `name` as its source. On failure returns nullopt and
// sets `error` (names the file). Blocking; safe off the UI thread.
// The importer's warnings (truncated path data, dropped images, unsupported features) are
// appended to `warnings` when given.
std::optional<Drawing> importSvgText(const DrawingSource& source, double toleranceMm,
                                     std::string& error,
                                     const std::atomic<bool>* cancel = nullptr,
                                     std::vector<Message>* warnings = nullptr);

// planJob, and when the drawing was flattened too coarsely for its placement, the drawing
// imported again within the tolerance the planner names and planned again (`drawing` is then
// the finer one). Needs a fixed placement in `options` for the result not to depend on the
// flattening.
PlanResult planRefining(Drawing& drawing, const DrawingSource& source, const MachineProfile& profile,
                        const PlanOptions& options, std::string& error);
// The same without touching `drawing`: `refined` is set to the finer import when one was
// planned (the studio plans its document's drawing without copying it).
PlanResult planRefining(const Drawing& drawing, const DrawingSource& source,
                        const MachineProfile& profile, const PlanOptions& options,
                        std::optional<Drawing>& refined, std::string& error);

// A job read from DRAWING.svg or PROJECT.fivebar, ready for planRefining.
struct LoadedJob {
  DrawingSource source;
  Drawing drawing;
  PlanOptions options;      // mode, tolerance and the fixed placement
  MachineProfile profile;   // the project's, or the one passed in
  Message note;             // "scaled to 62 % to fit the workspace" or empty
  std::vector<Message> warnings;  // the import's warnings ("line 3: <path id=...> ...")
  bool isProject = false;
  std::optional<Project> project;  // the project as read (isProject)
};

// True for a path that names a project (.fivebar).
bool isProjectPath(const QString& path);

// Loads a drawing or a project. For a drawing, `options` (mode, tolerance, placement options)
// and `profile` apply and the placement is chosen as in planJob (autoPlacement unless fixed);
// for a project its own settings apply, and `profile` replaces its machine when given.
// `fill`/`hatch` apply to a drawing (a project keeps outline fills); `maxPoints` to both (the
// import stops past it, DrawingSource::maxPoints).
std::optional<LoadedJob> loadJob(const QString& path, const std::optional<MachineProfile>& profile,
                                 PlanOptions options, std::string& error,
                                 FillMode fill = FillMode::Outline, const HatchSettings& hatch = {},
                                 std::size_t maxPoints = 0, bool solidDashes = false,
                                 const std::string& textFont = {});

// The same for SVG text already in memory (the built-in demo).
std::optional<LoadedJob> loadDrawing(const DrawingSource& source, const MachineProfile& profile,
                                     PlanOptions options, std::string& error);

// The Project of a loaded drawing with its current layers, placement and settings.
Project projectOf(const DrawingSource& source, const Drawing& drawing, const Placement& placement,
                  std::optional<WorkingMode> mode, double toleranceMm, const MachineProfile& profile);

}  // namespace fivebar::widgets
