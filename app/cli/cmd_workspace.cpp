// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar workspace: areas, type II curves and the largest singularity-free rectangle of one
// working mode; optionally a JSON summary and a PNG overlay image.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "commands.hpp"
#include "core/workspace/workspace.hpp"
#include "machine_arg.hpp"
#include "options.hpp"
#ifdef FIVEBAR_HAVE_QT
#include "workspace_png.hpp"
#endif

namespace fivebar::cli {
namespace {

constexpr const char* kHelp =
    "usage: fivebar workspace --machine PRESET|FILE [--mode ++|+-|-+|--] [--cells N]\n"
    "                         [--aspect W:H] [--json FILE] [--png FILE]\n"
    "Samples the working mode's workspace on the work side (y >= 0) of the machine frame and\n"
    "prints the reachable area, the singularity-free area (the profile's type II and type I\n"
    "margins) and the largest axis-aligned rectangle inside it (with --aspect, of that shape).\n"
    "--cells: grid cells along the longer side (default 512, 16..4096).\n"
    "--json writes the figures; --png draws the analysis (needs a build with Qt).\n";

struct Request {
  std::string machine;
  std::optional<WorkingMode> mode;
  int cells = 512;
  double aspect = 0.0;
  std::optional<std::string> jsonPath, pngPath;
};

double parseAspect(const std::string& text) {
  const auto colon = text.find(':');
  double w = 0.0, h = 1.0;
  try {
    std::size_t used = 0;
    if (colon == std::string::npos) {
      w = std::stod(text, &used);
      if (used != text.size()) throw std::invalid_argument(text);
    } else {
      w = std::stod(text.substr(0, colon), &used);
      if (used != colon) throw std::invalid_argument(text);
      const std::string rest = text.substr(colon + 1);
      h = std::stod(rest, &used);
      if (used != rest.size()) throw std::invalid_argument(text);
    }
  } catch (const std::exception&) {
    throw UsageError("--aspect must be W:H or a ratio, got '" + text + "'");
  }
  if (!(w > 0.0 && h > 0.0 && std::isfinite(w / h)))
    throw UsageError("--aspect must be positive, got '" + text + "'");
  return w / h;
}

Request parseRequest(const Options& o) {
  if (!o.positional().empty()) throw UsageError("unexpected argument '" + o.positional()[0] + "'");
  Request r;
  r.machine = o.required("--machine");
  if (auto m = o.value("--mode")) {
    r.mode = parseWorkingMode(*m);
    if (!r.mode) throw UsageError("--mode must be one of ++, +-, -+, --, got '" + *m + "'");
  }
  if (auto c = o.value("--cells")) {
    std::size_t used = 0;
    try {
      r.cells = std::stoi(*c, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != c->size() || r.cells < 16 || r.cells > 4096)
      throw UsageError("--cells must be an integer from 16 to 4096, got '" + *c + "'");
  }
  if (auto a = o.value("--aspect")) r.aspect = parseAspect(*a);
  r.jsonPath = o.value("--json");
  r.pngPath = o.value("--png");
  return r;
}

std::string number(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

void printReport(const MachineProfile& p, const WorkspaceMap& map, const WorkspaceAnalysis& a) {
  const Geometry& g = p.geometry;
  std::cout << "machine: " << p.name << " (a1=" << g.a1 << " b1=" << g.b1 << " a2=" << g.a2
            << " b2=" << g.b2 << " w=" << g.w << " mm), working mode " << toString(a.mode) << "\n"
            << "grid: " << map.grid.nx << " x " << map.grid.ny << " cells of "
            << number(map.grid.cellMm, 3) << " mm (work side, y >= 0)\n"
            << "reachable area: " << number(a.reachableAreaMm2, 0) << " mm^2\n"
            << "singularity-free area (type II >= " << number(degFromRad(map.typeIIMarginRad), 1)
            << " deg, type I >= " << number(degFromRad(map.typeIMarginRad), 1)
            << " deg): " << number(a.safeAreaMm2, 0) << " mm^2\n"
            << "type II singularity curves inside the workspace: " << a.typeIILoci.size() << "\n";
  if (const auto& r = a.largestRectangle) {
    std::cout << "largest rectangle: " << number(r->width(), 1) << " x " << number(r->height(), 1)
              << " mm, x " << number(r->xMin, 1) << " .. " << number(r->xMax, 1) << ", y "
              << number(r->yMin, 1) << " .. " << number(r->yMax, 1) << " mm\n";
  } else {
    std::cout << "largest rectangle: none (no singularity-free cell)\n";
  }
}

std::string writeJson(const std::string& path, const MachineProfile& p, const WorkspaceMap& map,
                      const WorkspaceAnalysis& a) {
  nlohmann::json j;
  j["machine"] = p.name;
  j["workingMode"] = std::string(toString(a.mode));
  j["grid"] = {{"x0Mm", map.grid.x0}, {"y0Mm", map.grid.y0}, {"cellMm", map.grid.cellMm},
               {"nx", map.grid.nx}, {"ny", map.grid.ny}};
  j["typeIIMarginDeg"] = degFromRad(map.typeIIMarginRad);
  j["typeIMarginDeg"] = degFromRad(map.typeIMarginRad);
  j["reachableAreaMm2"] = a.reachableAreaMm2;
  j["singularityFreeAreaMm2"] = a.safeAreaMm2;
  j["typeIICurves"] = a.typeIILoci.size();
  if (const auto& r = a.largestRectangle) {
    j["largestRectangle"] = {{"xMinMm", r->xMin},     {"yMinMm", r->yMin},
                             {"xMaxMm", r->xMax},     {"yMaxMm", r->yMax},
                             {"widthMm", r->width()}, {"heightMm", r->height()}};
  } else {
    j["largestRectangle"] = nullptr;
  }
  std::ofstream out(path);
  out << j.dump(2) << "\n";
  out.close();
  if (!out) return "cannot write " + path;
  return {};
}

}  // namespace

int runWorkspace(const Args& args) {
  Request req;
  try {
    const Options o(args, {"--machine", "--mode", "--cells", "--aspect", "--json", "--png"},
                    {"--help"});
    if (o.flag("--help")) {
      std::cout << kHelp;
      return 0;
    }
    req = parseRequest(o);
  } catch (const UsageError& e) {
    std::cerr << "fivebar workspace: " << e.what() << "\n" << kHelp;
    return 2;
  }
#ifndef FIVEBAR_HAVE_QT
  if (req.pngPath) {
    std::cerr << "fivebar workspace: --png is unavailable: this fivebar was built without Qt "
                 "(FIVEBAR_BUILD_GUI=OFF)\n";
    return 2;
  }
#endif
  const auto profile = loadMachine(req.machine, "workspace", std::cerr);
  if (!profile) return 1;
  const WorkingMode mode = req.mode.value_or(profile->defaultMode);
  const WorkspaceSettings settings = workspaceSettings(*profile);
  const GridSpec grid = gridCovering(profile->geometry, req.cells);
  const WorkspaceMap map = computeMap(profile->geometry, settings, mode, grid);
  const WorkspaceAnalysis analysis = analyse(map, profile->geometry, settings, req.aspect);
  printReport(*profile, map, analysis);
  if (req.jsonPath) {
    if (const std::string err = writeJson(*req.jsonPath, *profile, map, analysis); !err.empty()) {
      std::cerr << "fivebar workspace: " << err << "\n";
      return 1;
    }
  }
#ifdef FIVEBAR_HAVE_QT
  if (req.pngPath) {
    if (const std::string err = writeWorkspacePng(*req.pngPath, *profile, map, analysis);
        !err.empty()) {
      std::cerr << "fivebar workspace: " << err << "\n";
      return 1;
    }
  }
#endif
  return 0;
}

}  // namespace fivebar::cli
