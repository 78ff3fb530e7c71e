#include "record.hpp"

#include <QSaveFile>
#include <nlohmann/json.hpp>

namespace fivebar::simapp {

std::string recordJson(const sim::SimMachine& m) {
  nlohmann::json strokes = nlohmann::json::array();
  for (const auto& s : m.strokes()) strokes.push_back(s);
  const nlohmann::json j = {{"strokesDeg", strokes},
                            {"machinePosition", m.machinePosition()},
                            {"workPosition", m.workPosition()},
                            {"state", std::string(grbl::toString(m.state()))},
                            {"linesReceived", m.linesReceived()},
                            {"rxOverflowBytes", m.rxOverflowBytes()},
                            {"plannerStarvationsInStroke", m.plannerStarvationsInStroke()}};
  return j.dump() + "\n";
}

std::string writeRecord(const sim::SimMachine& m, const std::string& path) {
  QSaveFile file(QString::fromStdString(path));
  if (!file.open(QIODevice::WriteOnly)) return "cannot write " + path;
  const std::string text = recordJson(m);
  file.write(text.data(), qint64(text.size()));
  return file.commit() ? "" : "cannot save " + path;
}

}  // namespace fivebar::simapp
