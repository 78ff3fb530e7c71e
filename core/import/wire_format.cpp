// SPDX-License-Identifier: GPL-3.0-or-later
#include "wire_format.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string_view>

namespace fivebar::svg {
namespace {

constexpr std::string_view kMagic = "FBSVG3\n";
constexpr std::string_view kStreamMagic = "FBSVG4\n";
constexpr std::uint8_t kRunsRecord = 'C';
constexpr std::uint8_t kRestartRecord = 'R';
constexpr std::uint8_t kFinalRecord = 'F';
constexpr std::string_view kTrailer = "END\n";
constexpr std::uint32_t kMaxCount = 1u << 30;
constexpr std::uint32_t kMaxTextBytes = 1u << 24;  // messages, names: far below this

// Appends to a byte buffer; with a descriptor, hands the buffer to it whenever it passes 1 MB.
class Writer {
 public:
  explicit Writer(QByteArray& out, int fd = -1) : out_(out), fd_(fd) {}
  template <typename T>
  void raw(T value) { out_.append(reinterpret_cast<const char*>(&value), sizeof value); }
  void text(const std::string& s) {
    raw(static_cast<std::uint32_t>(s.size()));
    out_.append(s.data(), static_cast<qsizetype>(s.size()));
  }
  void bytes(const void* data, std::size_t n) {
    out_.append(static_cast<const char*>(data), static_cast<qsizetype>(n));
  }
  void bytes(std::string_view s) { bytes(s.data(), s.size()); }
  void maybeFlush(bool force = false) {
    if (fd_ < 0 || (!force && out_.size() < (qsizetype{1} << 20))) return;
    const char* p = out_.constData();
    qsizetype left = out_.size();
    while (left > 0 && ok_) {
      const ssize_t n = ::write(fd_, p, static_cast<std::size_t>(left));
      if (n < 0 && errno == EINTR) continue;
      ok_ = n > 0;
      if (ok_) {
        p += n;
        left -= n;
      }
    }
    out_.clear();
  }
  bool ok() const { return ok_; }

 private:
  QByteArray& out_;
  int fd_;
  bool ok_ = true;
};

void writePolylines(const std::vector<Polyline>& lines, Writer& w) {
  w.raw(static_cast<std::uint32_t>(lines.size()));
  for (const Polyline& line : lines) {
    // Flags: bit 0 closed, bits 1-2 fill rule, bit 3 fill start, bit 4 fill only, bit 5
    // flattened.
    w.raw(static_cast<std::uint8_t>((line.closed ? 1 : 0) | static_cast<int>(line.fill) << 1 |
                                    (line.fillStart ? 8 : 0) | (line.fillOnly ? 16 : 0) |
                                    (line.flattened ? 32 : 0)));
    w.raw(static_cast<std::uint32_t>(line.points.size()));
    static_assert(sizeof(Vec2) == 2 * sizeof(double), "points are sent as x, y doubles");
    w.bytes(line.points.data(), line.points.size() * sizeof(Vec2));
    w.maybeFlush();
  }
}

void writeTexts(const std::vector<std::string>& texts, Writer& w) {
  w.raw(static_cast<std::uint32_t>(texts.size()));
  for (const std::string& t : texts) w.text(t);
}

// A message: str context, str template, u32 n args, per arg u8 kind (0 text: str; 1 number:
// f64 value, i32 decimals; 2 nested: a message).
void writeMessage(const Message& m, Writer& w) {
  w.text(m.context());
  w.text(m.templ());
  w.raw(static_cast<std::uint32_t>(m.args().size()));
  for (const MessageArg& a : m.args()) {
    w.raw(static_cast<std::uint8_t>(a.kind));
    switch (a.kind) {
      case MessageArg::Kind::Text: w.text(a.text); break;
      case MessageArg::Kind::Number:
        w.raw(a.value);
        w.raw(static_cast<std::int32_t>(a.decimals));
        break;
      case MessageArg::Kind::Nested: writeMessage(*a.message, w); break;
    }
  }
}

void writeMessages(const std::vector<Message>& messages, Writer& w) {
  w.raw(static_cast<std::uint32_t>(messages.size()));
  for (const Message& m : messages) writeMessage(m, w);
}

void encode(const ImportResult& result, Writer& w) {
  w.bytes(kMagic);
  w.raw(static_cast<std::uint32_t>(result.status));
  writeMessage(result.message, w);
  writeMessages(result.warnings, w);
  const Drawing& d = result.drawing;
  w.raw(d.widthMm);
  w.raw(d.heightMm);
  w.text(d.source);
  w.raw(static_cast<std::uint32_t>(d.layers.size()));
  for (const Layer& layer : d.layers) {
    w.text(layer.id);
    w.text(layer.name);
    w.raw(layer.rgb);
    w.raw(static_cast<std::uint8_t>(layer.visible ? 1 : 0));
    writePolylines(layer.paths, w);
  }
  w.bytes(kTrailer);
  w.maybeFlush(true);
}

class Reader {
 public:
  explicit Reader(ByteSource& in) : in_(in) {}
  template <typename T>
  bool raw(T& value) { return in_.read(&value, sizeof value); }
  bool text(std::string& s) {
    std::uint32_t n = 0;
    if (!raw(n) || n > kMaxTextBytes) return false;
    s.resize(n);
    return n == 0 || in_.read(s.data(), n);
  }
  bool literal(std::string_view expected) {
    char buffer[16];
    return expected.size() <= sizeof buffer && in_.read(buffer, expected.size()) &&
           std::string_view(buffer, expected.size()) == expected;
  }
  bool count(std::uint32_t& n) { return raw(n) && n < kMaxCount; }
  // n points, read in blocks so that memory follows the data actually received.
  bool points(std::uint32_t n, std::vector<Vec2>& out) {
    constexpr std::uint32_t kBlock = 1u << 16;
    out.clear();
    out.reserve(std::min(n, kBlock));
    for (std::uint32_t done = 0; done < n;) {
      const std::uint32_t k = std::min(n - done, kBlock);
      out.resize(done + k);
      if (!in_.read(out.data() + done, k * sizeof(Vec2))) return false;
      done += k;
    }
    return true;
  }

