// SPDX-License-Identifier: GPL-3.0-or-later
#include "job_progress.hpp"

#include <QCryptographicHash>
#include <QFile>
#include <QSaveFile>
#include <nlohmann/json.hpp>

namespace fivebar::stream {

std::string progressPathFor(const std::string& jobPath) { return jobPath + ".progress"; }

std::string sha256Hex(std::string_view bytes) {
  const QByteArray digest = QCryptographicHash::hash(
      QByteArrayView(bytes.data(), qsizetype(bytes.size())), QCryptographicHash::Sha256);
  return digest.toHex().toStdString();
}

std::string toJson(const JobProgress& p) {
  nlohmann::json j = {{"version", JobProgress::kVersion},
                      {"jobHash", p.jobHash},
                      {"machine", p.machine},
                      {"totalLines", p.totalLines},
                      {"lastAckedLine", p.lastAckedLine},
                      {"lastCompletedLine", p.lastCompletedLine},
                      {"lastPenDownLine", p.lastPenDownLine},
                      {"penDownAnglesDeg", p.penDownAnglesDeg},
                      {"linesDone", p.linesDone},
                      {"reason", p.reason}};
  return j.dump(2) + "\n";
}

std::optional<JobProgress> progressFromJson(const std::string& text, const std::string& sourceName,
                                            std::string* error) {
  const auto fail = [&](const std::string& why) -> std::optional<JobProgress> {
    if (error) *error = sourceName + ": " + why;
    return std::nullopt;
  };
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return fail("not valid JSON");
  if (j.value("version", 0) != JobProgress::kVersion)
    return fail("unsupported progress version (expected " + std::to_string(JobProgress::kVersion) + ")");
  try {
    JobProgress p;
    p.jobHash = j.at("jobHash").get<std::string>();
    p.machine = j.value("machine", std::string());
    p.totalLines = j.at("totalLines").get<int>();
    p.lastAckedLine = j.at("lastAckedLine").get<int>();
    p.lastCompletedLine = j.at("lastCompletedLine").get<int>();
    p.lastPenDownLine = j.at("lastPenDownLine").get<int>();
    p.penDownAnglesDeg = j.at("penDownAnglesDeg").get<std::array<double, 2>>();
    p.linesDone = j.value("linesDone", 0);  // absent in files of earlier versions
    p.reason = j.value("reason", std::string());
    return p;
  } catch (const nlohmann::json::exception& e) {
    return fail(std::string("field missing or of the wrong type: ") + e.what());
  }
}

std::string saveProgress(const JobProgress& p, const std::string& path) {
  QSaveFile file(QString::fromStdString(path));
  if (!file.open(QIODevice::WriteOnly))
    return "cannot write " + path + ": " + file.errorString().toStdString();
  const std::string text = toJson(p);
  file.write(text.data(), qint64(text.size()));
  if (!file.commit()) return "cannot save " + path + ": " + file.errorString().toStdString();
  return {};
}

std::optional<std::string> readFile(const std::string& path, std::string* error) {
  QFile file(QString::fromStdString(path));
  if (!file.open(QIODevice::ReadOnly)) {
    if (error) *error = "cannot read " + path + ": " + file.errorString().toStdString();
    return std::nullopt;
  }
  return file.readAll().toStdString();
}

std::optional<JobProgress> loadProgress(const std::string& path, std::string* error) {
  const auto text = readFile(path, error);
  if (!text) return std::nullopt;
  return progressFromJson(*text, path, error);
}

}  // namespace fivebar::stream
