// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar-svg-worker: imports one SVG in its own process so that a crash or hang of Qt SVG on a
// hostile file cannot take the caller down (svg_import.hpp, importSvgFile).
// Usage: fivebar-svg-worker [--result-fd N] [options] -- FILE   (options: wire_format.cpp)
// The capture stream (wire_format.hpp) goes to descriptor N (importSvgFile passes a pipe of its
// own) or to stdout; stderr carries "progress <fraction>" lines.
// Exit code 0 whenever a result was written (whatever its status), 2 for a bad command line,
// 3 when the result could not be written.
#include <QGuiApplication>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "import_pipeline.hpp"
#include "svg_import.hpp"
#include "wire_format.hpp"

namespace {

std::vector<std::string>& qtMessages() {
  static std::vector<std::string> messages;
  return messages;
}

// Keeps Qt's own diagnostics out of stderr (which carries progress) and reports the distinct
// ones as import warnings.
void collectMessage(QtMsgType, const QMessageLogContext& context, const QString& text) {
  constexpr std::size_t kMaxMessages = 20;
  if (text.startsWith(u"QStandardPaths")) return;  // environment noise, not about the file
  auto& messages = qtMessages();
  const std::string category = context.category ? context.category : "qt";
  std::string line = "Qt (" + category + "): " + text.toStdString();
  for (const std::string& m : messages)
    if (m == line) return;
  if (messages.size() < kMaxMessages) messages.push_back(std::move(line));
}

}  // namespace

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  qInstallMessageHandler(collectMessage);
  QGuiApplication app(argc, argv);
  QString path;
  fivebar::svg::ImportOptions options;
  int resultFd = 1;
  const QString error =
      fivebar::svg::parseWorkerArguments(app.arguments().mid(1), path, options, &resultFd);
  if (!error.isEmpty()) {
    std::fprintf(stderr, "fivebar-svg-worker: %s\n", qPrintable(error));
    return 2;
  }
  options.isolation = fivebar::svg::Isolation::InProcess;
  int lastPercent = -1;
  auto progress = [&](double fraction) {
    const int percent = static_cast<int>(fraction * 100.0);
    if (percent == lastPercent) return;
    lastPercent = percent;
    std::fprintf(stderr, "%s%.2f\n", fivebar::svg::kProgressPrefix, fraction);
    std::fflush(stderr);
  };
  // Runs go out while the capture goes on; the caller builds the Drawing meanwhile.
  fivebar::svg::CaptureStreamWriter stream(resultFd);
  fivebar::svg::RunSink sink;
  sink.take = [&](std::vector<fivebar::svg::CapturedRun>& runs) { stream.runs(runs); };
  sink.restart = [&] { stream.restart(); };
  fivebar::svg::Capture capture = fivebar::svg::captureSvgFile(path, options, progress, sink);
  std::vector<std::string> qtWarnings;
  if (capture.status == fivebar::svg::ImportStatus::Ok) qtWarnings = qtMessages();
  else if (capture.status == fivebar::svg::ImportStatus::RenderFailed && !qtMessages().empty())
    capture.message = FB_TR("ImportError", "%1 (%2)").arg(std::move(capture.message)).arg(qtMessages().front());
  if (!stream.finish(capture, qtWarnings)) {
    std::fprintf(stderr, "fivebar-svg-worker: cannot write the result: %s\n", std::strerror(errno));
    return 3;
  }
  return 0;
}
