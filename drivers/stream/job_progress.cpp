// SPDX-License-Identifier: GPL-3.0-or-later
#include "job_progress.hpp"

#include <QCryptographicHash>
#include <QFile>
#include <QSaveFile>
#include <nlohmann/json.hpp>

#include <stdexcept>

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
  // A count or line number: an integer of int's range (nlohmann's get<int> of 1e300 or of a
  // float would convert without a check).
  const auto lineNumber = [&](const char* key, bool required) -> int {
    if (!j.contains(key)) {
      if (required) throw std::invalid_argument(std::string(key) + " is missing");
      return 0;
    }
    const nlohmann::json& v = j.at(key);
    const bool inRange = v.is_number_unsigned() ? v.get<unsigned long long>() <= 2147483647ULL
                         : v.is_number_integer() ? v.get<long long>() >= 0 && v.get<long long>() <= 2147483647LL
                                                 : false;
    if (!inRange) throw std::invalid_argument(std::string(key) + " must be a whole number from 0");
    return static_cast<int>(v.get<long long>());
  };
  try {
    if (!j.contains("version") || !j.at("version").is_number_integer() ||
        j.at("version").get<long long>() != JobProgress::kVersion)
      return fail("unsupported progress version (expected " + std::to_string(JobProgress::kVersion) + ")");
    JobProgress p;
    p.jobHash = j.at("jobHash").get<std::string>();
    p.machine = j.value("machine", std::string());
    p.totalLines = lineNumber("totalLines", true);
    p.lastAckedLine = lineNumber("lastAckedLine", true);
    p.lastCompletedLine = lineNumber("lastCompletedLine", true);
    p.lastPenDownLine = lineNumber("lastPenDownLine", true);
    p.penDownAnglesDeg = j.at("penDownAnglesDeg").get<std::array<double, 2>>();
    p.linesDone = lineNumber("linesDone", false);  // absent in files of earlier versions
    p.reason = j.value("reason", std::string());
    return p;
  } catch (const std::invalid_argument& e) {
    return fail(e.what());
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
