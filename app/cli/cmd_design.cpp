// SPDX-License-Identifier: GPL-3.0-or-later
// fivebar design: link lengths and motor spacing for a target rectangle (docs/design.md).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <thread>

#include "commands.hpp"
#include "core/design/design_json.hpp"
#include "core/design/placement.hpp"
#include "core/design/search.hpp"
#include "machine_arg.hpp"
#include "options.hpp"
#ifdef FIVEBAR_HAVE_QT
#include "design_png.hpp"
#endif

namespace fivebar::cli {
namespace {

using namespace fivebar::design;

constexpr const char* kHelp =
    "usage: fivebar design --rect WxH [--max-link MM] [--min-link MM] [--max-base MM]\n"
    "                      [--min-base MM] [--clearance MM] [--symmetric] [--mode ++|+-|-+|--]\n"
    "                      [--type2-margin DEG]\n"
    "                      [--objective condition|resolution|footprint|mix] [--weights C,R,F]\n"
    "                      [--allow-rotation] [--json OUT.json] [--profile-out PROFILE.json]\n"
    "                      [--png ATLAS.png] [--seed N] [--threads N]\n"
    "       fivebar design --rect WxH --machine PRESET|FILE [--mode M] [--type2-margin DEG]\n"
    "                      [--clearance MM] [--allow-rotation] [--json OUT.json] [--png ATLAS.png]\n"
    "Searches link lengths (a1, b1, a2, b2) and motor spacing w, with the placement of a\n"
    "W x H mm rectangle in the machine frame, for the best worst-case objective over the\n"
    "rectangle, keeping every point reachable, the type II margin (default 15 deg), a 2 deg\n"
    "type I margin and Hoang's criterion 1 (w >= a1 + a2 + clearance). Also prints the\n"
    "trade-off between worst-case condition number and footprint.\n"
    "Defaults: --min-link 30 --max-link 200 --min-base 0 --max-base 250 --clearance 10,\n"
    "all four working modes, --objective condition, --seed 1, --threads = CPU cores.\n"
    "--objective mix minimises C*kappa + R*resolution + F*footprint on normalised terms\n"
    "(docs/design.md \"Mix\"); --weights C,R,F (default 1,1,1) only with it.\n"
    "--allow-rotation also tries the rectangle turned by 90 deg (width along y).\n"
    "With --machine, evaluates that machine instead: the rectangle placed where the\n"
    "objective (default its worst condition number) is lowest (in the profile's working\n"
    "mode unless --mode is given).\n"
    "Exit status 1 when no design meets the brief (the message names the binding constraint).\n";

double parseMm(const Options& o, const std::string& name, double fallback, double lo, double hi) {
  const auto v = o.value(name);
  if (!v) return fallback;
  std::size_t used = 0;
  double x = 0.0;
  try {
    x = std::stod(*v, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != v->size() || !std::isfinite(x) || x < lo || x > hi) {
    char range[96];
    std::snprintf(range, sizeof range, "a number from %g to %g", lo, hi);
    throw UsageError(name + " must be " + range + ", got '" + *v + "'");
  }
  return x;
}

void parseRect(const std::string& text, double& w, double& h) {
  const auto x = text.find_first_of("xX");
  bool ok = x != std::string::npos;
  if (ok) {
    try {
      std::size_t u1 = 0, u2 = 0;
      const std::string a = text.substr(0, x), b = text.substr(x + 1);
      w = std::stod(a, &u1);
      h = std::stod(b, &u2);
      ok = u1 == a.size() && u2 == b.size() && w > 0 && h > 0 && std::isfinite(w) && std::isfinite(h);
    } catch (const std::exception&) {
      ok = false;
    }
  }
  if (!ok) throw UsageError("--rect must be WxH in mm, e.g. 110x90, got '" + text + "'");
}

// --weights C,R,F: three numbers >= 0, not all zero.
MixWeights parseWeights(const std::string& text) {
  double v[3] = {0.0, 0.0, 0.0};
  std::size_t start = 0;
  bool ok = true;
  for (int i = 0; i < 3 && ok; ++i) {
    const std::size_t comma = text.find(',', start);
    if ((i < 2) == (comma == std::string::npos)) ok = false;
    const std::string part = text.substr(start, i < 2 ? comma - start : std::string::npos);
    try {
      std::size_t used = 0;
      v[i] = std::stod(part, &used);
      ok = ok && used == part.size() && !part.empty();
    } catch (const std::exception&) {
      ok = false;
    }
    start = comma == std::string::npos ? text.size() : comma + 1;
  }
  const MixWeights w{v[0], v[1], v[2]};
  std::string problem = ok ? validateWeights(w).text() : std::string("it needs three numbers");
  if (!problem.empty())
    throw UsageError("--weights must be C,R,F (three numbers >= 0, not all zero), e.g. 1,0,0.5, got '" +
                     text + "': " + problem);
  return w;
}

struct Request {
  DesignBrief brief;
  SearchOptions search;
  std::optional<std::string> jsonPath, profilePath, pngPath, machine;
};

Request parseRequest(const Options& o) {
  if (!o.positional().empty()) throw UsageError("unexpected argument '" + o.positional()[0] + "'");
  Request r;
  DesignBrief& b = r.brief;
  parseRect(o.required("--rect"), b.widthMm, b.heightMm);
  b.bounds.minLinkMm = parseMm(o, "--min-link", 30.0, 1.0, 1e4);
  b.bounds.maxLinkMm = parseMm(o, "--max-link", std::max(200.0, b.bounds.minLinkMm), 1.0, 1e4);
  b.bounds.minBaseMm = parseMm(o, "--min-base", 0.0, 0.0, 1e4);
  b.bounds.maxBaseMm = parseMm(o, "--max-base", std::max(250.0, b.bounds.minBaseMm), 0.0, 1e4);
  b.rules.clearanceMm = parseMm(o, "--clearance", 10.0, 0.0, 1e4);
  b.rules.workspace.typeIIMarginRad = radFromDeg(parseMm(o, "--type2-margin", 15.0, 0.0, 89.0));
  b.bounds.symmetric = o.flag("--symmetric");
  if (auto m = o.value("--mode")) {
    b.mode = parseWorkingMode(*m);
    if (!b.mode) throw UsageError("--mode must be one of ++, +-, -+, --, got '" + *m + "'");
  }
  if (auto obj = o.value("--objective")) {
    const auto parsed = parseObjective(*obj);
    if (!parsed) throw UsageError("--objective must be condition, resolution, footprint or mix, got '" + *obj + "'");
    b.objective = *parsed;
  }
  if (auto w = o.value("--weights")) {
    if (b.objective != Objective::Mix) throw UsageError("--weights needs --objective mix");
    b.weights = parseWeights(*w);
  }
  b.allowRotation = o.flag("--allow-rotation");
  r.search.seed = static_cast<std::uint32_t>(parseMm(o, "--seed", 1.0, 0.0, 4e9));
  r.search.threads = static_cast<unsigned>(
      parseMm(o, "--threads", std::max(1u, std::thread::hardware_concurrency()), 1.0, 64.0));
  for (const ValidationIssue& issue : validate(b)) throw UsageError(issue.message.text());
  r.jsonPath = o.value("--json");
  r.profilePath = o.value("--profile-out");
  r.pngPath = o.value("--png");
  r.machine = o.value("--machine");
  if (r.machine && r.profilePath) throw UsageError("--profile-out is for searches, not with --machine");
  return r;
}

std::string num(double v, int decimals) {
  if (!std::isfinite(v)) return "inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

void printDesign(const Design& d, double penSpeed) {
  const Geometry& g = d.geometry;
  const DesignMeasures& m = d.evaluation.measures;
  std::cout << "design: a1=" << num(g.a1, 1) << " b1=" << num(g.b1, 1) << " a2=" << num(g.a2, 1)
            << " b2=" << num(g.b2, 1) << " w=" << num(g.w, 1) << " mm, working mode "
            << toString(d.mode) << "\n"
            << "rectangle: x " << num(d.rect.xMin, 1) << " .. " << num(d.rect.xMax, 1) << ", y "
            << num(d.rect.yMin, 1) << " .. " << num(d.rect.yMax, 1) << " mm"
            << (d.rotated ? " (turned)" : "") << "\n"
            << "worst condition number " << num(m.worstCondition, 2) << " (mean "
            << num(m.meanCondition, 2) << "), type II margin " << num(degFromRad(m.minTypeIIMarginRad), 1)
            << " deg, type I margin " << num(degFromRad(m.minTypeIMarginRad), 1) << " deg\n"
            << "worst " << num(m.worstMmPerStep * 1000.0, 1) << " um per step, worst motor speed "
            << num(degFromRad(m.worstMotorSpeedRadPerS), 0) << " deg/s at " << num(penSpeed, 0)
            << " mm/s, footprint " << num(m.footprintMm2 / 100.0, 0) << " cm^2, driving links "
            << num(m.drivingLinkSpacingMm, 1) << " mm apart at full turn"
            << (m.armsCanCollide ? " (can collide)" : "") << "\n";
}

std::string writeText(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  out.close();
  return out ? std::string() : "cannot write " + path;
}

// --machine: the given machine's best placement of the rectangle, reported like a design.
int evaluateMachine(const Request& req) {
  const auto profile = loadMachine(*req.machine, "design", std::cerr);
  if (!profile) return 1;
  DesignBrief b = req.brief;
  b.rules.workspace.typeIMarginRad = profile->typeIMarginRad;
  b.rules.workspace.stepRad1 = radFromDeg(1.0 / profile->motors.stepsPerDeg1);
  b.rules.workspace.stepRad2 = radFromDeg(1.0 / profile->motors.stepsPerDeg2);
  Design d;
  d.geometry = profile->geometry;
  d.mode = b.mode.value_or(profile->defaultMode);
  PlacementOptions po;
  po.objective = b.objective;
  po.weights = b.weights;
  po.allowRotation = b.allowRotation;
  const Placement p = bestPlacement(d.geometry, d.mode, b.widthMm, b.heightMm, b.rules, po);
  d.rect = p.rect;
  d.rotated = p.rotated;
  d.evaluation = p.evaluation;
  d.score = p.score;
  std::cout << "machine: " << profile->name << "\n";
  printDesign(d, b.rules.penSpeedMmPerS);
  if (!d.evaluation.feasible())
    std::cout << "the rectangle does not fit by the rules: " << d.evaluation.violations.binding(kViolationScaleMm)
              << " binds\n";
  if (req.jsonPath) {
    nlohmann::json j = designJson(d);
    j["machine"] = profile->name;
    if (const std::string err = writeText(*req.jsonPath, j.dump(2) + "\n"); !err.empty()) {
      std::cerr << "fivebar design: " << err << "\n";
      return 1;
    }
  }
#ifdef FIVEBAR_HAVE_QT
  if (req.pngPath)
    if (const std::string err = writeDesignPng(*req.pngPath, d, b); !err.empty()) {
      std::cerr << "fivebar design: " << err << "\n";
      return 1;
    }
#endif
  return d.evaluation.feasible() ? 0 : 1;
}

}  // namespace

int runDesign(const Args& args) {
  Request req;
  try {
    const Options o(args,
                    {"--rect", "--max-link", "--min-link", "--max-base", "--min-base", "--clearance",
                     "--mode", "--type2-margin", "--objective", "--json", "--profile-out", "--png",
                     "--seed", "--threads", "--machine", "--weights"},
                    {"--symmetric", "--allow-rotation", "--help"});
    if (o.flag("--help")) {
      std::cout << kHelp;
      return 0;
    }
    req = parseRequest(o);
  } catch (const UsageError& e) {
    std::cerr << "fivebar design: " << e.what() << "\n" << kHelp;
    return 2;
  }
#ifndef FIVEBAR_HAVE_QT
  if (req.pngPath) {
    std::cerr << "fivebar design: --png is unavailable: this fivebar was built without Qt\n";
    return 2;
  }
#endif
  if (req.machine) return evaluateMachine(req);
  const DesignBrief& b = req.brief;
  std::cout << "brief: " << num(b.widthMm, 1) << " x " << num(b.heightMm, 1) << " mm, links "
            << num(b.bounds.minLinkMm, 1) << " .. " << num(b.bounds.maxLinkMm, 1) << " mm, base "
            << num(b.bounds.minBaseMm, 1) << " .. " << num(b.bounds.maxBaseMm, 1) << " mm, clearance "
            << num(b.rules.clearanceMm, 1) << " mm, type II margin "
            << num(degFromRad(b.rules.workspace.typeIIMarginRad), 1) << " deg, "
            << (b.bounds.symmetric ? "symmetric, " : "") << "mode "
            << (b.mode ? std::string(toString(*b.mode)) : std::string("any")) << ", objective "
            << toString(b.objective);
  if (b.objective == Objective::Mix)
    std::cout << " (weights " << num(b.weights.condition, 2) << "," << num(b.weights.resolution, 2)
              << "," << num(b.weights.footprint, 2) << ")";
  std::cout << (b.allowRotation ? ", rotation allowed" : "") << "\n";
  const SearchResult result = searchDesigns(b, req.search);
  if (req.jsonPath)
    if (const std::string err = writeText(*req.jsonPath, searchJson(b, result, req.search).dump(2) + "\n");
        !err.empty()) {
      std::cerr << "fivebar design: " << err << "\n";
      return 1;
    }
  std::cout << "search: " << result.evaluations << " evaluations in " << num(result.seconds, 1)
            << " s on " << req.search.threads << " threads (seed " << req.search.seed << ")\n";
  if (result.status != SearchStatus::Found) {
    std::cerr << "fivebar design: no design meets the brief: " << result.message << "\n";
    return 1;
  }
  printDesign(*result.best, b.rules.penSpeedMmPerS);
  std::cout << "trade-off (worst condition number vs footprint), " << result.pareto.size()
            << " designs:\n";
  for (const Design& d : result.pareto) {
    const Geometry& g = d.geometry;
    std::cout << "  kappa " << num(d.evaluation.measures.worstCondition, 2) << "  footprint "
              << num(d.evaluation.measures.footprintMm2 / 100.0, 0) << " cm^2  a1=" << num(g.a1, 1)
              << " b1=" << num(g.b1, 1) << " a2=" << num(g.a2, 1) << " b2=" << num(g.b2, 1)
              << " w=" << num(g.w, 1) << " " << toString(d.mode) << "\n";
  }
  if (req.profilePath) {
    char name[64];
    std::snprintf(name, sizeof name, "design-%gx%g", b.widthMm, b.heightMm);
    const MachineProfile profile = designProfile(*result.best, b, name);
    if (const std::string err = saveProfile(profile, *req.profilePath); !err.empty()) {
      std::cerr << "fivebar design: " << err << "\n";
      return 1;
    }
  }
#ifdef FIVEBAR_HAVE_QT
  if (req.pngPath)
    if (const std::string err = writeDesignPng(*req.pngPath, *result.best, b); !err.empty()) {
      std::cerr << "fivebar design: " << err << "\n";
      return 1;
    }
#endif
  return 0;
}

}  // namespace fivebar::cli