 private:
  ByteSource& in_;
};

// Appends the polylines (count, then each) to `out`.
bool readPolylines(Reader& r, std::vector<Polyline>& out) {
  std::uint32_t paths = 0;
  if (!r.count(paths)) return false;
  for (std::uint32_t i = 0; i < paths; ++i) {
    std::uint8_t closed = 0;
    std::uint32_t n = 0;
    if (!r.raw(closed) || !r.count(n)) return false;
    Polyline& line = out.emplace_back();
    if ((closed >> 1 & 3) > 2 || closed > 63) return false;
    line.closed = (closed & 1) != 0;
    line.fill = static_cast<FillRule>(closed >> 1 & 3);
    line.fillStart = (closed & 8) != 0;
    line.fillOnly = (closed & 16) != 0;
    line.flattened = (closed & 32) != 0;
    if (!r.points(n, line.points)) return false;
  }
  return true;
}

bool readTexts(Reader& r, std::vector<std::string>& out) {
  std::uint32_t n = 0;
  if (!r.count(n)) return false;
  out.clear();
  for (std::uint32_t i = 0; i < n; ++i)
    if (!r.text(out.emplace_back())) return false;
  return true;
}

// Nesting and arguments a message may have on the wire (ours have at most 3 levels, 5 args).
constexpr int kMaxMessageDepth = 8;
constexpr std::uint32_t kMaxMessageArgs = 99;

bool readMessage(Reader& r, Message& out, int depth = 0) {
  std::string context, templ;
  std::uint32_t n = 0;
  if (depth > kMaxMessageDepth || !r.text(context) || !r.text(templ) || !r.raw(n) || n > kMaxMessageArgs)
    return false;
  out = context.empty() ? Message(std::move(templ)) : Message(std::move(context), std::move(templ));
  for (std::uint32_t i = 0; i < n; ++i) {
    std::uint8_t kind = 0;
    if (!r.raw(kind)) return false;
    switch (static_cast<MessageArg::Kind>(kind)) {
      case MessageArg::Kind::Text: {
        std::string t;
        if (!r.text(t)) return false;
        out.arg(std::move(t));
        break;
      }
      case MessageArg::Kind::Number: {
        double v = 0.0;
        std::int32_t decimals = 0;
        if (!r.raw(v) || !r.raw(decimals) || decimals < 0 || decimals > 17) return false;
        out.arg(v, decimals);
        break;
      }
      case MessageArg::Kind::Nested: {
        Message nested;
        if (!readMessage(r, nested, depth + 1)) return false;
        out.arg(std::move(nested));
        break;
      }
      default: return false;
    }
  }
  return true;
}

bool readMessages(Reader& r, std::vector<Message>& out) {
  std::uint32_t n = 0;
  if (!r.count(n)) return false;
  out.clear();
  for (std::uint32_t i = 0; i < n; ++i)
    if (!readMessage(r, out.emplace_back())) return false;
  return true;
}

bool decodeLayer(Reader& r, Layer& layer) {
  std::uint8_t visible = 0;
  if (!r.text(layer.id) || !r.text(layer.name) || !r.raw(layer.rgb) || !r.raw(visible)) return false;
  layer.visible = visible != 0;
  return readPolylines(r, layer.paths);
}

class ArraySource final : public ByteSource {
 public:
  explicit ArraySource(const QByteArray& bytes) : bytes_(bytes) {}
  bool read(void* dst, std::size_t n) override {
    if (n > static_cast<std::size_t>(bytes_.size() - pos_)) return false;
    std::memcpy(dst, bytes_.constData() + pos_, n);
    pos_ += static_cast<qsizetype>(n);
    return true;
  }

