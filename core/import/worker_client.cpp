// SPDX-License-Identifier: GPL-3.0-or-later
// importSvgFile: runs fivebar-svg-worker under a time and memory limit and maps every way it can
// end (result, crash, timeout, cancel, garbage output) to an ImportResult naming the file. The
// result comes back on a pipe of its own and is decoded while the worker still writes it.
#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include "import_pipeline.hpp"
#include "svg_import.hpp"
#include "svgz.hpp"
#include "wire_format.hpp"

namespace fivebar::svg {
namespace {

// A .svgz file: the size its gzip trailer announces (bounded), so that the time limit follows
// the document's real size; 0 for other files.
qint64 svgzAnnouncedSize(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly) || !isGzip(file.read(2))) return 0;
  file.seek(std::max<qint64>(0, file.size() - 4));
  return std::min<qint64>(gzipAnnouncedSize(file.read(4)), kMaxDecompressedBytes);
}

const char kWorkerName[] = "fivebar-svg-worker";
constexpr int kPipeBytes = 1 << 20;  // result pipe capacity asked for (Linux default max)

ImportResult failure(ImportStatus status, const QString& path, Message message) {
  ImportResult r;
  r.status = status;
  r.message = FB_TR("ImportError", "%1: %2").arg(path.toStdString()).arg(std::move(message));
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


}  // namespace

QString findSvgWorker(const ImportOptions& options) {
  QStringList candidates;
  if (!options.workerPath.isEmpty()) return isExecutable(options.workerPath) ? options.workerPath : QString();
  if (const QString env = qEnvironmentVariable("FIVEBAR_SVG_WORKER"); !env.isEmpty())
    candidates << env;
  const QDir exeDir(runningExecutableDir());
  candidates << exeDir.filePath(QString::fromLatin1(kWorkerName));
  // Installed (the Debian package, cmake --install): a helper, not a command, so not in bin/.
  candidates << exeDir.filePath(QStringLiteral("../libexec/fivebar-studio/") +
                                QString::fromLatin1(kWorkerName));
#ifdef FIVEBAR_SVG_WORKER_BUILD_PATH
  candidates << QStringLiteral(FIVEBAR_SVG_WORKER_BUILD_PATH);
#endif
  for (const QString& c : candidates)
    if (isExecutable(c)) return c;
  return {};
}

namespace {

// The parent's end of the result pipe: reads in big blocks and, while waiting for the worker,
// reports its progress and watches the cancel flag and the deadline.
class ResultPipe final : public ByteSource {
 public:
  enum class Stop { None, EndOfData, Cancelled, Timeout };

  ResultPipe(int fd, QProcess& process, const ImportOptions& options, const QDeadlineTimer& deadline,
             const ProgressFn& progress)
      : fd_(fd), process_(process), options_(options), deadline_(deadline), progress_(progress),
        buffer_(std::size_t{1} << 20) {}
  ~ResultPipe() override { ::close(fd_); }

  bool read(void* dst, std::size_t n) override {
    auto* out = static_cast<char*>(dst);
    while (n > 0) {
      if (pos_ == end_ && !refill()) return false;
      const std::size_t k = std::min(n, end_ - pos_);
      std::memcpy(out, buffer_.data() + pos_, k);
      pos_ += k;
      out += k;
      n -= k;
    }
    return true;
  }

  // Discards the rest of the output until the worker has ended; false on cancel or timeout.
  bool waitForEnd() {
    while (process_.state() != QProcess::NotRunning) {
      while (stop_ == Stop::None && readSome() > 0) {}
      process_.waitForFinished(20);
      if (!pump()) return false;
    }
    readErrorChannel(process_, pendingErrors_, diagnostics_, progress_);
    return !cancelled() || (stop_ = Stop::Cancelled, false);
  }

  Stop stop() const { return stop_; }
  QByteArray diagnostics() const { return diagnostics_ + pendingErrors_; }

 private:
  bool cancelled() const { return options_.cancel && options_.cancel->load(); }

