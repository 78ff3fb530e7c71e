// SPDX-License-Identifier: GPL-3.0-or-later
#include "svgz.hpp"

#include <zlib.h>

#include <algorithm>

namespace fivebar::svg {

bool isGzip(const QByteArray& data) {
  return data.size() >= 2 && static_cast<unsigned char>(data[0]) == 0x1f &&
         static_cast<unsigned char>(data[1]) == 0x8b;
}

std::uint32_t gzipAnnouncedSize(const QByteArray& tail) {
  if (tail.size() < 4) return 0;
  const auto* p = reinterpret_cast<const unsigned char*>(tail.constData() + tail.size() - 4);
  return std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 |
         std::uint32_t{p[3]} << 24;
}

std::string gunzip(const QByteArray& in, qint64 maxBytes, QByteArray& out) {
  out.clear();
  z_stream z{};
  if (inflateInit2(&z, 16 + MAX_WBITS) != Z_OK) return "zlib could not start";
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.constData()));
  z.avail_in = static_cast<uInt>(in.size());
  constexpr qsizetype kChunk = qsizetype{1} << 20;
  std::string error;
  for (;;) {
    if (out.size() >= maxBytes) {
      error = "more than " + std::to_string(maxBytes >> 20) + " MiB after decompression";
      break;
    }
    const qsizetype before = out.size();
    const qsizetype chunk = std::min<qsizetype>(kChunk, maxBytes - before);
    out.resize(before + chunk);
    z.next_out = reinterpret_cast<Bytef*>(out.data() + before);
    z.avail_out = static_cast<uInt>(chunk);
    const int rc = inflate(&z, Z_NO_FLUSH);
    out.resize(before + chunk - static_cast<qsizetype>(z.avail_out));
    if (rc == Z_STREAM_END) {
      if (z.avail_in == 0) break;
      // Another gzip member follows (concatenated files): continue with it.
      if (inflateReset(&z) != Z_OK) {
        error = "corrupt gzip data";
        break;
      }
      continue;
    }
    if (rc == Z_BUF_ERROR && z.avail_in == 0) {
      error = "the gzip data ends early (truncated file)";
      break;
    }
    if (rc != Z_OK && rc != Z_BUF_ERROR) {
      error = std::string("corrupt gzip data (") + (z.msg ? z.msg : "zlib error") + ")";
      break;
    }
  }
  inflateEnd(&z);
  if (!error.empty()) out.clear();
  return error;
}

}  // namespace fivebar::svg
