// SPDX-License-Identifier: GPL-3.0-or-later
// The job library's door (fivebar::job, Qt Core + the SVG import, no Gui widgets): where a job's
// drawing comes from, the same for the studio (window and --export-gcode) and for `fivebar plan`:
// an SVG file or a .fivebar project, imported through the SVG worker (the file itself while it is
// unchanged since it was read, else its bytes through a temporary copy), placed by core's
// autoPlacement when no placement is given, and planned by core's planJob, imported again more
// finely when the planner asks for it. Two callers that use these functions get byte-identical
// G-code for the same input.
#pragma once

#include <QByteArray>
#include <QDateTime>
#include <QString>
#include <atomic>
#include <optional>
#include <string>

#include "core/machine/profile.hpp"
#include "core/planning/auto_placement.hpp"
#include "core/planning/hatch.hpp"
#include "core/planning/planner.hpp"
#include "core/import/svg_import.hpp"
#include "core/project/project.hpp"

namespace fivebar::job {

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
  // The file `svg` was read from, with its size and modification time then ("" for text made in
  // memory: the demo, a project's embedded drawing). While the file is unchanged the import hands
  // this path to the worker; otherwise the bytes go through a temporary copy.
  QString path;
  qint64 fileSize = -1;
  QDateTime fileModified;
};

// Why loading or planning a job failed: the words (naming the file) and, for an import, its
// status as a value (svg::ImportStatus::TooManyPoints when DrawingSource::maxPoints stopped it).
struct JobError {
  std::string text;  // empty = no error
  svg::ImportStatus importStatus = svg::ImportStatus::Ok;
  bool empty() const { return text.empty(); }
  bool pointBudgetExceeded() const { return importStatus == svg::ImportStatus::TooManyPoints; }
};

// Imports SVG text flattened within toleranceMm (work mm); the result carries that tolerance
// (Drawing::flatteningToleranceMm) and `name` as its source. On failure returns nullopt and
// sets `error` (names the file). Blocking; safe off the UI thread.
// The importer's warnings (truncated path data, dropped images, unsupported features) are
// appended to `warnings` when given.
std::optional<Drawing> importSvgText(const DrawingSource& source, double toleranceMm,
                                     JobError& error,
                                     const std::atomic<bool>* cancel = nullptr,
                                     std::vector<Message>* warnings = nullptr);

// planJob, and when the drawing was flattened too coarsely for its placement, the drawing
// imported again within the tolerance the planner names and planned again (`drawing` is then
// the finer one). Needs a fixed placement in `options` for the result not to depend on the
// flattening.
PlanResult planRefining(Drawing& drawing, const DrawingSource& source, const MachineProfile& profile,
                        const PlanOptions& options, JobError& error);
// The same without touching `drawing`: `refined` is set to the finer import when one was
// planned (the studio plans its document's drawing without copying it).
PlanResult planRefining(const Drawing& drawing, const DrawingSource& source,
                        const MachineProfile& profile, const PlanOptions& options,
                        std::optional<Drawing>& refined, JobError& error);

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
                                 PlanOptions options, JobError& error,
                                 FillMode fill = FillMode::Outline, const HatchSettings& hatch = {},
                                 std::size_t maxPoints = 0, bool solidDashes = false,
                                 const std::string& textFont = {});

// The same for SVG text already in memory (the built-in demo).
std::optional<LoadedJob> loadDrawing(const DrawingSource& source, const MachineProfile& profile,
                                     PlanOptions options, JobError& error);

// The Project of a loaded drawing with its current layers, placement and settings.
Project projectOf(const DrawingSource& source, const Drawing& drawing, const Placement& placement,
                  std::optional<WorkingMode> mode, double toleranceMm, const MachineProfile& profile);

}  // namespace fivebar::job
