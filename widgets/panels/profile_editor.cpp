// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/panels/profile_editor.hpp"

#include <QCheckBox>
#include <QCoreApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>
#include <cmath>
#include <map>
#include <string_view>

#include "core/machine/profile.hpp"
#include "core/machine/profile_fields.hpp"
#include "i18n/translated.hpp"
#include "core/kinematics/units.hpp"

namespace fivebar::widgets {
namespace {

constexpr double kDefaultLimitDeg = 180.0;  // limits offered when "joint limits" is switched on

bool unlimited(const JointLimits& l) {
  return l.theta1Max >= JointLimits::kDefaultSpan && l.theta2Max >= JointLimits::kDefaultSpan;
}

using Get = std::function<double(const MachineProfile&)>;
using Set = std::function<void(MachineProfile&, double)>;


}  // namespace

QString profileFieldLabel(const ProfileField& f) {
  // Marked for lupdate where the table writes it (core/machine/profile_fields.cpp).
  return QCoreApplication::translate("ProfileField", f.label);
}

QString profileUnitSuffix(const ProfileField& f) {
  // The file's unit names (deg, deg/min, ...) as a maker reads them, translated.
  static const std::map<std::string, const char*> shown = {
      {"mm", QT_TRANSLATE_NOOP("fivebar::widgets::ProfileEditor", " mm")},         {"deg", QT_TRANSLATE_NOOP("fivebar::widgets::ProfileEditor", " °")},
      {"s", QT_TRANSLATE_NOOP("fivebar::widgets::ProfileEditor", " s")},           {"deg/min", QT_TRANSLATE_NOOP("fivebar::widgets::ProfileEditor", " °/min")},
      {"deg/s²", QT_TRANSLATE_NOOP("fivebar::widgets::ProfileEditor", " °/s²")},   {"mm/min", QT_TRANSLATE_NOOP("fivebar::widgets::ProfileEditor", " mm/min")},
      {"mm/s", QT_TRANSLATE_NOOP("fivebar::widgets::ProfileEditor", " mm/s")},     {"steps/deg", QT_TRANSLATE_NOOP("fivebar::widgets::ProfileEditor", " steps/°")},
      {"baud", QT_TRANSLATE_NOOP("fivebar::widgets::ProfileEditor", " baud")}};
  const auto it = shown.find(f.unit);
  if (it != shown.end()) return ProfileEditor::tr(it->second);
  return *f.unit ? QStringLiteral(" ") + QString::fromUtf8(f.unit) : QString();
}

ProfileEditor::ProfileEditor(StudioDocument& doc, QWidget* parent) : QWidget(parent), doc_(doc) {
  setObjectName(QStringLiteral("profileEditor"));
  presets_ = new QComboBox(this);
  for (const std::string& name : presetNames()) presets_->addItem(QString::fromStdString(name));
  auto* loadPresetButton = new QPushButton(tr("Load preset"), this);
  auto* importButton = new QPushButton(tr("Import…"), this);
  importButton->setToolTip(tr("Load a machine profile from a JSON file"));
  auto* exportButton = new QPushButton(tr("Export…"), this);
  exportButton->setToolTip(tr("Save this machine profile as a JSON file"));
  // Two rows, so that the dock stays narrow in every language (French and Spanish labels are
  // longer: one row of four clipped the editor at the left docks' width).
  auto* presetRow = new QHBoxLayout;
  presetRow->addWidget(presets_, 1);
  presetRow->addWidget(loadPresetButton);
  auto* fileRow = new QHBoxLayout;
  fileRow->addStretch(1);
  fileRow->addWidget(importButton);
  fileRow->addWidget(exportButton);
  auto* top = new QVBoxLayout;
  top->addLayout(presetRow);
  top->addLayout(fileRow);

  general_ = new QLabel(this);
  general_->setWordWrap(true);
  general_->setStyleSheet(QStringLiteral("color: #dc2626"));
  general_->hide();

  auto* content = new QWidget;
  auto* contentLayout = new QVBoxLayout(content);
  auto group = [&](const QString& title) {
    auto* box = new QGroupBox(title, content);
    contentLayout->addWidget(box);
    auto* form = new QFormLayout(box);
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);  // long translated labels above their field
    return form;
  };
  QFormLayout* general = group(tr("Machine"));
  name_ = new QLineEdit(content);
  general->addRow(tr("Name"), name_);
  addMessage(general, "name");
  QFormLayout* geometry = group(tr("Geometry"));
  QFormLayout* limits = group(tr("Joint limits"));
  QFormLayout* motors = group(tr("Motors"));
  QFormLayout* tool = group(tr("Tool"));
  QFormLayout* motion = group(tr("Motion and safety"));
  QFormLayout* home = group(tr("Connection and home pose"));
  buildFields(geometry, limits, motors, tool, motion, home);
  contentLayout->addStretch(1);
  auto* scroll = new QScrollArea(this);
  scroll->setWidgetResizable(true);
  scroll->setWidget(content);

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addLayout(top);
  layout->addWidget(general_);
  layout->addWidget(scroll, 1);