 private:
  const QByteArray& bytes_;
  qsizetype pos_ = 0;
};

}  // namespace

QByteArray encodeResult(const ImportResult& result) {
  QByteArray out;
  qsizetype bytes = 4096;
  for (const Layer& layer : result.drawing.layers) {
    bytes += 64 + static_cast<qsizetype>(layer.id.size() + layer.name.size());
    for (const Polyline& line : layer.paths)
      bytes += 5 + 16 * static_cast<qsizetype>(line.points.size());
  }
  for (const Message& w : result.warnings) bytes += 16 + static_cast<qsizetype>(w.templ().size());
  out.reserve(bytes + static_cast<qsizetype>(result.message.templ().size() + result.drawing.source.size()));
  Writer w(out);
  encode(result, w);
  return out;
}

bool decodeResult(ByteSource& source, ImportResult& result) {
  Reader r(source);
  std::uint32_t status = 0, layers = 0;
  if (!r.literal(kMagic) || !r.raw(status) || !readMessage(r, result.message) ||
      !readMessages(r, result.warnings))
    return false;
  if (status > static_cast<std::uint32_t>(ImportStatus::TooManyPoints)) return false;
  result.status = static_cast<ImportStatus>(status);
  Drawing& d = result.drawing;
  if (!r.raw(d.widthMm) || !r.raw(d.heightMm) || !r.text(d.source) || !r.count(layers))
    return false;
  d.layers.clear();
  for (std::uint32_t i = 0; i < layers; ++i)
    if (!decodeLayer(r, d.layers.emplace_back())) return false;
  return r.literal(kTrailer);
}

bool decodeResult(const QByteArray& bytes, ImportResult& result) {
  ArraySource source(bytes);
  return decodeResult(source, result);
}

// --- the capture stream ---

struct CaptureStreamWriter::Impl {
  explicit Impl(int fd) : writer(buffer, fd) { buffer.reserve((qsizetype{1} << 20) + 65536); }
  QByteArray buffer;
  Writer writer;
};

CaptureStreamWriter::CaptureStreamWriter(int fd) : impl_(std::make_unique<Impl>(fd)) {
  impl_->writer.bytes(kStreamMagic);
}

CaptureStreamWriter::~CaptureStreamWriter() = default;

void CaptureStreamWriter::runs(const std::vector<CapturedRun>& runs) {
  Writer& w = impl_->writer;
  if (runs.empty()) return;
  w.raw(kRunsRecord);
  w.raw(static_cast<std::uint32_t>(runs.size()));
  for (const CapturedRun& run : runs) {
    w.raw(static_cast<std::int32_t>(run.topIndex));
    w.raw(run.rgb);
    writePolylines(run.paths, w);
  }
  w.maybeFlush();
}

void CaptureStreamWriter::restart() { impl_->writer.raw(kRestartRecord); }

bool CaptureStreamWriter::finish(const Capture& c, const std::vector<std::string>& qtMessages) {
  Writer& w = impl_->writer;
  runs(c.runs);
  w.raw(kFinalRecord);
  w.raw(static_cast<std::uint32_t>(c.status));
  writeMessage(c.message, w);
  writeMessages(c.warnings, w);
  writeTexts(qtMessages, w);
  w.raw(static_cast<std::uint8_t>(c.page.sizeKnown ? 1 : 0));
  w.raw(c.page.widthMm);
  w.raw(c.page.heightMm);
  w.raw(static_cast<std::uint32_t>(c.topLevel.size()));
  for (const TopLevelElement& t : c.topLevel) {
    w.text(t.tag.toStdString());
    w.text(t.id.toStdString());
    w.text(t.label.toStdString());
    w.raw(static_cast<std::uint8_t>(t.inkscapeLayer ? 1 : 0));
  }
  w.bytes(kTrailer);
  w.maybeFlush(true);
  return w.ok();
}

namespace {

bool readFinal(Reader& r, StreamedCapture& out) {
  Capture& c = out.capture;
  std::uint32_t status = 0, elements = 0;
  std::uint8_t sizeKnown = 0;
  if (!r.raw(status) || status > static_cast<std::uint32_t>(ImportStatus::TooManyPoints) ||
      !readMessage(r, c.message) || !readMessages(r, c.warnings) || !readTexts(r, out.qtMessages) ||
      !r.raw(sizeKnown) || !r.raw(c.page.widthMm) || !r.raw(c.page.heightMm) || !r.count(elements))
    return false;
  c.status = static_cast<ImportStatus>(status);
  c.page.sizeKnown = sizeKnown != 0;
  for (std::uint32_t i = 0; i < elements; ++i) {
    std::string tag, id, label;
    std::uint8_t inkscape = 0;
    if (!r.text(tag) || !r.text(id) || !r.text(label) || !r.raw(inkscape)) return false;
    c.topLevel.push_back(TopLevelElement{QString::fromStdString(tag), QString::fromStdString(id),
                                         QString::fromStdString(label), inkscape != 0});
  }
  return r.literal(kTrailer);
}

}  // namespace

bool decodeCaptureStream(ByteSource& source, StreamedCapture& out) {
  Reader r(source);
  if (!r.literal(kStreamMagic)) return false;
  std::vector<CapturedRun>& runs = out.capture.runs;
  for (;;) {
    std::uint8_t kind = 0;
    if (!r.raw(kind)) return false;
    if (kind == kFinalRecord) return readFinal(r, out);
    if (kind == kRestartRecord) {
      runs.clear();
      continue;
    }
    std::uint32_t n = 0;
    if (kind != kRunsRecord || !r.count(n)) return false;
    for (std::uint32_t i = 0; i < n; ++i) {
      CapturedRun& run = runs.emplace_back();
      std::int32_t top = 0;
      if (!r.raw(top) || !r.raw(run.rgb) || !readPolylines(r, run.paths)) return false;
      run.topIndex = top;
    }
  }
}

QStringList workerArguments(const QString& path, const ImportOptions& o) {
  const char* mode = o.layerMode == LayerMode::ByGroup   ? "group"
                     : o.layerMode == LayerMode::ByColor ? "color"
                                                         : "auto";
  auto number = [](double v) { return QString::number(v, 'g', 17); };
  return {QStringLiteral("--tolerance-mm"), number(o.toleranceMm),
          QStringLiteral("--dpi"), number(o.dpi),
          QStringLiteral("--width-mm"), number(o.forcedWidthMm),
          QStringLiteral("--height-mm"), number(o.forcedHeightMm),
          QStringLiteral("--max-coordinate-mm"), number(o.maxCoordinateMm),
          QStringLiteral("--max-points"), QString::number(static_cast<qulonglong>(o.maxPoints)),
          QStringLiteral("--outline-fills"), o.outlineFills ? QStringLiteral("1") : QStringLiteral("0"),
          QStringLiteral("--dashes"), o.dashes == DashMode::Solid ? QStringLiteral("solid") : QStringLiteral("dashed"),
          QStringLiteral("--layers"), QString::fromLatin1(mode),
          QStringLiteral("--text-font"), QString::fromStdString(o.textFont),
          QStringLiteral("--"), path};
}

QString parseWorkerArguments(const QStringList& arguments, QString& path, ImportOptions& o,
                             int* resultFd) {
  for (qsizetype i = 0; i < arguments.size(); ++i) {
    const QString& key = arguments[i];
    if (key == u"--") {
      if (i + 2 != arguments.size()) return QStringLiteral("expected exactly one file after --");
      path = arguments[i + 1];
      return {};
    }
    if (i + 1 >= arguments.size()) return QStringLiteral("missing value after ") + key;
    const QString& value = arguments[++i];
    bool ok = true;
    if (key == u"--tolerance-mm") o.toleranceMm = value.toDouble(&ok);
    else if (key == u"--dpi") o.dpi = value.toDouble(&ok);
    else if (key == u"--width-mm") o.forcedWidthMm = value.toDouble(&ok);
    else if (key == u"--height-mm") o.forcedHeightMm = value.toDouble(&ok);
    else if (key == u"--max-coordinate-mm") o.maxCoordinateMm = value.toDouble(&ok);
    else if (key == u"--outline-fills") o.outlineFills = value == u"1";
    else if (key == u"--dashes") {
      if (value == u"dashed") o.dashes = DashMode::Dashed;
      else if (value == u"solid") o.dashes = DashMode::Solid;
      else ok = false;
    }
    else if (key == u"--text-font") o.textFont = value.toStdString();
    else if (key == u"--max-points") o.maxPoints = static_cast<std::size_t>(value.toULongLong(&ok));
    else if (key == QLatin1StringView(kResultFdOption) && resultFd) {
      *resultFd = value.toInt(&ok);
      ok = ok && *resultFd >= 0;
    }
    else if (key == u"--layers") {
      if (value == u"auto") o.layerMode = LayerMode::Auto;
      else if (value == u"group") o.layerMode = LayerMode::ByGroup;
      else if (value == u"color") o.layerMode = LayerMode::ByColor;
      else ok = false;
    } else {
      return QStringLiteral("unknown option ") + key;
    }
    if (!ok) return QStringLiteral("bad value for ") + key + QStringLiteral(": ") + value;
  }
  return QStringLiteral("usage: fivebar-svg-worker [options] -- FILE");
}

}  // namespace fivebar::svg
