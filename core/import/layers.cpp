// SPDX-License-Identifier: GPL-3.0-or-later
#include "layers.hpp"

#include <cstdio>
#include <map>

namespace fivebar::svg {
namespace {

std::string hexColour(std::uint32_t rgb) {
  char text[8];
  std::snprintf(text, sizeof text, "#%06x", static_cast<unsigned>(rgb & 0xFFFFFFu));
  return text;
}

// Which top-level elements become layers of their own.
std::vector<bool> groupLayers(const std::vector<TopLevelElement>& topLevel, LayerMode mode) {
  std::vector<bool> isLayer(topLevel.size(), false);
  int inkscape = 0;
  int groups = 0;
  for (const TopLevelElement& t : topLevel) {
    inkscape += t.inkscapeLayer ? 1 : 0;
    groups += t.tag == u"g" ? 1 : 0;
  }
  for (std::size_t k = 0; k < topLevel.size(); ++k) {
    const bool group = topLevel[k].tag == u"g";
    switch (mode) {
      case LayerMode::ByColor: break;
      case LayerMode::ByGroup: isLayer[k] = group; break;
      case LayerMode::Auto:
        isLayer[k] = inkscape > 0 ? topLevel[k].inkscapeLayer : (groups >= 2 && group);
        break;
    }
  }
  return isLayer;
}

}  // namespace

std::vector<Layer> buildLayers(std::vector<CapturedRun>&& runs,
                               const std::vector<TopLevelElement>& topLevel, LayerMode mode) {
  const std::vector<bool> isLayer = groupLayers(topLevel, mode);
  std::vector<Layer> layers;
  std::map<std::string, std::size_t> indexByKey;
  for (CapturedRun& run : runs) {
    const bool group = run.topIndex >= 0 && static_cast<std::size_t>(run.topIndex) < isLayer.size() &&
                       isLayer[static_cast<std::size_t>(run.topIndex)];
    const std::string key = group ? "group:" + std::to_string(run.topIndex) : "color:" + hexColour(run.rgb);
    auto [it, inserted] = indexByKey.try_emplace(key, layers.size());
    if (inserted) {
      Layer layer;
      layer.rgb = run.rgb;
      if (group) {
        const TopLevelElement& t = topLevel[static_cast<std::size_t>(run.topIndex)];
        const std::string number = std::to_string(run.topIndex + 1);
        layer.id = t.id.isEmpty() ? "layer" + number : t.id.toStdString();
        layer.name = !t.label.isEmpty() ? t.label.toStdString()
                     : !t.id.isEmpty()  ? t.id.toStdString()
                                        : "Layer " + number;
      } else {
        layer.id = "color:" + hexColour(run.rgb);
        layer.name = hexColour(run.rgb);
      }
      layers.push_back(std::move(layer));
    }
    auto& paths = layers[it->second].paths;
    if (paths.empty()) paths = std::move(run.paths);
    else for (Polyline& p : run.paths) paths.push_back(std::move(p));
  }
  return layers;
}

}  // namespace fivebar::svg