  connect(loadPresetButton, &QPushButton::clicked, this, [this] { loadPreset(presets_->currentText()); });
  connect(importButton, &QPushButton::clicked, this, &ProfileEditor::importClicked);
  connect(exportButton, &QPushButton::clicked, this, &ProfileEditor::exportClicked);
  connect(name_, &QLineEdit::textEdited, this, &ProfileEditor::onEdited);
  connect(&doc_, &StudioDocument::profileChanged, this, [this] {
    if (!applying_) loadFromDocument();
  });
  loadFromDocument();
}

void ProfileEditor::buildFields(QFormLayout* geometry, QFormLayout* limits, QFormLayout* motors,
                                QFormLayout* tool, QFormLayout* motion, QFormLayout* home) {
  // The rows that are not numbers, each before the numbers of its group.
  limited_ = new QCheckBox(tr("Limit the motor angles"), this);
  limits->addRow(limited_);
  toolKind_ = new QComboBox(this);
  toolKind_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  toolKind_->setMinimumContentsLength(12);
  toolKind_->addItem(tr("Pen servo (M3 S / M5)"), int(ToolKind::PenServo));
  toolKind_->addItem(tr("Z axis"), int(ToolKind::ZAxis));
  toolKind_->addItem(tr("Laser (M4 S / M5)"), int(ToolKind::Laser));
  tool->addRow(tr("Tool"), toolKind_);
  addMessage(tool, "tool.kind");
  connect(toolKind_, &QComboBox::currentIndexChanged, this, &ProfileEditor::onEdited);
  workingMode_ = new QComboBox(this);
  for (WorkingMode m : {WorkingMode::PlusPlus, WorkingMode::PlusMinus, WorkingMode::MinusPlus, WorkingMode::MinusMinus})
    workingMode_->addItem(QString::fromUtf8(toString(m).data(), qsizetype(toString(m).size())), int(m));
  motion->addRow(tr("Working mode (built)"), workingMode_);
  assembly_ = new QComboBox(this);
  for (AssemblyMode m : {AssemblyMode::Plus, AssemblyMode::Minus})
    assembly_->addItem(QString::fromUtf8(toString(m).data(), qsizetype(toString(m).size())), int(m));
  motion->addRow(tr("Assembly mode"), assembly_);
  connect(workingMode_, &QComboBox::currentIndexChanged, this, &ProfileEditor::onEdited);
  connect(assembly_, &QComboBox::currentIndexChanged, this, &ProfileEditor::onEdited);

  // Every number from core's one table of profile fields (core/machine/profile_fields.hpp):
  // label, unit, input range and decimals as the table gives them, the label translated.
  for (const ProfileField& f : profileFields()) {
    const std::string section = sectionOf(f);
    QFormLayout* form = section == "geometry"                         ? geometry
                        : section == "limits"                         ? limits
                        : section == "motors"                         ? motors
                        : section == "tool"                           ? tool
                        : section == "motion" || section == "safety"  ? motion
                        : section == "connection" || section == "home" ? home
                                                                      : nullptr;
    if (form == nullptr) continue;  // calibration: written by the calibration tools, not typed here
    addNumber(form, f.path, profileFieldLabel(f), profileUnitSuffix(f), f.inputMin, f.inputMax,
              f.decimals, [get = f.get](const MachineProfile& p) { return get(p); },
              [set = f.set](MachineProfile& p, double v) { set(p, v); });
    if (std::string_view(f.path) == "connection.baudRate") {
      homing_ = new QCheckBox(tr("The machine has homing switches ($H)"), this);
      home->addRow(homing_);
      connect(homing_, &QCheckBox::toggled, this, &ProfileEditor::onEdited);
    }
  }
  connect(limited_, &QCheckBox::toggled, this, [this](bool on) {
    for (const char* path : {"limits.theta1MinDeg", "limits.theta1MaxDeg", "limits.theta2MinDeg",
                             "limits.theta2MaxDeg"}) {
      QDoubleSpinBox* box = numberField(path);
      box->setEnabled(on);
      if (on && std::abs(box->value()) >= box->maximum())
        box->setValue(QString(path).contains(QStringLiteral("Min")) ? -kDefaultLimitDeg : kDefaultLimitDeg);
    }
    onEdited();
  });
}

