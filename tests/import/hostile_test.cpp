// SPDX-License-Identifier: GPL-3.0-or-later
// Process isolation: importSvgFile through the real worker and through fake workers that crash,
// hang or print garbage. None of these may take the test process down.
#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <algorithm>
#include <atomic>
#include <chrono>

#include "import_support.hpp"

namespace fivebar::svg {
namespace {

QString writeFile(const QTemporaryDir& dir, const QString& name, const QByteArray& text,
                  bool executable = false) {
  const QString path = dir.filePath(name);
  QFile f(path);
  EXPECT_TRUE(f.open(QIODevice::WriteOnly));
  f.write(text);
  f.close();
  if (executable) f.setPermissions(f.permissions() | QFileDevice::ExeOwner);
  return path;
}

class Isolation : public ::testing::Test {
 protected:
  QTemporaryDir dir;
  QString svgFile() {
    return writeFile(dir, QStringLiteral("ok.svg"),
                     QByteArray::fromStdString(test::page("<path d=\"M1 1 L9 9\" stroke=\"black\"/>")));
  }
  ImportOptions withFakeWorker(const char* script) {
    ImportOptions o;
    o.workerPath = writeFile(dir, QStringLiteral("fake-worker"),
                             QByteArray("#!/bin/sh\n") + script + "\n", true);
    return o;
  }
};

TEST_F(Isolation, RealWorkerGivesTheSameDrawingAsInProcess) {
  ASSERT_FALSE(findSvgWorker().isEmpty()) << "fivebar-svg-worker not built";
  const QString file = svgFile();
  std::vector<double> progress;
  const ImportResult viaWorker = importSvgFile(file, {}, [&](double f) { progress.push_back(f); });
  ASSERT_TRUE(viaWorker.ok()) << viaWorker.message;
  const ImportResult direct = importSvgInProcess(file);
  ASSERT_TRUE(direct.ok()) << direct.message;
  ASSERT_EQ(test::allPaths(viaWorker.drawing).size(), 1u);
  EXPECT_EQ(test::allPaths(viaWorker.drawing)[0].points, test::allPaths(direct.drawing)[0].points);
  EXPECT_EQ(viaWorker.drawing.widthMm, direct.drawing.widthMm);
  ASSERT_FALSE(progress.empty());
  EXPECT_DOUBLE_EQ(progress.back(), 1.0);
}

TEST_F(Isolation, ImageThatLoadsItselfIsStrippedNotFatal) {
  const QString file = writeFile(dir, QStringLiteral("self.svg"),
      "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
      "width=\"20mm\" height=\"20mm\" viewBox=\"0 0 20 20\"><image xlink:href=\"self.svg\" "
      "width=\"20\" height=\"20\"/><path d=\"M1 1 L5 5\" stroke=\"black\"/></svg>");
  const ImportResult r = importSvgFile(file);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(test::pathCount(r.drawing), 1u);
  bool warned = false;
  for (const fivebar::Message& w : r.warnings) warned = warned || w.text().find("<image>") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST_F(Isolation, CrashingWorkerEndsInAClearErrorNamingTheFile) {
  const QString file = svgFile();
  const ImportResult r = importSvgFile(file, withFakeWorker("kill -SEGV $$"));
  EXPECT_EQ(r.status, ImportStatus::WorkerCrashed);
  EXPECT_NE(r.message.text().find(file.toStdString()), std::string::npos) << r.message;
  EXPECT_NE(r.message.text().find("crashed"), std::string::npos) << r.message;
}

TEST_F(Isolation, HangingWorkerIsStoppedAtTheTimeout) {
  ImportOptions o = withFakeWorker("exec sleep 30");
  o.timeoutS = 0.5;
  o.timeoutPerMegabyteS = 0.0;
  const auto start = std::chrono::steady_clock::now();
  const ImportResult r = importSvgFile(svgFile(), o);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.status, ImportStatus::WorkerTimeout);
  EXPECT_NE(r.message.text().find("did not finish within 0.5 s"), std::string::npos) << r.message;
  EXPECT_LT(elapsed, 5.0);
}

TEST_F(Isolation, CancelFromTheProgressCallbackStopsTheWorker) {
  ImportOptions o = withFakeWorker("while true; do echo 'progress 0.25' >&2; sleep 0.05; done");
  std::atomic<bool> cancel{false};
  o.cancel = &cancel;
  double last = -1.0;
  const auto start = std::chrono::steady_clock::now();
  const ImportResult r = importSvgFile(svgFile(), o, [&](double f) {
    last = f;
    cancel = true;
  });
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.status, ImportStatus::Cancelled);
  EXPECT_DOUBLE_EQ(last, 0.25);
  EXPECT_LT(elapsed, 5.0);
}

// About 2 MB of plotter paths: long enough for several progress reports.
QByteArray bigDocument() {
  QByteArray body;
  for (int i = 0; body.size() < (2 << 20); ++i) {
    const QByteArray a = QByteArray::number(i % 190), b = QByteArray::number((i * 7) % 190);
    body += "<path d=\"M" + a + " " + b + " L" + b + " " + a + " C10 10 " + a + " 5 " + b + " 20\"/>\n";
  }
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200mm\" height=\"200mm\" "
         "viewBox=\"0 0 200 200\"><g stroke=\"black\" fill=\"none\">" + body + "</g></svg>";
}

TEST_F(Isolation, BigFileReportsRisingProgressAndCanBeCancelledMidway) {
  const QString file = writeFile(dir, QStringLiteral("big.svg"), bigDocument());
  std::vector<double> seen;
  const ImportResult r = importSvgFile(file, {}, [&](double f) { seen.push_back(f); });
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_GE(seen.size(), 10u);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_DOUBLE_EQ(seen.back(), 1.0);
  std::atomic<bool> cancel{false};
  ImportOptions o;
  o.cancel = &cancel;
  double cancelledAt = -1.0;
  const ImportResult c = importSvgFile(file, o, [&](double f) {
    if (f >= 0.1 && !cancel) {
      cancelledAt = f;
      cancel = true;
    }
  });
  EXPECT_EQ(c.status, ImportStatus::Cancelled);
  EXPECT_GE(cancelledAt, 0.1);
  EXPECT_LT(cancelledAt, 1.0);
}

TEST_F(Isolation, GarbageOutputAndMissingPiecesAreReported) {
  const ImportResult garbage = importSvgFile(svgFile(), withFakeWorker("echo hello; echo oops >&2"));
  EXPECT_EQ(garbage.status, ImportStatus::WorkerCrashed);
  EXPECT_NE(garbage.message.text().find("without a readable result"), std::string::npos) << garbage.message;
  EXPECT_NE(garbage.message.text().find("oops"), std::string::npos) << garbage.message;
  ImportOptions nowhere;
  nowhere.workerPath = dir.filePath(QStringLiteral("no-such-worker"));
  const ImportResult missing = importSvgFile(svgFile(), nowhere);
  EXPECT_EQ(missing.status, ImportStatus::WorkerNotFound);
  EXPECT_NE(missing.message.text().find("FIVEBAR_SVG_WORKER"), std::string::npos) << missing.message;
  const ImportResult noFile = importSvgFile(dir.filePath(QStringLiteral("absent.svg")));
  EXPECT_EQ(noFile.status, ImportStatus::FileError);
  EXPECT_NE(noFile.message.text().find("absent.svg: no such file"), std::string::npos) << noFile.message;
}

}  // namespace
}  // namespace fivebar::svg
