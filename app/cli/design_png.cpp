// SPDX-License-Identifier: GPL-3.0-or-later
#include "design_png.hpp"

#include <QGuiApplication>
#include <clocale>
#include <memory>

#include "paint/design_painter.hpp"

namespace fivebar::cli {

std::string writeDesignPng(const std::string& path, const design::Design& d,
                           const design::DesignBrief& brief) {
  // Text needs fonts, and fonts need a QGuiApplication: make one (offscreen) if there is none.
  std::unique_ptr<QGuiApplication> app;
  if (!QCoreApplication::instance()) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    static int argc = 1;
    static char name[] = "fivebar";
    static char* argv[] = {name, nullptr};
    app = std::make_unique<QGuiApplication>(argc, argv);
    std::setlocale(LC_NUMERIC, "C");  // Qt took the environment's; CLI output keeps the point
  }
  const paint::DesignMaps maps = paint::computeDesignMaps(d, brief.rules);
  const QString title = QStringLiteral("Design for a %1 x %2 mm rectangle")
                            .arg(brief.widthMm, 0, 'f', 0)
                            .arg(brief.heightMm, 0, 'f', 0);
  const QImage image = paint::designAtlas(d, maps, title);
  if (!image.save(QString::fromStdString(path), "PNG")) return "cannot write PNG " + path;
  return {};
}

}  // namespace fivebar::cli