  // One non-blocking read into the buffer: > 0 bytes read, 0 nothing yet, < 0 end of data.
  ssize_t readSome() {
    for (;;) {
      const ssize_t n = ::read(fd_, buffer_.data(), buffer_.size());
      if (n > 0) {
        pos_ = 0;
        end_ = static_cast<std::size_t>(n);
        return n;
      }
      if (n < 0 && errno == EINTR) continue;
      if (n < 0 && errno == EAGAIN) return 0;
      stop_ = Stop::EndOfData;
      return -1;
    }
  }

  bool refill() {
    if (stop_ != Stop::None) return false;
    if ((++refills_ & 63) == 0 && !pump()) return false;
    for (;;) {
      const ssize_t n = readSome();
      if (n > 0) return true;
      if (n < 0) return false;
      pollfd p{fd_, POLLIN, 0};
      ::poll(&p, 1, kPollMs);
      if (!pump()) return false;
    }
  }

  // Progress lines, cancel and deadline; false when the import must stop.
  bool pump() {
    process_.waitForReadyRead(0);  // reads the worker's stderr, notices its end
    readErrorChannel(process_, pendingErrors_, diagnostics_, progress_);
    if (cancelled()) stop_ = Stop::Cancelled;
    else if (deadline_.hasExpired()) stop_ = Stop::Timeout;
    return stop_ == Stop::None || stop_ == Stop::EndOfData;
  }

  static constexpr int kPollMs = 20;
  int fd_;
  QProcess& process_;
  const ImportOptions& options_;
  const QDeadlineTimer& deadline_;
  const ProgressFn& progress_;
  std::vector<char> buffer_;
  std::size_t pos_ = 0, end_ = 0;
  unsigned refills_ = 0;
  Stop stop_ = Stop::None;
  QByteArray pendingErrors_, diagnostics_;
};

// A pipe whose read end stays here (non-blocking) and whose write end the worker inherits.
// Both descriptors are >= 3 and close-on-exec; the child modifier clears the flag on its copy.
bool makeResultPipe(int& readFd, int& writeFd) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return false;
  for (int& fd : fds) {
    if (fd < 3) {
      const int moved = ::fcntl(fd, F_DUPFD_CLOEXEC, 3);
      ::close(fd);
      fd = moved;
    }
  }
  if (fds[0] < 0 || fds[1] < 0) {
    for (int fd : fds) if (fd >= 0) ::close(fd);
    return false;
  }
  ::fcntl(fds[0], F_SETFL, ::fcntl(fds[0], F_GETFL) | O_NONBLOCK);
  ::fcntl(fds[0], F_SETPIPE_SZ, kPipeBytes);  // fewer wake-ups; the default 64 KB also works
  readFd = fds[0];
  writeFd = fds[1];
  return true;
}

// Configures the child: offscreen Qt, no core dumps, the address-space limit, the result pipe,
// and huge pages for its heap (fewer page faults while it fills tens of MB with points).
void prepareWorker(QProcess& process, const QString& worker, const QString& path,
                   const ImportOptions& options, int resultFd) {
  process.setProgram(worker);
  process.setArguments(QStringList{QString::fromLatin1(kResultFdOption), QString::number(resultFd)} +
                       workerArguments(path, options));  // same working directory
  process.setStandardOutputFile(QProcess::nullDevice());
  process.setReadChannel(QProcess::StandardError);
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
  const QString tunables = env.value(QStringLiteral("GLIBC_TUNABLES"));
  env.insert(QStringLiteral("GLIBC_TUNABLES"),
             (tunables.isEmpty() ? QString() : tunables + u':') + QStringLiteral("glibc.malloc.hugetlb=1"));
  process.setProcessEnvironment(env);
  const rlim_t memory = static_cast<rlim_t>(options.memoryLimitBytes);
  process.setChildProcessModifier([memory, resultFd] {
    ::fcntl(resultFd, F_SETFD, 0);  // keep the result pipe across exec
    const rlimit noCore{0, 0};
    setrlimit(RLIMIT_CORE, &noCore);
    if (memory > 0) {
      const rlimit as{memory, memory};
      setrlimit(RLIMIT_AS, &as);
    }
  });
}

}  // namespace

