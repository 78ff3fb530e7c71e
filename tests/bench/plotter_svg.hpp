// SPDX-License-Identifier: GPL-3.0-or-later
// The 10 MB plotter SVG of the benchmarks (issue 3 goal), generated in memory: the file
// `fivebar_bench_pipeline --write-svg` writes, byte for byte.
#pragma once

#include <QByteArray>

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>

namespace fivebar::bench {

// The plotter file of the pipeline benchmark (`fivebar_bench_pipeline --write-svg`), generated
// the same way: 42,000 paths on a 200 x 150 mm page, 60 % chains of 3..10 cubic "petals", 40 %
// polylines of 2..7 points, 3 decimals; about 9.7 MB and 2.65 M points at 0.04 mm. Byte for
// byte the file of `fivebar_bench_pipeline --write-svg` (GCC evaluates its Vec2(a(), b())
// arguments right to left; the draws below follow that order).
inline QByteArray plotterSvg() {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> x(10, 190), y(10, 140), d(-6, 6), u(0, 1);
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200mm\" height=\"150mm\" "
                    "viewBox=\"0 0 200 150\">\n<g fill=\"none\" stroke=\"black\" stroke-width=\"0.3\">\n";
  std::string lines;
  char buffer[64];
  auto point = [&](std::string& to, double px, double py) {
    std::snprintf(buffer, sizeof buffer, "%.3f %.3f", px, 150.0 - py);
    to += buffer;
  };
  for (int i = 0; i < 42000; ++i) {
    if (u(rng) < 0.6) {
      double ay = y(rng), ax = x(rng);  // GCC's right-to-left argument order in the original
      const int n = 3 + static_cast<int>(u(rng) * 8);
      std::string path = "<path d=\"M";
      point(path, ax, ay);
      for (int k = 0; k < n; ++k) {
        const double p1y = ay + d(rng), p1x = ax + d(rng), p3y = ay + d(rng), p3x = ax + d(rng);
        const double p2y = p3y + d(rng), p2x = p3x + d(rng);
        ax = std::clamp(p3x, 1.0, 199.0);
        ay = std::clamp(p3y, 1.0, 149.0);
        path += " C";
        point(path, p1x, p1y);
        path += ' ';
        point(path, p2x, p2y);
        path += ' ';
        point(path, ax, ay);
      }
      out += path + "\"/>\n";
    } else {
      std::string line = "<polyline points=\"";
      const int n = 2 + static_cast<int>(u(rng) * 6);
      for (int k = 0; k < n; ++k) {
        const double py = y(rng), px = x(rng);
        point(line, px, py);
        line += ' ';
      }
      lines += line + "\"/>\n";
    }
  }
  out += lines + "</g>\n</svg>\n";
  return QByteArray::fromStdString(out);
}

}  // namespace fivebar::bench
