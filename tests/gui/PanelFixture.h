#pragma once

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QListView>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <memory>

#include "hmi/CellSession.h"
#include "hmi/PanelLanguage.h"
#include "hmi/PanelStartup.h"
#include "hmi/PanelWindow.h"
#include "hmi/ScreenRegistry.h"
#include "screens/ScreenCatalog.h"
#include "screens/programs/ProgramDirectoryModel.h"

/// The real panel on the built-in demo cell, shown and active, for QtTest.
struct PanelFixture {
    mtc::hmi::ScreenRegistry registry;
    std::unique_ptr<mtc::hmi::CellSession> session;
    std::unique_ptr<mtc::hmi::PanelWindow> window;

    explicit PanelFixture(const mtc::hmi::PanelOptions& options = {}) {
        QString error;
        // The panel's language as main() installs it: English unless the
        // test asks for another (--lang), whatever the desk's locale.
        if (!mtc::hmi::installPanelTranslation(
                options.language.isEmpty() ? QString("en") : options.language, error))
            qFatal("%s", qPrintable(error));
        session = mtc::hmi::createSession(options, error);
        if (!session) qFatal("cannot create the demo cell: %s", qPrintable(error));
        mtc::screens::registerAllScreens(registry);
        window = std::make_unique<mtc::hmi::PanelWindow>(session.get(), &registry);
        window->show();
        QApplication::setActiveWindow(window.get());
        if (!QTest::qWaitForWindowActive(window.get())) qWarning("panel window not active");
    }

    /// Presses a key on whatever has the focus in the panel (as a user would).
    void press(int key, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
        QWidget* target = QApplication::focusWidget();
        QTest::keyClick(target ? target : window.get(), static_cast<Qt::Key>(key), modifiers);
    }
};

/// Settings go to a throw-away location of their own for every test process:
/// test mode alone puts them in one file under ~/.qttest that every test
/// binary of every worktree shares, so a parallel run's QSettings().clear()
/// could wipe this run's user compiler approvals (D-010) mid-test.
inline void useTestSettings() {
    QStandardPaths::setTestModeEnabled(true);
    QApplication::setOrganizationName("MTC200SimTest");
    QApplication::setApplicationName("mtc200-panel-test");
    static QTemporaryDir settingsDirectory;
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settingsDirectory.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDirectory.path());
}

/// The directory at `path` with its files removed (each test case starts
/// from its own programs only).
inline QDir emptiedDirectory(const QString& path) {
    QDir dir(path);
    for (const QString& name : dir.entryList(QDir::Files))
        dir.remove(name);
    return dir;
}

/// Writes NC program `number` of plant 1, package 01, process 0 into `dir`.
inline void writeProgram(const QDir& dir, int number, const QString& text) {
    QFile file(dir.filePath(QString("N1010%1.DAT").arg(number, 3, 10, QChar('0'))));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(text.toUtf8());
}

/// Writes the program directory's global macro file (GM-005) with `text`.
inline void writeGlobalMacros(const QDir& dir, const QString& text) {
    QFile file(dir.filePath("GLOBAL_MACROS.MAC"));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(text.toUtf8());
}

/// The child `name` of station 0's screen `screen`.
template <typename T>
T* child(PanelFixture& panel, const char* screen, const char* name) {
    return panel.window->screen(0, screen)->findChild<T*>(name);
}

/// Header lines of test program `number` (plant 1, package 01, process 0)
/// with `title`; the blocks follow.
inline QString programHeader(int number, const char* title) {
    return QString(
               "iMTc/01%1/01.00/0000000000/21.11.2026/15:00:00/N1010%1.DAT/1\n"
               "%NPG:1:01:0:%1\n!01.00\n#01%2\n$\n$\n$\n$\n*%2\n%NPG\n")
        .arg(number, 3, 10, QChar('0'))
        .arg(title);
}

/// Shows the program directory and puts its cursor on program `number`.
inline void pickProgram(PanelFixture& panel, int number) {
    panel.window->showScreen("programs");
    auto* list = child<QListView>(panel, "programs", "programList");
    const auto* model = qobject_cast<const mtc::screens::ProgramDirectoryModel*>(list->model());
    QVERIFY(model && model->rowOf(number) >= 0);
    list->setCurrentIndex(model->index(model->rowOf(number)));
}

/// The program directory's row text of program `number` (with its N/C/E).
inline QString directoryRow(PanelFixture& panel, int number) {
    auto* list = child<QListView>(panel, "programs", "programList");
    const auto* model = qobject_cast<const mtc::screens::ProgramDirectoryModel*>(list->model());
    return model->index(model->rowOf(number)).data().toString();
}

/// The scale `widget` is drawn at, checked against how ctest set it (144
/// dpi as QT_FONT_DPI or as QT_SCALE_FACTOR 1.5: the panel scales by the
/// screen's dpi), and the device-pixel width of a 1-px line of the toolpath
/// view then (TP-026): 1 at 96 dpi (100 offscreen), 2 at 144 (1.5 -> 2).
/// Callers check QTest::currentTestFailed() after it.
inline void lineWidthAtScale(const QWidget& widget, double& ratio, int& expectedWidth) {
    const int dpi = widget.logicalDpiY();
    ratio = widget.devicePixelRatioF();
    expectedWidth = dpi * ratio >= 144 ? 2 : 1;
    if (qEnvironmentVariableIsSet("QT_FONT_DPI"))
        QCOMPARE(dpi, qEnvironmentVariableIntValue("QT_FONT_DPI"));
    if (qEnvironmentVariableIsSet("QT_SCALE_FACTOR"))
        QCOMPARE(ratio, qEnvironmentVariable("QT_SCALE_FACTOR").toDouble());
}
