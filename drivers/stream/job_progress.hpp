// SPDX-License-Identifier: GPL-3.0-or-later
// Resume state of a job, saved beside it as JOB.gcode.progress (JSON, format in
// docs/machine-protocol.md) atomically with QSaveFile, so that after a stop, an alarm, a
// disconnect or a crash of the host the job can continue from its last completed pen-down point.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace fivebar::stream {

struct JobProgress {
  static constexpr int kVersion = 1;
  std::string jobHash;        // SHA-256 (hex) of the job file's bytes
  std::string machine;        // the --machine preset or file the job ran with ("" unknown)
  int totalLines = 0;         // non-empty lines of the job
  int lastAckedLine = 0;      // file line number (1-based) of the last acknowledged line, 0 none
  int lastCompletedLine = 0;  // file line number of the last line known executed, 0 none
  int lastPenDownLine = 0;    // file line number of the last completed pen-down point, 0 none
  std::array<double, 2> penDownAnglesDeg{0.0, 0.0};  // theta1, theta2 at that point
  int linesDone = 0;          // job lines executed (the count "line N of M" shows), 0 none
  std::string reason;         // why the run ended ("ALARM:2 (Soft limit) ...")
};

std::string progressPathFor(const std::string& jobPath);  // jobPath + ".progress"
std::string sha256Hex(std::string_view bytes);

std::string toJson(const JobProgress& p);
// Parses progress JSON; on failure returns nullopt and sets *error (naming `sourceName`).
std::optional<JobProgress> progressFromJson(const std::string& text, const std::string& sourceName,
                                            std::string* error);

// Atomic save (QSaveFile). Returns an error message, or "" on success.
std::string saveProgress(const JobProgress& p, const std::string& path);
std::optional<JobProgress> loadProgress(const std::string& path, std::string* error);

// Reads a whole file; nullopt with *error naming the file when it cannot be read.
std::optional<std::string> readFile(const std::string& path, std::string* error);

}  // namespace fivebar::stream
