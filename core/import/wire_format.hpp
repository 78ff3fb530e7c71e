// SPDX-License-Identifier: GPL-3.0-or-later
// Binary forms between fivebar-svg-worker and importSvgFile (little-endian).
// An ImportResult (tools and tests):
//   magic "FBSVG3\n", u32 status, msg message, u32 n + n msg warnings,
//   f64 widthMm, f64 heightMm, str source, u32 layers, per layer:
//     str id, str name, u32 rgb, u8 visible, u32 paths, per path: u8 closed, u32 n, n x (f64 x, f64 y)
//   str = u32 byte length + UTF-8 bytes; msg = str context, str template, u32 n args, per arg
//   u8 kind (0: str; 1: f64 value, i32 decimals; 2: msg) (core/support/message.hpp).
//   Trailer "END\n".
#pragma once

#include <QByteArray>
#include <QStringList>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "import_pipeline.hpp"
#include "svg_import.hpp"

namespace fivebar::svg {

QByteArray encodeResult(const ImportResult& result);

// Where decodeResult takes its bytes from.
class ByteSource {
 public:
  virtual ~ByteSource() = default;
  // Copies exactly n bytes to dst; false when the data ends first or cannot be read.
  virtual bool read(void* dst, std::size_t n) = 0;
};

// False when the bytes are truncated or not in this format. Memory grows only with the bytes
// actually received (a bogus count cannot allocate ahead of the data).
bool decodeResult(ByteSource& source, ImportResult& result);
bool decodeResult(const QByteArray& bytes, ImportResult& result);

// The worker's stream (what importSvgFile reads; ImportResult above is for tools and tests):
//   magic "FBSVG4\n", then records, each starting with one byte:
//   'C' runs: u32 n, per run: i32 topIndex, u32 rgb, u32 paths, per path as above
//   'R' restart: forget the runs received so far (the direct reader declined late)
//   'F' final: u32 status, msg message, u32 n + n msg warnings, u32 n + n str Qt messages,
//       u8 sizeKnown, f64 widthMm, f64 heightMm, u32 n + per top-level element:
//       str tag, str id, str label, u8 inkscapeLayer; then "END\n".
// The caller turns it into the ImportResult with finishImport (import_pipeline.hpp), then
// appends the Qt messages to the warnings when the result is Ok.
class CaptureStreamWriter {
 public:
  explicit CaptureStreamWriter(int fd);  // writes in chunks of about 1 MB
  ~CaptureStreamWriter();
  void runs(const std::vector<CapturedRun>& runs);
  void restart();
  // The remaining runs, the final record and the trailer; false on a write error.
  bool finish(const Capture& capture, const std::vector<std::string>& qtMessages);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

struct StreamedCapture {
  Capture capture;
  std::vector<std::string> qtMessages;
};

bool decodeCaptureStream(ByteSource& source, StreamedCapture& out);

// The worker's command line: the options that affect the drawing, then "--" and the file.
QStringList workerArguments(const QString& path, const ImportOptions& options);

// The option that sends the result to an inherited descriptor instead of stdout.
inline constexpr char kResultFdOption[] = "--result-fd";

// Inverse of workerArguments (which may be preceded by kResultFdOption N, stored in *resultFd
// when given); returns an error text (empty when fine).
QString parseWorkerArguments(const QStringList& arguments, QString& path, ImportOptions& options,
                             int* resultFd = nullptr);

// Progress lines the worker writes on stderr: "progress <fraction>\n".
inline constexpr char kProgressPrefix[] = "progress ";

}  // namespace fivebar::svg