void ProfileEditor::addNumber(QFormLayout* form, const std::string& path, const QString& label,
                              const QString& suffix, double min, double max, int decimals,
                              Get get, Set set) {
  auto* box = new QDoubleSpinBox(this);
  box->setObjectName(QString::fromStdString(path));
  box->setRange(min, max);
  box->setDecimals(decimals);
  box->setSuffix(suffix);
  box->setKeyboardTracking(false);  // applied when editing finishes: one undo step per change
  form->addRow(label, box);
  addMessage(form, path);
  numbers_.push_back({path, box, std::move(get), std::move(set)});
  connect(box, &QDoubleSpinBox::valueChanged, this, &ProfileEditor::onEdited);
}

QLabel* ProfileEditor::addMessage(QFormLayout* form, const std::string& path) {
  auto* label = new QLabel(this);
  label->setWordWrap(true);
  label->setStyleSheet(QStringLiteral("color: #dc2626"));
  label->hide();
  form->addRow(QString(), label);
  messages_[path] = label;
  return label;
}

QDoubleSpinBox* ProfileEditor::numberField(const std::string& path) const {
  for (const NumberField& f : numbers_)
    if (f.path == path) return f.box;
  return nullptr;
}

QLabel* ProfileEditor::messageFor(const std::string& path) const {
  const auto it = messages_.find(path);
  return it == messages_.end() ? nullptr : it->second;
}

MachineProfile ProfileEditor::editedProfile() const {
  MachineProfile p = doc_.profile();
  p.name = name_->text().toStdString();
  for (const NumberField& f : numbers_) f.set(p, f.box->value());
  if (!limited_->isChecked()) p.limits = JointLimits{};
  p.tool.kind = ToolKind(toolKind_->currentData().toInt());
  p.defaultMode = WorkingMode(workingMode_->currentData().toInt());
  p.assembly = AssemblyMode(assembly_->currentData().toInt());
  p.hasHomingSwitches = homing_->isChecked();
  return p;
}

