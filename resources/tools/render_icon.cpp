// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar-render-icon SVG PNG SIZE: renders the SVG icon into a SIZE x SIZE PNG with a
// transparent background (the hicolor PNG sizes of the installed icon). Build tool only.
#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <QSvgRenderer>
#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: fivebar-render-icon SVG PNG SIZE\n");
    return 2;
  }
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QGuiApplication app(argc, argv);
  bool ok = false;
  const int size = QString::fromLocal8Bit(argv[3]).toInt(&ok);
  if (!ok || size < 8 || size > 1024) {
    std::fprintf(stderr, "fivebar-render-icon: SIZE must be 8..1024, got '%s'\n", argv[3]);
    return 2;
  }
  QSvgRenderer svg(QString::fromLocal8Bit(argv[1]));
  if (!svg.isValid()) {
    std::fprintf(stderr, "fivebar-render-icon: %s: not a valid SVG\n", argv[1]);
    return 1;
  }
  QImage image(size, size, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::transparent);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  svg.render(&painter, QRectF(0, 0, size, size));
  painter.end();
  if (!image.save(QString::fromLocal8Bit(argv[2]), "PNG")) {
    std::fprintf(stderr, "fivebar-render-icon: cannot write %s\n", argv[2]);
    return 1;
  }
  return 0;
}
