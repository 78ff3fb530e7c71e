#include "wire_format.hpp"

#include <cstdio>
#include <cstring>
#include <string_view>

namespace fivebar::svg {
namespace {

constexpr std::string_view kMagic = "FBSVG1\n";
constexpr std::string_view kTrailer = "END\n";
constexpr std::uint32_t kMaxCount = 1u << 30;

// Appends to a byte buffer; with a file, hands the buffer to it whenever it passes 1 MB.
class Writer {
 public:
  explicit Writer(QByteArray& out, std::FILE* file = nullptr) : out_(out), file_(file) {}
  template <typename T>
  void raw(T value) { out_.append(reinterpret_cast<const char*>(&value), sizeof value); }
  void text(const std::string& s) {
    raw(static_cast<std::uint32_t>(s.size()));
    out_.append(s.data(), static_cast<qsizetype>(s.size()));
  }
  void bytes(std::string_view s) { out_.append(s.data(), static_cast<qsizetype>(s.size())); }
  void maybeFlush(bool force = false) {
    if (!file_ || (!force && out_.size() < (qsizetype{1} << 20))) return;
    std::fwrite(out_.constData(), 1, static_cast<std::size_t>(out_.size()), file_);
    out_.clear();
  }

 private:
  QByteArray& out_;
  std::FILE* file_;
};

void encode(const ImportResult& result, Writer& w) {
  w.bytes(kMagic);
  w.raw(static_cast<std::uint32_t>(result.status));
  w.text(result.message);
  w.raw(static_cast<std::uint32_t>(result.warnings.size()));
  for (const std::string& warning : result.warnings) w.text(warning);
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
    w.raw(static_cast<std::uint32_t>(layer.paths.size()));
    for (const Polyline& line : layer.paths) {
      w.raw(static_cast<std::uint8_t>(line.closed ? 1 : 0));
      w.raw(static_cast<std::uint32_t>(line.points.size()));
      for (const Vec2& p : line.points) {
        w.raw(p.x());
        w.raw(p.y());
      }
      w.maybeFlush();
    }
  }
  w.bytes(kTrailer);
  w.maybeFlush(true);
}

class Reader {
 public:
  explicit Reader(const QByteArray& in) : in_(in) {}
  template <typename T>
  bool raw(T& value) {
    if (pos_ + static_cast<qsizetype>(sizeof value) > in_.size()) return false;
    std::memcpy(&value, in_.constData() + pos_, sizeof value);
    pos_ += static_cast<qsizetype>(sizeof value);
    return true;
  }
  bool text(std::string& s) {
    std::uint32_t n = 0;
    if (!raw(n) || pos_ + static_cast<qsizetype>(n) > in_.size()) return false;
    s.assign(in_.constData() + pos_, n);
    pos_ += static_cast<qsizetype>(n);
    return true;
  }
  bool literal(std::string_view expected) {
    if (pos_ + static_cast<qsizetype>(expected.size()) > in_.size()) return false;
    if (std::string_view(in_.constData() + pos_, expected.size()) != expected) return false;
    pos_ += static_cast<qsizetype>(expected.size());
    return true;
  }
  bool count(std::uint32_t& n) { return raw(n) && n < kMaxCount; }

 private:
  const QByteArray& in_;
  qsizetype pos_ = 0;
};

bool decodeLayer(Reader& r, Layer& layer) {
  std::uint8_t visible = 0;
  std::uint32_t paths = 0;
  if (!r.text(layer.id) || !r.text(layer.name) || !r.raw(layer.rgb) || !r.raw(visible) ||
      !r.count(paths))
    return false;
  layer.visible = visible != 0;
  layer.paths.resize(paths);
  for (Polyline& line : layer.paths) {
    std::uint8_t closed = 0;
    std::uint32_t n = 0;
    if (!r.raw(closed) || !r.count(n)) return false;
    line.closed = closed != 0;
    line.points.resize(n);
    for (Vec2& p : line.points) {
      double x = 0, y = 0;
      if (!r.raw(x) || !r.raw(y)) return false;
      p = Vec2(x, y);
    }
  }
  return true;
}

}  // namespace

QByteArray encodeResult(const ImportResult& result) {
  QByteArray out;
  qsizetype bytes = 4096;
  for (const Layer& layer : result.drawing.layers) {
    bytes += 64 + static_cast<qsizetype>(layer.id.size() + layer.name.size());
    for (const Polyline& line : layer.paths)
      bytes += 5 + 16 * static_cast<qsizetype>(line.points.size());
  }
  for (const std::string& w : result.warnings) bytes += 4 + static_cast<qsizetype>(w.size());
  out.reserve(bytes + static_cast<qsizetype>(result.message.size() + result.drawing.source.size()));
  Writer w(out);
  encode(result, w);
  return out;
}

void writeResult(const ImportResult& result, std::FILE* file) {
  QByteArray buffer;
  buffer.reserve((qsizetype{1} << 20) + 65536);
  Writer w(buffer, file);
  encode(result, w);
  std::fflush(file);
}

bool decodeResult(const QByteArray& bytes, ImportResult& result) {
  Reader r(bytes);
  std::uint32_t status = 0, warnings = 0, layers = 0;
  if (!r.literal(kMagic) || !r.raw(status) || !r.text(result.message) || !r.count(warnings))
    return false;
  if (status > static_cast<std::uint32_t>(ImportStatus::InvalidOptions)) return false;
  result.status = static_cast<ImportStatus>(status);
  result.warnings.resize(warnings);
  for (std::string& w : result.warnings)
    if (!r.text(w)) return false;
  Drawing& d = result.drawing;
  if (!r.raw(d.widthMm) || !r.raw(d.heightMm) || !r.text(d.source) || !r.count(layers))
    return false;
  d.layers.resize(layers);
  for (Layer& layer : d.layers)
    if (!decodeLayer(r, layer)) return false;
  return r.literal(kTrailer);
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
          QStringLiteral("--outline-fills"), o.outlineFills ? QStringLiteral("1") : QStringLiteral("0"),
          QStringLiteral("--layers"), QString::fromLatin1(mode),
          QStringLiteral("--"), path};
}

QString parseWorkerArguments(const QStringList& arguments, QString& path, ImportOptions& o) {
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
