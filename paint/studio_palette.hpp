// SPDX-License-Identifier: GPL-3.0-or-later
// The studio's colours, in one place so canvas, legends, screenshots and the CLI's PNGs agree.
// A light theme: paper-white background, slate machine, blue drawing, red problems.
#pragma once

#include <QColor>

namespace fivebar::paint::palette {

inline QColor background() { return QColor(0xfa, 0xfa, 0xf7); }
inline QColor gridMinor() { return QColor(0xe9, 0xea, 0xe6); }
inline QColor gridMajor() { return QColor(0xd3, 0xd5, 0xcf); }
inline QColor gridLabel() { return QColor(0x8a, 0x8f, 0x98); }
inline QColor axis() { return QColor(0xb0, 0xb4, 0xbb); }
inline QColor machineBase() { return QColor(0x37, 0x41, 0x51); }
inline QColor drivingLink() { return QColor(0x47, 0x55, 0x69); }
inline QColor floatingLink() { return QColor(0x64, 0x74, 0x8b); }
inline QColor joint() { return QColor(0xff, 0xff, 0xff); }
inline QColor pen() { return QColor(0xe1, 0x1d, 0x48); }
inline QColor drawing() { return QColor(0x1d, 0x4e, 0xd8); }
inline QColor travel() { return QColor(0x9c, 0xa3, 0xaf); }
inline QColor problem() { return QColor(0xdc, 0x26, 0x26); }
inline QColor trace() { return QColor(0x0f, 0x76, 0x6e); }
inline QColor selection() { return QColor(0xf5, 0x9e, 0x0b); }

}  // namespace fivebar::paint::palette