ImportResult importSvgFile(const QString& path, const ImportOptions& options,
                           const ProgressFn& progress) {
  if (options.isolation == Isolation::InProcess) return importSvgInProcess(path, options, progress);
  const QFileInfo info(path);
  if (!info.isFile()) return failure(ImportStatus::FileError, path, FB_TR("ImportError", "no such file"));
  if (!info.isReadable()) return failure(ImportStatus::FileError, path, FB_TR("ImportError", "not readable"));
  const QString worker = findSvgWorker(options);
  if (worker.isEmpty())
    return failure(ImportStatus::WorkerNotFound, path,
                   FB_TR("ImportError", "the SVG worker (fivebar-svg-worker) was not found; set ImportOptions::workerPath "
                                        "or FIVEBAR_SVG_WORKER, or install it next to the program"));
  int readFd = -1, writeFd = -1;
  if (!makeResultPipe(readFd, writeFd))
    return failure(ImportStatus::WorkerNotFound, path,
                   FB_TR("ImportError", "could not create a pipe for the SVG worker: %1").arg(std::strerror(errno)));
  QProcess process;
  prepareWorker(process, worker, path, options, writeFd);
  process.start(QIODevice::ReadOnly);
  const bool started = process.waitForStarted(10000);
  ::close(writeFd);  // the worker holds the only write end: its exit ends the data
  const double megabytes = static_cast<double>(std::max<qint64>(info.size(), svgzAnnouncedSize(path))) /
                          (1024.0 * 1024.0);
  const double limitS = options.timeoutS + options.timeoutPerMegabyteS * megabytes;
  const QDeadlineTimer deadline(static_cast<qint64>(limitS * 1000.0));
  ResultPipe pipe(readFd, process, options, deadline, progress);
  if (!started)
    return failure(ImportStatus::WorkerNotFound, path,
                   FB_TR("ImportError", "could not start the SVG worker %1: %2")
                       .arg(worker.toStdString())
                       .arg(process.errorString().toStdString()));

  StreamedCapture streamed;
  const bool decoded = decodeCaptureStream(pipe, streamed);  // while the worker still writes
  if (!pipe.waitForEnd() || pipe.stop() == ResultPipe::Stop::Cancelled ||
      pipe.stop() == ResultPipe::Stop::Timeout) {
    process.kill();
    process.waitForFinished(5000);
    if (pipe.stop() == ResultPipe::Stop::Cancelled)
      return failure(ImportStatus::Cancelled, path, FB_TR("ImportError", "import cancelled"));
    return failure(ImportStatus::WorkerTimeout, path,
                   FB_TR("ImportError", "the SVG parser did not finish within %1 s and was stopped (the file is too "
                                        "complex or makes Qt SVG hang)")
                       .arg(limitS, 1));
  }
  if (process.exitStatus() == QProcess::CrashExit)
    return failure(ImportStatus::WorkerCrashed, path,
                   FB_TR("ImportError", "the SVG parser crashed on this file (it is hostile or corrupt, or needed more "
                                        "than the %1 MB memory limit)")
                       .arg(static_cast<long long>(options.memoryLimitBytes >> 20)));
  if (process.exitCode() != 0 || !decoded)
    return failure(ImportStatus::WorkerCrashed, path,
                   FB_TR("ImportError", "the SVG worker ended without a readable result (exit code %1): %2")
                       .arg(process.exitCode())
                       .arg(pipe.diagnostics().trimmed().toStdString()));
  ImportResult result = finishImport(std::move(streamed.capture), path, options, progress);
  if (result.ok())
    for (std::string& m : streamed.qtMessages) result.warnings.push_back(std::move(m));
  return result;
}

}  // namespace fivebar::svg
