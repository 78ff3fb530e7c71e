// SPDX-License-Identifier: GPL-3.0-or-later
// The page-frame transform Qt SVG applies to the top-level content of a document (root
// viewBox, preserveAspectRatio, size, and the render mapping of svg_render.cpp), taken from Qt
// itself by rendering a one-path document with the same root attributes. Used by the direct
// reader (fast_import.hpp) so that its points go through exactly Qt's matrix.
#pragma once

#include <QTransform>

#include "svg_units.hpp"

namespace fivebar::svg {

// False when Qt SVG did not draw the probe (the root attributes are unusable). Needs a
// QGuiApplication (QPainter).
bool probePageTransform(const RootAttributes& root, const PageSetup& page, QTransform& out);

}  // namespace fivebar::svg
