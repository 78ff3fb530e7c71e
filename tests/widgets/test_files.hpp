// SPDX-License-Identifier: GPL-3.0-or-later
// A file written for a test in its temporary directory (a drawing, a profile).
#pragma once

#include <QFile>
#include <QTemporaryDir>
#include <QString>

namespace fivebar::test {

// Writes `text` to `name` in `dir` and returns the path (empty when it could not be written).
inline QString writeTestFile(const QTemporaryDir& dir, const QString& name, const char* text) {
  const QString path = dir.filePath(name);
  QFile f(path);
  if (!f.open(QIODevice::WriteOnly) || f.write(text) < 0) return {};
  return path;
}

}  // namespace fivebar::test
