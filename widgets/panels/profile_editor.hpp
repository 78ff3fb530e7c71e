// SPDX-License-Identifier: GPL-3.0-or-later
// The machine profile editor: geometry, joint limits, motors, tool, motion and safety margins,
// connection and home pose, presets, import and export of profile JSON (atomic save). Every
// change is validated at once with core validate(); the messages appear next to their fields.
// A valid profile goes to the document (undoable), so the workspace redraws live; an invalid one
// stays in the editor until it is fixed. The editor shows the document's profile after undo.
#pragma once

#include <QWidget>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/machine/profile_fields.hpp"
#include "widgets/document/studio_document.hpp"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;

namespace fivebar::widgets {

class ProfileEditor : public QWidget {
  Q_OBJECT
 public:
  explicit ProfileEditor(StudioDocument& doc, QWidget* parent = nullptr);

  // The field editor for a validate() field path ("geometry.a1", "tool.penDownS", ...).
  QDoubleSpinBox* numberField(const std::string& path) const;
  // The inline message label of a field path (hidden when the field is valid).
  QLabel* messageFor(const std::string& path) const;
  QLabel* generalMessage() const { return general_; }
  // The profile the fields describe now (may be invalid).
  MachineProfile editedProfile() const;
  bool valid() const { return valid_; }

  // Import / export without dialogs (the buttons use these); false with *error on failure.
  bool importFrom(const QString& path, QString* error);
  bool exportTo(const QString& path, QString* error) const;

 public slots:
  void loadFromDocument();
  void loadPreset(const QString& name);

 private slots:
  void onEdited();
  void importClicked();
  void exportClicked();

 private:
  struct NumberField {
    std::string path;
    QDoubleSpinBox* box = nullptr;
    std::function<double(const MachineProfile&)> get;
    std::function<void(MachineProfile&, double)> set;
  };
  void buildFields(QFormLayout* geometry, QFormLayout* limits, QFormLayout* motors,
                   QFormLayout* tool, QFormLayout* motion, QFormLayout* home);
  void addNumber(QFormLayout* form, const std::string& path, const QString& label,
                 const QString& suffix, double min, double max, int decimals,
                 std::function<double(const MachineProfile&)> get,
                 std::function<void(MachineProfile&, double)> set);
  QLabel* addMessage(QFormLayout* form, const std::string& path);
  void showIssues(const std::vector<ValidationIssue>& issues);
  void fill(const MachineProfile& p);

  StudioDocument& doc_;
  std::vector<NumberField> numbers_;
  std::map<std::string, QLabel*> messages_;
  QLineEdit* name_ = nullptr;
  QComboBox* presets_ = nullptr;
  QCheckBox* limited_ = nullptr;
  QComboBox* toolKind_ = nullptr;
  QComboBox* workingMode_ = nullptr;
  QComboBox* assembly_ = nullptr;
  QCheckBox* homing_ = nullptr;
  QLabel* general_ = nullptr;
  bool filling_ = false;
  bool applying_ = false;
  bool valid_ = true;
};

// A field's label and unit suffix (" mm", " °/min") from core's table, in the UI language.
QString profileFieldLabel(const fivebar::ProfileField& field);
QString profileUnitSuffix(const fivebar::ProfileField& field);
}  // namespace fivebar::widgets
