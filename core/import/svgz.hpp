// SPDX-License-Identifier: GPL-3.0-or-later
// .svgz: gzip-compressed SVG (what Inkscape saves as "Compressed Inkscape SVG"). Decompressed
// in memory with zlib, bounded so that a small file cannot expand into gigabytes.
#pragma once

#include <QByteArray>

#include <cstdint>
#include <string>

namespace fivebar::svg {

inline constexpr qint64 kMaxDecompressedBytes = qint64{512} << 20;  // 512 MiB

// True when the data starts with the gzip magic bytes (1f 8b).
bool isGzip(const QByteArray& data);

// The size the gzip trailer announces (ISIZE, modulo 4 GiB); 0 when not gzip. A hint only
// (for the worker's time limit), never trusted for allocation.
std::uint32_t gzipAnnouncedSize(const QByteArray& tail);

// Decompresses every gzip member of `in` into `out`; returns an error text (empty when fine):
// corrupt data, or more than maxBytes after decompression.
std::string gunzip(const QByteArray& in, qint64 maxBytes, QByteArray& out);

}  // namespace fivebar::svg
