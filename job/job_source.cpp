// SPDX-License-Identifier: GPL-3.0-or-later
// Job sources shared by the studio and `fivebar plan`. Contract: job_source.hpp.
#include "job/job_source.hpp"

#include <utility>

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryFile>

#include "i18n/translated.hpp"

namespace fivebar::job {

namespace {
// The studio's own sentences about a source, in the user's language (context "JobPipeline").
QString trSource(const char* text) { return QCoreApplication::translate("JobPipeline", text); }
}  // namespace

bool isProjectPath(const QString& path) {
  return path.endsWith(QStringLiteral(".fivebar"), Qt::CaseInsensitive);
}

namespace {

// The source's own file while it is what was read (same size and time), else none.
bool fileUnchanged(const DrawingSource& source) {
  if (source.path.isEmpty()) return false;
  const QFileInfo info(source.path);
  return info.isFile() && info.size() == source.fileSize && info.lastModified() == source.fileModified;
}

}  // namespace

std::optional<Drawing> importSvgText(const DrawingSource& source, double toleranceMm,
                                     JobError& error, const std::atomic<bool>* cancel,
                                     std::vector<Message>* warnings) {
  svg::ImportOptions options;
  options.toleranceMm = toleranceMm;
  options.cancel = cancel;
  options.maxPoints = source.maxPoints;
  options.dashes = source.solidDashes ? svg::DashMode::Solid : svg::DashMode::Dashed;
  options.textFont = source.textFont;
  // Through a file, so that the import runs in the isolated worker process: the source's own
  // when it is unchanged, else a temporary copy of the bytes.
  QTemporaryFile copy(QDir::temp().filePath(QStringLiteral("fivebar-import-XXXXXX.svg")));
  QString importPath = source.path;
  if (!fileUnchanged(source)) {
    if (!copy.open() || copy.write(source.svg) != source.svg.size() || !copy.flush()) {
      error.text = trSource(QT_TRANSLATE_NOOP("JobPipeline", "%1: cannot write a temporary copy to import"))
                       .arg(source.name).toStdString();
      return std::nullopt;
    }
    copy.close();
    importPath = copy.fileName();
  }
  svg::ImportResult r = svg::importSvgFile(importPath, options);
  if (!r.ok()) {
    // In the user's language, naming the drawing, not the file it was read through.
    const QString message = translated(r.message).replace(importPath, source.name);
    error.importStatus = r.status;
    error.text = message.isEmpty()
                     ? trSource(QT_TRANSLATE_NOOP("JobPipeline", "%1: cannot be imported")).arg(source.name).toStdString()
                     : message.toStdString();
    return std::nullopt;
  }
  if (warnings) warnings->insert(warnings->end(), r.warnings.begin(), r.warnings.end());
  // The fill is the layers' own (applied where the drawing is placed), so it can change per layer.
  for (Layer& layer : r.drawing.layers) {
    layer.fill = source.fill;
    layer.hatch = source.hatch;
  }
  r.drawing.source = source.name.toStdString();
  r.drawing.flatteningToleranceMm = toleranceMm;
  return std::move(r.drawing);
}

PlanResult planRefining(const Drawing& drawing, const DrawingSource& source,
                        const MachineProfile& profile, const PlanOptions& options,
                        std::optional<Drawing>& refined, JobError& error) {
  refined.reset();
  PlanResult r = planJob(drawing, profile, options);
  // One finer import is enough with a fixed placement; a second guards a moved bounding box.
  for (int attempt = 0; attempt < 2 && r.status == PlanStatus::CoarseDrawing; ++attempt) {
    std::vector<ProjectLayer> layers = layerStatesOf(refined ? *refined : drawing);
    auto finer = importSvgText(source, r.requiredFlatteningToleranceMm, error, options.cancel);
    if (!finer) return r;
    applyLayerStates(*finer, layers);
    refined = std::move(finer);
    r = planJob(*refined, profile, options);
  }
  return r;
}

PlanResult planRefining(Drawing& drawing, const DrawingSource& source, const MachineProfile& profile,
                        const PlanOptions& options, JobError& error) {
  std::optional<Drawing> refined;
  PlanResult r = planRefining(std::as_const(drawing), source, profile, options, refined, error);
  if (refined) drawing = std::move(*refined);
  return r;
}

namespace {

bool readFile(const QString& path, QByteArray& out, JobError& error) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) {
    error.text = trSource(QT_TRANSLATE_NOOP("JobPipeline", "%1: cannot read (%2)")).arg(path, f.errorString()).toStdString();
    return false;
  }
  out = f.readAll();
  return true;
}

