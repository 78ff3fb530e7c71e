// importSvgFile: runs fivebar-svg-worker under a time and memory limit and maps every way it can
// end (result, crash, timeout, cancel, garbage output) to an ImportResult naming the file.
#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QDir>
#include <QFileInfo>
#include <QProcess>

#include <sys/resource.h>

#include <string>

#include "svg_import.hpp"
#include "wire_format.hpp"

namespace fivebar::svg {
namespace {

const char kWorkerName[] = "fivebar-svg-worker";

ImportResult failure(ImportStatus status, const QString& path, const std::string& message) {
  ImportResult r;
  r.status = status;
  r.message = path.toStdString() + ": " + message;
  return r;
}

bool isExecutable(const QString& file) {
  const QFileInfo info(file);
  return info.isFile() && info.isExecutable();
}

QString runningExecutableDir() {
  if (QCoreApplication::instance()) return QCoreApplication::applicationDirPath();
  return QFileInfo(QFile::symLinkTarget(QStringLiteral("/proc/self/exe"))).absolutePath();
}

// Reads stderr: "progress 0.42" lines are reported, any other line is kept as a diagnostic.
void readErrorChannel(QProcess& process, QByteArray& pending, QByteArray& diagnostics,
                      const ProgressFn& progress) {
  pending += process.readAllStandardError();
  qsizetype newline;
  while ((newline = pending.indexOf('\n')) >= 0) {
    const QByteArray line = pending.left(newline);
    pending.remove(0, newline + 1);
    if (!line.startsWith(kProgressPrefix)) {
      if (diagnostics.size() < 4096) diagnostics += line + ' ';
      continue;
    }
    bool ok = false;
    const double f = line.mid(static_cast<qsizetype>(sizeof kProgressPrefix) - 1).toDouble(&ok);
    if (ok && progress) progress(f);
  }
}

std::string seconds(double s) { return QString::number(s, 'f', 1).toStdString() + " s"; }

}  // namespace

QString findSvgWorker(const ImportOptions& options) {
  QStringList candidates;
  if (!options.workerPath.isEmpty()) return isExecutable(options.workerPath) ? options.workerPath : QString();
  if (const QString env = qEnvironmentVariable("FIVEBAR_SVG_WORKER"); !env.isEmpty())
    candidates << env;
  candidates << QDir(runningExecutableDir()).filePath(QString::fromLatin1(kWorkerName));
#ifdef FIVEBAR_SVG_WORKER_BUILD_PATH
  candidates << QStringLiteral(FIVEBAR_SVG_WORKER_BUILD_PATH);
#endif
  for (const QString& c : candidates)
    if (isExecutable(c)) return c;
  return {};
}

namespace {

// Configures the child: offscreen Qt, no core dumps, the address-space limit.
void prepareWorker(QProcess& process, const QString& worker, const QString& path,
                   const ImportOptions& options) {
  process.setProgram(worker);
  process.setArguments(workerArguments(path, options));  // same working directory
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
  process.setProcessEnvironment(env);
  const rlim_t memory = static_cast<rlim_t>(options.memoryLimitBytes);
  process.setChildProcessModifier([memory] {
    const rlimit noCore{0, 0};
    setrlimit(RLIMIT_CORE, &noCore);
    if (memory > 0) {
      const rlimit as{memory, memory};
      setrlimit(RLIMIT_AS, &as);
    }
  });
}

// Maps how the finished worker ended to a result.
ImportResult collectResult(QProcess& process, const QByteArray& output, const QByteArray& diagnostics,
                           const QString& path, const ImportOptions& options) {
  if (process.exitStatus() == QProcess::CrashExit)
    return failure(ImportStatus::WorkerCrashed, path,
                   "the SVG parser crashed on this file (it is hostile or corrupt, or needed more "
                   "than the " + std::to_string(options.memoryLimitBytes >> 20) + " MB memory limit)");
  ImportResult result;
  if (process.exitCode() != 0 || !decodeResult(output, result))
    return failure(ImportStatus::WorkerCrashed, path,
                   "the SVG worker ended without a readable result (exit code " +
                       std::to_string(process.exitCode()) + "): " + diagnostics.trimmed().toStdString());
  return result;
}

}  // namespace

ImportResult importSvgFile(const QString& path, const ImportOptions& options,
                           const ProgressFn& progress) {
  if (options.isolation == Isolation::InProcess) return importSvgInProcess(path, options, progress);
  const QFileInfo info(path);
  if (!info.isFile()) return failure(ImportStatus::FileError, path, "no such file");
  if (!info.isReadable()) return failure(ImportStatus::FileError, path, "not readable");
  const QString worker = findSvgWorker(options);
  if (worker.isEmpty())
    return failure(ImportStatus::WorkerNotFound, path,
                   "the SVG worker (fivebar-svg-worker) was not found; set ImportOptions::workerPath "
                   "or FIVEBAR_SVG_WORKER, or install it next to the program");
  QProcess process;
  prepareWorker(process, worker, path, options);
  process.start(QIODevice::ReadOnly);
  if (!process.waitForStarted(10000))
    return failure(ImportStatus::WorkerNotFound, path,
                   "could not start the SVG worker " + worker.toStdString() + ": " +
                       process.errorString().toStdString());

  const double megabytes = static_cast<double>(info.size()) / (1024.0 * 1024.0);
  const double limitS = options.timeoutS + options.timeoutPerMegabyteS * megabytes;
  QDeadlineTimer deadline(static_cast<qint64>(limitS * 1000.0));
  QByteArray output, pendingErrors, diagnostics;
  while (process.state() != QProcess::NotRunning) {
    process.waitForFinished(50);
    output += process.readAllStandardOutput();
    readErrorChannel(process, pendingErrors, diagnostics, progress);
    const bool cancel = options.cancel && options.cancel->load();
    if (cancel || deadline.hasExpired()) {
      process.kill();
      process.waitForFinished(5000);
      if (cancel) return failure(ImportStatus::Cancelled, path, "import cancelled");
      return failure(ImportStatus::WorkerTimeout, path,
                     "the SVG parser did not finish within " + seconds(limitS) +
                         " and was stopped (the file is too complex or makes Qt SVG hang)");
    }
  }
  output += process.readAllStandardOutput();
  readErrorChannel(process, pendingErrors, diagnostics, progress);
  return collectResult(process, output, diagnostics + pendingErrors, path, options);
}

}  // namespace fivebar::svg