void ProfileEditor::fill(const MachineProfile& p) {
  filling_ = true;
  name_->setText(QString::fromStdString(p.name));
  const bool limitedNow = !unlimited(p.limits);
  limited_->setChecked(limitedNow);
  for (const NumberField& f : numbers_) {
    const bool limitField = f.path.rfind("limits.", 0) == 0;
    f.box->setValue(limitField && !limitedNow ? (f.path.find("Min") != std::string::npos ? -kDefaultLimitDeg
                                                                                         : kDefaultLimitDeg)
                                              : f.get(p));
    if (limitField) f.box->setEnabled(limitedNow);
  }
  toolKind_->setCurrentIndex(toolKind_->findData(int(p.tool.kind)));
  workingMode_->setCurrentIndex(workingMode_->findData(int(p.defaultMode)));
  assembly_->setCurrentIndex(assembly_->findData(int(p.assembly)));
  homing_->setChecked(p.hasHomingSwitches);
  const int presetIndex = presets_->findText(QString::fromStdString(p.name));
  if (presetIndex >= 0) presets_->setCurrentIndex(presetIndex);
  filling_ = false;
}

void ProfileEditor::loadFromDocument() {
  fill(doc_.profile());
  showIssues(validate(doc_.profile()));
}

void ProfileEditor::loadPreset(const QString& name) {
  const auto p = preset(name.toStdString());
  if (!p) return;
  fill(*p);
  onEdited();
}

void ProfileEditor::onEdited() {
  if (filling_) return;
  const MachineProfile p = editedProfile();
  const std::vector<ValidationIssue> issues = validate(p);
  showIssues(issues);
  if (!issues.empty() || toJson(p) == toJson(doc_.profile())) return;
  applying_ = true;
  doc_.setProfile(p);
  applying_ = false;
}

void ProfileEditor::showIssues(const std::vector<ValidationIssue>& issues) {
  std::map<std::string, QStringList> byField;
  QStringList unmatched;
  for (const ValidationIssue& issue : issues) {
    const QString text = translated(issue.message);
    if (messages_.count(issue.field)) {
      byField[issue.field] << text;
    } else {
      unmatched << text;
    }
  }
  for (const auto& [path, label] : messages_) {
    const auto it = byField.find(path);
    label->setVisible(it != byField.end());
    label->setText(it != byField.end() ? it->second.join(QLatin1Char('\n')) : QString());
  }
  general_->setVisible(!unmatched.isEmpty());
  general_->setText(unmatched.join(QLatin1Char('\n')));
  valid_ = issues.empty();
  if (!valid_) {
    general_->setVisible(true);
    const QString note = tr("The profile is not applied until these problems are fixed.");
    general_->setText(unmatched.isEmpty() ? note : unmatched.join(QLatin1Char('\n')) + QLatin1Char('\n') + note);
  }
}

bool ProfileEditor::importFrom(const QString& path, QString* error) {
  const ProfileLoad load = loadProfile(path.toStdString());
  if (!load.profile) {
    QStringList lines;
    for (const ValidationIssue& issue : load.issues) lines << translated(issue.message);
    *error = tr("%1 cannot be used:\n%2").arg(path, lines.join(QLatin1Char('\n')));
    return false;
  }
  fill(*load.profile);
  onEdited();
  return true;
}

bool ProfileEditor::exportTo(const QString& path, QString* error) const {
  const MachineProfile p = editedProfile();
  if (!validate(p).empty()) {
    *error = tr("Fix the profile's problems before exporting it.");
    return false;
  }
  const std::string why = saveProfile(p, path.toStdString());
  if (!why.empty()) *error = QString::fromStdString(why);
  return why.empty();
}

void ProfileEditor::importClicked() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Import machine profile"), QString(),
                                                    tr("Machine profiles (*.json)"));
  if (path.isEmpty()) return;
  QString error;
  if (!importFrom(path, &error)) QMessageBox::warning(this, tr("Import failed"), error);
}

void ProfileEditor::exportClicked() {
  QString path = QFileDialog::getSaveFileName(this, tr("Export machine profile"),
                                              QString::fromStdString(editedProfile().name) + QStringLiteral(".json"),
                                              tr("Machine profiles (*.json)"));
  if (path.isEmpty()) return;
  QString error;
  if (!exportTo(path, &error)) QMessageBox::warning(this, tr("Export failed"), error);
}

}  // namespace fivebar::widgets
