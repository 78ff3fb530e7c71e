// SPDX-License-Identifier: GPL-3.0-or-later
// Rewrites the sanitiser applies so that Qt SVG 6.4 draws what a browser draws (svg_sanitize.cpp
// calls these; docs/svg-import.md lists them):
//  - <symbol> instanced by <use>: the symbol becomes a <g> inside <defs> (never drawn by itself),
//    the <use> a <g transform="use transform, x/y, the symbol's viewBox mapping"> around a plain
//    <use>; nested uses work the same way;
//  - zero-size shapes (rect width/height, circle r, ellipse rx/ry <= 0) are not drawn;
//  - lengths Qt 6.4 misreads: %, em, ex in text x/y/dx/dy, vw/vh/vmin/vmax anywhere, become user
//    units; transform-origin is folded into transform.
// The viewport for percentages and vw/vh is the root's viewBox (or its size in user units).
#pragma once

#include <QByteArray>
#include <QString>
#include <QStringView>
#include <QXmlStreamAttributes>

#include <map>
#include <optional>

namespace fivebar::svg {

struct SymbolInfo {
  QString viewBox, preserveAspectRatio, width, height;
};

// id -> the viewport attributes of a nested <svg> (not the root) with an id, for a <use> of it;
// one quick pass, only when the text holds a second <svg> element.
struct NestedSvgInfo {
  QString x, y, width, height, viewBox, preserveAspectRatio;
};
std::map<QString, NestedSvgInfo> scanNestedSvgs(const QByteArray& document);

// id -> the symbol's viewport attributes; one quick pass, only when the text holds "<symbol".
std::map<QString, SymbolInfo> scanSymbols(const QByteArray& document);

// A <clipPath id>: its units and rule, and the clip path it is itself clipped by (an id or empty).
struct ClipPathInfo {
  bool objectBoundingBox = false;  // clipPathUnits="objectBoundingBox"
  QString clipRule;
  QString clipRef;
};

// id -> the clip path; one quick pass, only when the text holds "clipPath".
std::map<QString, ClipPathInfo> scanClipPaths(const QByteArray& document);

// The id in an element's clip-path="url(#id)" (attribute or style), empty when none.
QString clipPathReference(const QXmlStreamAttributes& attributes);

struct UserViewport {
  double width = 0.0;   // user units; 0 = unknown
  double height = 0.0;
};

// True when SVG disables rendering of the element: rect with width or height <= 0 (or missing),
// circle with r <= 0, ellipse whose rx and ry (one standing in for a missing other) are not > 0.
bool isZeroSizeShape(QStringView tag, const QXmlStreamAttributes& attributes);

// The transform text placing a symbol's content for a <use x y width height> (the use's own
// transform comes first).
QString useSymbolTransform(const QXmlStreamAttributes& use, const SymbolInfo& symbol,
                           const UserViewport& viewport, double dpi);

// Replaces every number with a vw/vh/vmin/vmax unit by user units; nullopt when there is none.
std::optional<QString> resolveViewportUnits(QStringView value, const UserViewport& viewport);

// A text coordinate list (x, y, dx, dy) with %, em, ex or absolute units as plain user units;
// nullopt when nothing had to change or an entry is not a length.
std::optional<QString> resolveTextLengths(QStringView value, double percentReference,
                                          double fontSizeUser, double dpi);

// A font-size value in user units given the parent's; nullopt when not a length we know.
std::optional<double> fontSizeUser(QStringView value, double parentUser, double dpi);

// "translate(o) transform translate(-o)" for transform-origin (keywords, lengths, %);
// nullopt when the origin is not understood.
std::optional<QString> transformWithOrigin(QStringView transform, QStringView origin,
                                           const UserViewport& viewport, double dpi);

}  // namespace fivebar::svg
