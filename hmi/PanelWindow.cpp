#include "hmi/PanelWindow.h"

#include <QCloseEvent>
#include <QHBoxLayout>
#include <QMessageBox>
#include <QScreen>
#include <QSettings>
#include <QShortcut>
#include <QStackedWidget>
#include <QVBoxLayout>

#include "cnc_core/cell/StationStatus.h"
#include "hmi/CellSession.h"
#include "hmi/KeyMap.h"
#include "hmi/MachineKeyBar.h"
#include "hmi/NcOptionsHolder.h"
#include "hmi/PanelStyle.h"
#include "hmi/Screen.h"
#include "hmi/ScreenRegistry.h"
#include "hmi/SoftKeyBar.h"
#include "hmi/StatusHeader.h"

namespace mtc::hmi {

namespace {
const QString kMenuScreen = "menu";
const QString kHelpScreen = "help";
const QString kRestartScreen = "restart";
const QString kReposScreen = "repos";
const QString kBaseScreen = "position";
const QString kProgramsScreen = "programs";
}  // namespace

PanelWindow::PanelWindow(CellSession* session, const ScreenRegistry* registry, QWidget* parent)
    : QMainWindow(parent), session_(session), registry_(registry) {
    setObjectName("panelWindow");
    setWindowTitle(tr("MTC200 panel simulator"));
    setStyleSheet(panelStyleSheet());
    auto* central = new QWidget(this);
    auto* outer = new QVBoxLayout(central);
    outer->setContentsMargins(4, 4, 4, 4);
    header_ = new StatusHeader(central);
    outer->addWidget(header_);
    auto* middle = new QHBoxLayout;
    stationStack_ = new QStackedWidget(central);
    stationStack_->setObjectName("stationStack");
    middle->addWidget(stationStack_, 1);
    machineKeys_ = new MachineKeyBar(central);
    machineKeys_->setObjectName("machineKeyBar");
    middle->addWidget(machineKeys_);
    outer->addLayout(middle, 1);
    softKeys_ = new SoftKeyBar(central);
    softKeys_->setObjectName("softKeyBar");
    outer->addWidget(softKeys_);
    setCentralWidget(central);
    resize(1024, 720);

    buildStations();
    installShortcuts();
    connect(machineKeys_, &MachineKeyBar::keyPressed, this, &PanelWindow::onMachineKey);
    connect(machineKeys_, &MachineKeyBar::speedPressed, session_, &CellSession::cycleSpeed);
    connect(machineKeys_, &MachineKeyBar::overrideStep, this, &PanelWindow::stepOverride);
    connect(session_, &CellSession::speedChanged, this, [this] {
        machineKeys_->setSpeedText(session_->speedText());
        refresh();
    });
    machineKeys_->setSpeedText(session_->speedText());
    connect(session_, &CellSession::processChanged, this, [this](int slot) {
        if (slot == station_) refresh();
    });
    session_->ncOptions().setUserCompilerAsker(
        [this](int slot, const QString& command, const QString& folder) {
            return askToRunUserCompiler(slot, command, folder);
        });
    showStation(0);
}

bool PanelWindow::askToRunUserCompiler(int slot, const QString& command, const QString& folder) {
    // D-010: the operator sees the whole command before anything of a
    // program folder runs with their rights; No is the default and Escape.
    QMessageBox box(QMessageBox::Warning, tr("User compiler from the program folder"),
                    tr("User compiler %1 of the program folder\n%2\nwants to run this "
                       "command (from its %3):\n\n%4\n\nIt did not come from this desk. "
                       "Run it now and from now on for this folder?")
                        .arg(slot)
                        .arg(folder, "NC_OPTIONS.CFG", command),
                    QMessageBox::Yes | QMessageBox::No, this);
    box.setObjectName("userCompilerQuestion");
    box.setDefaultButton(QMessageBox::No);
    box.setEscapeButton(QMessageBox::No);
    return box.exec() == QMessageBox::Yes;
}

void PanelWindow::buildStations() {
    for (int slot = 0; slot < session_->processCount(); ++slot) {
        auto* page = new QStackedWidget(stationStack_);
        page->setObjectName(QString("station%1").arg(slot));
        stationStack_->addWidget(page);
        stationPages_.push_back(page);
        screens_.push_back({});
        currentScreen_.push_back(kMenuScreen);
        previousScreen_.push_back({});
        ScreenContext context{session_, slot,
                              [this, slot] {
                                  QVector<Screen*> list;
                                  for (Screen* s : screens_[slot])
                                      list.push_back(s);
                                  return list;
                              },
                              [this, slot] { return previousScreen_.value(slot); }};
        for (const auto& entry : registry_->entries()) {
            Screen* screen = entry.factory(context);
            screen->setObjectName(entry.name);
            page->addWidget(screen);
            screens_[slot].insert(entry.name, screen);
            connect(screen, &Screen::softKeysChanged, this, [this, screen] {
                if (screen == currentScreen()) refresh();
            });
            connect(screen, &Screen::navigateTo, this,
                    [this](const QString& name) { showScreen(name); });
        }
    }
}

void PanelWindow::installShortcuts() {
    for (int i = 0; i < 8; ++i) {
        auto* shortcut = new QShortcut(QKeySequence(Qt::Key_F1 + i), this);
        connect(shortcut, &QShortcut::activated, this, [this, i] { softKeys_->trigger(i); });
    }
    auto add = [this](const QKeySequence& keys, auto slot) {
        auto* shortcut = new QShortcut(keys, this);
        connect(shortcut, &QShortcut::activated, this, slot);
    };
    add(QKeySequence(Qt::Key_Escape), [this] { showScreen(kMenuScreen); });
    add(QKeySequence(Qt::Key_F12), [this] { showScreen(kHelpScreen); });
    add(baseScreenShortcut(), [this] { showScreen(kBaseScreen); });
    add(stationShortcut(-1), [this] { showStation(station_ - 1); });
    add(stationShortcut(+1), [this] { showStation(station_ + 1); });
    for (mtc::core::ControlKey key : machineKeys())
        add(machineKeyShortcut(key), [this, key] { onMachineKey(key); });
    add(speedKeyShortcut(), [this] { session_->cycleSpeed(); });
    for (int direction : {1, -1}) {
        add(feedOverrideShortcut(direction), [this, direction] { stepOverride(false, direction); });
        add(rapidOverrideShortcut(direction), [this, direction] { stepOverride(true, direction); });
    }
}

bool PanelWindow::showScreen(const QString& name) {
    Screen* target = screen(station_, name);
    if (!target) return false;
    if (currentScreen_[station_] != name) previousScreen_[station_] = currentScreen_[station_];
    currentScreen_[station_] = name;
    stationPages_[station_]->setCurrentWidget(target);
    target->activated();
    target->setFocus();
    refresh();
    return true;
}

bool PanelWindow::showScreenOnEveryStation(const QString& name) {
    for (int slot = 0; slot < screens_.size(); ++slot) {
        Screen* target = screen(slot, name);
        if (!target) return false;
        currentScreen_[slot] = name;
        stationPages_[slot]->setCurrentWidget(target);
    }
    showStation(station_);
    return true;
}

void PanelWindow::showStation(int slot) {
    const int count = session_->processCount();
    if (count == 0) return;
    station_ = ((slot % count) + count) % count;
    stationStack_->setCurrentIndex(station_);
    showScreen(currentScreen_[station_]);
}

QString PanelWindow::currentScreenName() const {
    return currentScreen_.value(station_);
}

Screen* PanelWindow::currentScreen() const {
    return screen(station_, currentScreenName());
}

Screen* PanelWindow::screen(int slot, const QString& name) const {
    if (slot < 0 || slot >= screens_.size()) return nullptr;
    return screens_[slot].value(name, nullptr);
}

void PanelWindow::refresh() {
    Screen* current = currentScreen();
    header_->show(*session_, station_, current ? current->title() : QString());
    const auto& station = session_->station(station_);
    for (mtc::core::ControlKey key : machineKeys())
        machineKeys_->setLamp(key, mtc::core::keyLamp(station, key));
    machineKeys_->setOverrides(station.feedOverride(), station.rapidOverride());
    softKeys_->setKeys(current ? current->softKeys() : SoftKeys{});
}

void PanelWindow::stepOverride(bool rapid, int direction) {
    mtc::core::Station& station = session_->station(station_);
    if (rapid)
        station.stepRapidOverride(direction);
    else
        station.stepFeedOverride(direction);
    session_->notifyChanged(station_);
}

void PanelWindow::onMachineKey(mtc::core::ControlKey key) {
    const bool accepted = session_->pressKey(station_, key);
    // The M key 'NC program restart' brings up the restart screen (seed 000, 2.2).
    if (accepted && key == mtc::core::ControlKey::ProgramRestart) showScreen(kRestartScreen);
    // REPOS during a restart's repositioning phase: the SPS sets PxxCREPOS,
    // which brings up the repositioning screen (seed 000, Fig. 7-14 rung 6).
    if (accepted && key == mtc::core::ControlKey::Repos) showScreen(kReposScreen);
    // A program started from the menu or the program directory is watched
    // on the base screen (D-014); other screens (MDI, restart) stay.
    const QString current = currentScreenName();
    if (accepted && key == mtc::core::ControlKey::Start &&
        (current == kMenuScreen || current == kProgramsScreen))
        showScreen(kBaseScreen);
}

void PanelWindow::restoreSettings() {
    QSettings settings;
    if (!restoreGeometry(settings.value("window/geometry").toByteArray())) fitIntoScreen();
    for (int slot = 0; slot < screens_.size(); ++slot) {
        const QString name = settings.value(QString("station%1/screen").arg(slot)).toString();
        if (screens_[slot].contains(name)) currentScreen_[slot] = name;
    }
    showStation(settings.value("window/station", 0).toInt());
}

void PanelWindow::fitIntoScreen() {
    // The default size is in logical pixels: at 144 dpi the panel scales by
    // 1.5, so 1024 x 720 would open as 1536 x 1080 and hang off a 1280 x 1024
    // screen with the machine keys and soft keys cut off. The window never
    // goes below what its contents need (Qt keeps the minimum size).
    const QScreen* where = QWidget::screen();  // not the panel's Screen lookup
    if (!where) return;
    resize(size().boundedTo(where->availableGeometry().size()).expandedTo(minimumSizeHint()));
}

void PanelWindow::saveSettings() const {
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/station", station_);
    for (int slot = 0; slot < currentScreen_.size(); ++slot)
        settings.setValue(QString("station%1/screen").arg(slot), currentScreen_[slot]);
}

void PanelWindow::closeEvent(QCloseEvent* event) {
    saveSettings();
    event->accept();
}

}  // namespace mtc::hmi
