#include "widgets/panels/profile_editor.hpp"

#include <QCheckBox>
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

#include "core/machine/profile.hpp"
#include "core/kinematics/units.hpp"

namespace fivebar::widgets {
namespace {

constexpr double kLengthMaxMm = 10000.0;
constexpr double kDefaultLimitDeg = 180.0;  // limits offered when "joint limits" is switched on

bool unlimited(const JointLimits& l) {
  return l.theta1Max >= JointLimits::kDefaultSpan && l.theta2Max >= JointLimits::kDefaultSpan;
}

using Get = std::function<double(const MachineProfile&)>;
using Set = std::function<void(MachineProfile&, double)>;

// Accessors for an angle stored in radians and edited in degrees.
std::pair<Get, Set> degrees(double MachineProfile::*member) {
  return {[member](const MachineProfile& p) { return degFromRad(p.*member); },
          [member](MachineProfile& p, double v) { p.*member = radFromDeg(v); }};
}

}  // namespace

ProfileEditor::ProfileEditor(StudioDocument& doc, QWidget* parent) : QWidget(parent), doc_(doc) {
  setObjectName(QStringLiteral("profileEditor"));
  presets_ = new QComboBox(this);
  for (const std::string& name : presetNames()) presets_->addItem(QString::fromStdString(name));
  auto* loadPresetButton = new QPushButton(tr("Load preset"), this);
  auto* importButton = new QPushButton(tr("Import…"), this);
  importButton->setToolTip(tr("Load a machine profile from a JSON file"));
  auto* exportButton = new QPushButton(tr("Export…"), this);
  exportButton->setToolTip(tr("Save this machine profile as a JSON file"));
  auto* top = new QHBoxLayout;
  top->addWidget(presets_, 1);
  top->addWidget(loadPresetButton);
  top->addWidget(importButton);
  top->addWidget(exportButton);

  general_ = new QLabel(this);
  general_->setWordWrap(true);
  general_->setStyleSheet(QStringLiteral("color: #dc2626"));
  general_->hide();

  auto* content = new QWidget;
  auto* contentLayout = new QVBoxLayout(content);
  auto group = [&](const QString& title) {
    auto* box = new QGroupBox(title, content);
    contentLayout->addWidget(box);
    return new QFormLayout(box);
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
  const QString mm = tr(" mm"), deg = tr(" °"), s = tr(" s");
  auto length = [&](const char* path, const QString& label, double Geometry::*member) {
    addNumber(geometry, path, label, mm, -kLengthMaxMm, kLengthMaxMm, 2,
              [member](const MachineProfile& p) { return p.geometry.*member; },
              [member](MachineProfile& p, double v) { p.geometry.*member = v; });
  };
  length("geometry.a1", tr("Driving link a1"), &Geometry::a1);
  length("geometry.b1", tr("Floating link b1"), &Geometry::b1);
  length("geometry.a2", tr("Driving link a2"), &Geometry::a2);
  length("geometry.b2", tr("Floating link b2"), &Geometry::b2);
  length("geometry.w", tr("Motor distance w"), &Geometry::w);

  limited_ = new QCheckBox(tr("Limit the motor angles"), this);
  limits->addRow(limited_);
  auto limit = [&](const char* path, const QString& label, double JointLimits::*member) {
    addNumber(limits, path, label, deg, -3600.0, 3600.0, 3,
              [member](const MachineProfile& p) { return degFromRad(p.limits.*member); },
              [member](MachineProfile& p, double v) { p.limits.*member = radFromDeg(v); });
  };
  limit("limits.theta1MinDeg", tr("θ1 minimum"), &JointLimits::theta1Min);
  limit("limits.theta1MaxDeg", tr("θ1 maximum"), &JointLimits::theta1Max);
  limit("limits.theta2MinDeg", tr("θ2 minimum"), &JointLimits::theta2Min);
  limit("limits.theta2MaxDeg", tr("θ2 maximum"), &JointLimits::theta2Max);
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

  auto motor = [&](const char* path, const QString& label, const QString& suffix, int decimals,
                   Get get, Set set) { addNumber(motors, path, label, suffix, -1e6, 1e6, decimals, get, set); };
  motor("motors.stepsPerDeg1", tr("Motor 1 steps per degree"), QString(), 4,
        [](const MachineProfile& p) { return p.motors.stepsPerDeg1; },
        [](MachineProfile& p, double v) { p.motors.stepsPerDeg1 = v; });
  motor("motors.stepsPerDeg2", tr("Motor 2 steps per degree"), QString(), 4,
        [](const MachineProfile& p) { return p.motors.stepsPerDeg2; },
        [](MachineProfile& p, double v) { p.motors.stepsPerDeg2 = v; });
  motor("motors.maxSpeedDegPerMin1", tr("Motor 1 maximum speed"), tr(" °/min"), 0,
        [](const MachineProfile& p) { return degFromRad(p.motors.maxSpeedRadPerS1) * 60.0; },
        [](MachineProfile& p, double v) { p.motors.maxSpeedRadPerS1 = radFromDeg(v / 60.0); });
  motor("motors.maxSpeedDegPerMin2", tr("Motor 2 maximum speed"), tr(" °/min"), 0,
        [](const MachineProfile& p) { return degFromRad(p.motors.maxSpeedRadPerS2) * 60.0; },
        [](MachineProfile& p, double v) { p.motors.maxSpeedRadPerS2 = radFromDeg(v / 60.0); });
  motor("motors.maxAccelDegPerS2_1", tr("Motor 1 acceleration"), tr(" °/s²"), 1,
        [](const MachineProfile& p) { return degFromRad(p.motors.maxAccelRadPerS2_1); },
        [](MachineProfile& p, double v) { p.motors.maxAccelRadPerS2_1 = radFromDeg(v); });
  motor("motors.maxAccelDegPerS2_2", tr("Motor 2 acceleration"), tr(" °/s²"), 1,
        [](const MachineProfile& p) { return degFromRad(p.motors.maxAccelRadPerS2_2); },
        [](MachineProfile& p, double v) { p.motors.maxAccelRadPerS2_2 = radFromDeg(v); });
  motor("motors.junctionDeviationDeg", tr("Junction deviation"), deg, 3,
        [](const MachineProfile& p) { return p.motors.junctionDeviationDeg; },
        [](MachineProfile& p, double v) { p.motors.junctionDeviationDeg = v; });

  toolKind_ = new QComboBox(this);
  toolKind_->addItem(tr("Pen servo (M3 S / M5)"), int(ToolKind::PenServo));
  toolKind_->addItem(tr("Z axis"), int(ToolKind::ZAxis));
  toolKind_->addItem(tr("Laser (M4 S / M5)"), int(ToolKind::Laser));
  tool->addRow(tr("Tool"), toolKind_);
  addMessage(tool, "tool.kind");
  connect(toolKind_, &QComboBox::currentIndexChanged, this, &ProfileEditor::onEdited);
  auto toolNumber = [&](const char* path, const QString& label, const QString& suffix, double min,
                        double max, int decimals, double ToolSettings::*member) {
    addNumber(tool, path, label, suffix, min, max, decimals,
              [member](const MachineProfile& p) { return p.tool.*member; },
              [member](MachineProfile& p, double v) { p.tool.*member = v; });
  };
  toolNumber("tool.penUpS", tr("Pen up S value"), QString(), -1e5, 1e5, 0, &ToolSettings::penUpS);
  toolNumber("tool.penDownS", tr("Pen down S value"), QString(), -1e5, 1e5, 0, &ToolSettings::penDownS);
  toolNumber("tool.penUpDelayS", tr("Pen up delay"), s, -100, 100, 2, &ToolSettings::penUpDelayS);
  toolNumber("tool.penDownDelayS", tr("Pen down delay"), s, -100, 100, 2, &ToolSettings::penDownDelayS);
  toolNumber("tool.zUpMm", tr("Z up"), mm, -1000, 1000, 2, &ToolSettings::zUpMm);
  toolNumber("tool.zDownMm", tr("Z down"), mm, -1000, 1000, 2, &ToolSettings::zDownMm);
  toolNumber("tool.zFeedMmPerMin", tr("Z feed"), tr(" mm/min"), -1e5, 1e5, 0, &ToolSettings::zFeedMmPerMin);
  toolNumber("tool.laserPowerS", tr("Laser power S value"), QString(), -1e5, 1e5, 0, &ToolSettings::laserPowerS);

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
  addNumber(motion, "motion.drawSpeedMmPerS", tr("Drawing speed"), tr(" mm/s"), -1e4, 1e4, 1,
            [](const MachineProfile& p) { return p.drawSpeedMmPerS; },
            [](MachineProfile& p, double v) { p.drawSpeedMmPerS = v; });
  addNumber(motion, "motion.travelSpeedMmPerS", tr("Travel speed"), tr(" mm/s"), -1e4, 1e4, 1,
            [](const MachineProfile& p) { return p.travelSpeedMmPerS; },
            [](MachineProfile& p, double v) { p.travelSpeedMmPerS = v; });
  const auto [getII, setII] = degrees(&MachineProfile::typeIIMarginRad);
  addNumber(motion, "safety.typeIIMarginDeg", tr("Type II singularity margin"), deg, -180, 180, 2, getII, setII);
  const auto [getI, setI] = degrees(&MachineProfile::typeIMarginRad);
  addNumber(motion, "safety.typeIMarginDeg", tr("Type I singularity margin"), deg, -180, 180, 2, getI, setI);

  addNumber(home, "connection.baudRate", tr("Baud rate"), QString(), -1e7, 1e7, 0,
            [](const MachineProfile& p) { return double(p.baudRate); },
            [](MachineProfile& p, double v) { p.baudRate = int(v); });
  homing_ = new QCheckBox(tr("The machine has homing switches ($H)"), this);
  home->addRow(homing_);
  connect(homing_, &QCheckBox::toggled, this, &ProfileEditor::onEdited);
  addNumber(home, "home.theta1Deg", tr("Home θ1"), deg, -3600, 3600, 4,
            [](const MachineProfile& p) { return degFromRad(p.homeAngles.theta1); },
            [](MachineProfile& p, double v) { p.homeAngles.theta1 = radFromDeg(v); });
  addNumber(home, "home.theta2Deg", tr("Home θ2"), deg, -3600, 3600, 4,
            [](const MachineProfile& p) { return degFromRad(p.homeAngles.theta2); },
            [](MachineProfile& p, double v) { p.homeAngles.theta2 = radFromDeg(v); });
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
    const QString text = QString::fromStdString(issue.message);
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
    for (const ValidationIssue& issue : load.issues) lines << QString::fromStdString(issue.message);
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
