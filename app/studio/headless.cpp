// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/studio/headless.hpp"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QSaveFile>
#include <clocale>
#include <cstdio>
#include <cstring>

#include "app/studio/startup.hpp"
#include "core/output/gcode.hpp"
#include "widgets/document/job_pipeline.hpp"
#include "job/job_source.hpp"

namespace fivebar::studio {
namespace {

int fail(const std::string& text, int code = 1) {
  std::fprintf(stderr, "fivebar-studio: %s\n", text.c_str());
  return code;
}

}  // namespace

bool wantsHeadlessExport(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--export-gcode") == 0) return true;
  return false;
}

int runHeadlessExport(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  std::setlocale(LC_NUMERIC, "C");  // Qt took the environment's; files keep the decimal point
  QCoreApplication::setOrganizationName(QStringLiteral("FiveBar"));
  QCoreApplication::setApplicationName(QStringLiteral("FiveBar Studio"));
  QCommandLineParser parser;
  const QCommandLineOption machine(QStringLiteral("machine"), QString(), QStringLiteral("PRESET|FILE"));
  const QCommandLineOption exportGcode(QStringLiteral("export-gcode"), QString(), QStringLiteral("OUT.gcode"));
  parser.addOptions({machine, exportGcode});
  if (!parser.parse(QCoreApplication::arguments()))
    return fail(parser.errorText().toStdString(), 2);
  if (parser.positionalArguments().size() != 1)
    return fail("--export-gcode needs exactly one DRAWING.svg or PROJECT.fivebar", 2);
  const QString input = parser.positionalArguments().front();
  const QString output = parser.value(exportGcode);

  // The machine as the window would have it: --machine, else a project's own, else the
  // remembered profile, else the default preset.
  std::optional<MachineProfile> profile;
  std::string error;
  if (parser.isSet(machine) || !job::isProjectPath(input)) {
    profile = startupProfile(parser.isSet(machine) ? std::optional<QString>(parser.value(machine))
                                                   : std::nullopt, error);
    if (!profile) return fail(error, 2);
  }
  PlanOptions defaults;  // the document's defaults: Auto mode, 0.1 mm
  job::JobError jobError;
  auto loaded = job::loadJob(input, profile, defaults, jobError);
  if (!loaded) return fail(jobError.text);
  if (!loaded->note.empty()) std::fprintf(stderr, "fivebar-studio: %s: %s\n", qPrintable(input), loaded->note.text().c_str());
  if (!loaded->options.atMm) return fail(input.toStdString() + ": nothing to place (no visible path or no singularity-free area)");
  const Placement placement{*loaded->options.atMm, loaded->options.rotationRad, loaded->options.scale,
                            loaded->options.stretchY};
  const PlanOptions options =
      widgets::studioPlanOptions(placement, loaded->options.mode, loaded->options.toleranceMm);
  PlanResult r = job::planRefining(loaded->drawing, loaded->source, loaded->profile, options, jobError);
  if (!r.ok()) {
    std::fprintf(stderr, "fivebar-studio: %s: %s\n", qPrintable(input),
                 (jobError.empty() ? r.message.text() : jobError.text).c_str());
    for (std::size_t i = 0; i < r.report.problems.size() && i < 10; ++i)
      std::fprintf(stderr, "  %s: %s\n", r.report.problems[i].path.text().c_str(),
                   r.report.problems[i].why.text().c_str());
    return 1;
  }
  QSaveFile file(output);
  if (!file.open(QIODevice::WriteOnly)) return fail(output.toStdString() + ": " + file.errorString().toStdString());
  bool ok = true;
  writeGcode(r.job, loaded->profile, [&](std::string_view piece) {
    ok = ok && file.write(piece.data(), static_cast<qint64>(piece.size())) == static_cast<qint64>(piece.size());
  });
  if (!ok || !file.commit()) return fail(output.toStdString() + ": cannot write (" + file.errorString().toStdString() + ")");
  std::printf("%s: mode %s, %d segments, estimated %ld s, scale %.1f %%\n", qPrintable(output),
              std::string(toString(r.report.mode)).c_str(), r.report.segments,
              std::lround(r.report.estimatedTimeS), placement.scale * 100.0);
  return 0;
}

}  // namespace fivebar::studio
