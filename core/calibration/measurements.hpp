// SPDX-License-Identifier: GPL-3.0-or-later
// Reading the calibration's measurement files (docs/calibration.md): CSV with a header line.
//   MEASURED.csv   id,theta1_deg,theta2_deg,x_mm,y_mm   (a mark's commanded angles and its
//                  measured position in any paper frame, mirrored or not)
//   distances      id_a,id_b,distance_mm                (ruler distances between marks)
//   marks          id,theta1_deg,theta2_deg[,...]       (the marks' commanded angles, for distances)
// Columns may come in any order and further columns are ignored; blank lines and lines starting
// with '#' are skipped. Every problem names the file and line.
#pragma once

#include <string>
#include <vector>

#include "core/support/message.hpp"
#include "core/calibration/fit.hpp"

namespace fivebar::calibration {

enum class MeasurementForm { Marks, Distances };

struct MeasurementRead {
  MeasurementForm form = MeasurementForm::Marks;
  std::vector<MarkMeasurement> marks;         // form Marks
  std::vector<DistanceMeasurement> distances;  // form Distances
  Message error;                              // "FILE:LINE: message"; empty on success (translatable)
  bool ok() const { return error.empty(); }
};

// A measurement file of either form, told apart by its header.
MeasurementRead readMeasurements(const std::string& text, const std::string& sourceName);

struct MarkPosesRead {
  std::vector<MarkPose> marks;
  Message error;  // translatable
  bool ok() const { return error.empty(); }
};
MarkPosesRead readMarkPoses(const std::string& text, const std::string& sourceName);

// The whole file's text; an error message naming the file when it cannot be read.
bool readTextFile(const std::string& path, std::string& text, Message& error);

}  // namespace fivebar::calibration
