// The worker's output on stdout: an ImportResult in a compact little-endian binary form.
//   magic "FBSVG1\n", u32 status, str message, u32 n + n str warnings,
//   f64 widthMm, f64 heightMm, str source, u32 layers, per layer:
//     str id, str name, u32 rgb, u8 visible, u32 paths, per path: u8 closed, u32 n, n x (f64 x, f64 y)
//   str = u32 byte length + UTF-8 bytes. Trailer "END\n".
#pragma once

#include <QByteArray>
#include <QStringList>

#include <cstdio>

#include "svg_import.hpp"

namespace fivebar::svg {

QByteArray encodeResult(const ImportResult& result);

// The same bytes, written to a file in chunks of about 1 MB (the worker's stdout).
void writeResult(const ImportResult& result, std::FILE* file);

// False when the bytes are truncated or not in this format.
bool decodeResult(const QByteArray& bytes, ImportResult& result);

// The worker's command line: the options that affect the drawing, then "--" and the file.
QStringList workerArguments(const QString& path, const ImportOptions& options);

// Inverse of workerArguments; returns an error text (empty when fine).
QString parseWorkerArguments(const QStringList& arguments, QString& path, ImportOptions& options);

// Progress lines the worker writes on stderr: "progress <fraction>\n".
inline constexpr char kProgressPrefix[] = "progress ";

}  // namespace fivebar::svg
