// Job sources shared by the studio and `fivebar plan`. Contract: job_source.hpp.
#include "widgets/document/job_source.hpp"

#include <utility>

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryFile>

#include "core/import/svg_import.hpp"
#include "widgets/document/core_message.hpp"

namespace fivebar::widgets {

namespace {
// The studio's own sentences about a source, in the user's language (context "JobPipeline").
QString trSource(const char* text) { return QCoreApplication::translate("JobPipeline", text); }
}  // namespace

bool isProjectPath(const QString& path) {
  return path.endsWith(QStringLiteral(".fivebar"), Qt::CaseInsensitive);
}

std::optional<Drawing> importSvgText(const DrawingSource& source, double toleranceMm,
                                     std::string& error, const std::atomic<bool>* cancel,
                                     std::vector<Message>* warnings) {
  // Through a file, so that the import runs in the isolated worker process.
  QTemporaryFile file(QStringLiteral("fivebar-import-XXXXXX.svg"));
  if (!file.open() || file.write(source.svg) != source.svg.size() || !file.flush()) {
    error = trSource(QT_TRANSLATE_NOOP("JobPipeline", "%1: cannot write a temporary copy to import"))
                .arg(source.name).toStdString();
    return std::nullopt;
  }
  file.close();
  svg::ImportOptions options;
  options.toleranceMm = toleranceMm;
  options.cancel = cancel;
  options.maxPoints = source.maxPoints;
  options.dashes = source.solidDashes ? svg::DashMode::Solid : svg::DashMode::Dashed;
  options.textFont = source.textFont;
  svg::ImportResult r = svg::importSvgFile(file.fileName(), options);
  if (!r.ok()) {
    // In the user's language, naming the drawing, not the temporary copy.
    const QString message = translated(r.message).replace(file.fileName(), source.name);
    error = message.isEmpty()
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

bool isPointBudgetError(const std::string& error) {
  return error.find("(the points budget)") != std::string::npos;
}

PlanResult planRefining(const Drawing& drawing, const DrawingSource& source,
                        const MachineProfile& profile, const PlanOptions& options,
                        std::optional<Drawing>& refined, std::string& error) {
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
                        const PlanOptions& options, std::string& error) {
  std::optional<Drawing> refined;
  PlanResult r = planRefining(std::as_const(drawing), source, profile, options, refined, error);
  if (refined) drawing = std::move(*refined);
  return r;
}

namespace {

bool readFile(const QString& path, QByteArray& out, std::string& error) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) {
    error = trSource(QT_TRANSLATE_NOOP("JobPipeline", "%1: cannot read (%2)")).arg(path, f.errorString()).toStdString();
    return false;
  }
  out = f.readAll();
  return true;
}

std::optional<LoadedJob> loadProject(const QString& path, const std::optional<MachineProfile>& profile,
                                     std::string& error, std::size_t maxPoints) {
  QByteArray text;
  if (!readFile(path, text, error)) return std::nullopt;
  ProjectLoad load = projectFromJson(text.toStdString(), path.toStdString());
  if (!load.project) {
    error.clear();
    for (const ValidationIssue& issue : load.issues)
      error += (error.empty() ? QString() : QStringLiteral("\n")).toStdString() +
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
                                     PlanOptions options, std::string& error) {
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
                                 PlanOptions options, std::string& error, FillMode fill,
                                 const HatchSettings& hatch, std::size_t maxPoints, bool solidDashes,
                                 const std::string& textFont) {
  if (isProjectPath(path)) return loadProject(path, profile, error, maxPoints);
  if (!profile) {
    error = trSource(QT_TRANSLATE_NOOP("JobPipeline", "no machine profile given")).toStdString();
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

}  // namespace fivebar::widgets