std::optional<LoadedJob> loadProject(const QString& path, const std::optional<MachineProfile>& profile,
                                     JobError& error, std::size_t maxPoints) {
  QByteArray text;
  if (!readFile(path, text, error)) return std::nullopt;
  ProjectLoad load = projectFromJson(text.toStdString(), path.toStdString());
  if (!load.project) {
    error = JobError{};
    for (const ValidationIssue& issue : load.issues)
      error.text += (error.empty() ? QString() : QStringLiteral("\n")).toStdString() +
                    QStringLiteral("%1: %2").arg(path, translated(issue.message)).toStdString();
    return std::nullopt;
  }
  LoadedJob job;
  job.isProject = true;
  Project& p = *load.project;
  if (profile) p.profile = *profile;
  job.source.svg = QByteArray::fromStdString(p.drawingSvg);
  job.source.name = QString::fromStdString(p.drawingName);
  if (job.source.name.isEmpty()) job.source.name = QFileInfo(path).fileName();
  job.source.maxPoints = maxPoints;
  job.source.solidDashes = p.solidDashes;
  job.source.textFont = p.textFont;
  auto drawing = importSvgText(job.source, p.flatteningToleranceMm, error, nullptr, &job.warnings);
  if (!drawing) return std::nullopt;
  applyLayerStates(*drawing, p.layers);
  job.drawing = std::move(*drawing);
  job.options = planOptionsOf(p);
  job.profile = p.profile;
  job.project = std::move(p);
  return job;
}

}  // namespace

std::optional<LoadedJob> loadDrawing(const DrawingSource& source, const MachineProfile& profile,
                                     PlanOptions options, JobError& error) {
  LoadedJob job;
  job.profile = profile;
  job.source = source;
  const bool fixed = options.atMm && !options.fit;
  const double scale = fixed ? options.scale * std::max(1.0, options.stretchY) : 1.0;
  auto drawing = importSvgText(job.source, importToleranceMm(options.toleranceMm, scale), error,
                               options.cancel, &job.warnings);
  if (!drawing) return std::nullopt;
  job.drawing = std::move(*drawing);
  if (!fixed) {
    const auto placed = autoPlacement(job.drawing, job.profile, options.mode, options.rotationRad,
                                      options.fit ? PlacementSizing::Fit : PlacementSizing::TrueSize);
    if (placed) {
      setFixedPlacement(options, placed->placement);
      job.note = scaleNote(*placed);
    }
    // No placement: planJob reports why (empty drawing or no singularity-free area).
  }
  job.options = options;
  return job;
}

std::optional<LoadedJob> loadJob(const QString& path, const std::optional<MachineProfile>& profile,
                                 PlanOptions options, JobError& error, FillMode fill,
                                 const HatchSettings& hatch, std::size_t maxPoints, bool solidDashes,
                                 const std::string& textFont) {
  if (isProjectPath(path)) return loadProject(path, profile, error, maxPoints);
  if (!profile) {
    error.text = trSource(QT_TRANSLATE_NOOP("JobPipeline", "no machine profile given")).toStdString();
    return std::nullopt;
  }
  DrawingSource source;
  source.name = QFileInfo(path).fileName();
  source.fill = fill;
  source.hatch = hatch;
  source.maxPoints = maxPoints;
  source.solidDashes = solidDashes;
  source.textFont = textFont;
  if (!readFile(path, source.svg, error)) return std::nullopt;
  // The worker reads the file itself while it stays as read (no temporary copy of its bytes).
  const QFileInfo info(path);
  source.path = info.absoluteFilePath();
  source.fileSize = info.size();
  source.fileModified = info.lastModified();
  if (source.fileSize != source.svg.size()) source.path.clear();  // changed while read
  return loadDrawing(source, *profile, std::move(options), error);
}

Project projectOf(const DrawingSource& source, const Drawing& drawing, const Placement& placement,
                  std::optional<WorkingMode> mode, double toleranceMm, const MachineProfile& profile) {
  Project p;
  p.drawingName = source.name.toStdString();
  p.drawingSvg = source.svg.toStdString();
  p.flatteningToleranceMm = drawing.flatteningToleranceMm;
  p.solidDashes = source.solidDashes;
  p.textFont = source.textFont;
  p.placement = placement;
  p.layers = layerStatesOf(drawing);
  p.mode = mode;
  p.toleranceMm = toleranceMm;
  p.profile = profile;
  return p;
}

}  // namespace fivebar::job
