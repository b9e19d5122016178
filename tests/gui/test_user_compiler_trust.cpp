// No commands from untrusted folders (issue 22 §5, docs/DECISIONS.md D-010):
// a user compiler command that came with a program folder's NC_OPTIONS.CFG
// is shown to the operator before it runs; refusing does not run it, an
// approval is remembered for the folder; a command typed at this desk runs
// without a question.
#include <QAbstractButton>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QListView>
#include <QListWidget>
#include <QMessageBox>
#include <QTemporaryDir>
#include <QTimer>

#include "PanelFixture.h"
#include "cnc_core/compiler/NcOptions.h"
#include "hmi/NcOptionsHolder.h"
#include "hmi/UserCompilerTrust.h"

namespace {

const char* kPlain =
    "N0000 G0 G90 X0 Y0 Z0\n"
    "N0001 G1 X10 F500\n"
    "N0002 M30\n"
    "N0003 PROGRAMMENDE\n";

/// What the operator does with the question when it comes.
struct Answer {
    bool yes = false;
    bool asked = false;
    QString text;
    QString name;  ///< objectName of the question box
};

/// Answers the user compiler question with keys as soon as it is shown
/// (looks every 20 ms, for at most 10 s: a question that never comes fails
/// the test's QTRY_VERIFY(asked) instead of leaving a timer behind forever).
void answerWhenAsked(Answer& answer, int triesLeft = 500) {
    QTimer::singleShot(20, [&answer, triesLeft] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box) {
            if (triesLeft > 0) answerWhenAsked(answer, triesLeft - 1);  // not shown yet
            return;
        }
        answer.asked = true;
        answer.text = box->text();
        answer.name = box->objectName();
        // Keys on the box's own widgets: a mnemonic (Alt+Y) needs the box to
        // be the active window, which an offscreen run under load may not
        // give it, and the panel would then wait in the question forever.
        if (answer.yes)
            QTest::keyClick(box->button(QMessageBox::Yes), Qt::Key_Space);
        else
            QTest::keyClick(box, Qt::Key_Escape);
    });
}

}  // namespace

/// A folder as it comes from a USB stick: program 9 and an NC_OPTIONS.CFG
/// whose user compiler 1 copies the program and leaves a marker file.
struct StickFolder {
    QTemporaryDir dir;
    QString path(const QString& name) const { return QDir(dir.path()).filePath(name); }
    QString marker() const { return path("COMPILER_RAN"); }
    QString command() const {
        return QString("sh -c 'cp \"$0\" \"$1\" && touch %1'").arg(marker());
    }
    mtc::hmi::PanelOptions options() const {
        mtc::hmi::PanelOptions o;
        o.programsDir = dir.path();
        return o;
    }
    StickFolder() {
        writeProgram(QDir(dir.path()), 9, programHeader(9, "Plain") + kPlain);
        QFile options(path("NC_OPTIONS.CFG"));
        if (options.open(QIODevice::WriteOnly))
            options.write(
                QString("COMPILER_ACTIVE = YES\nUSER_COMPILER_1 = %1\n").arg(command()).toUtf8());
    }
};

QStringList errorTexts(PanelFixture& panel) {
    panel.window->showScreen("errors");
    auto* list = panel.window->screen(0, "errors")->findChild<QListWidget*>("errorList");
    QStringList texts;
    for (int row = 0; list && row < list->count(); ++row)
        texts << list->item(row)->text() << list->item(row)->toolTip();
    return texts;
}

class UserCompilerTrustTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    void aCommandOfTheFolderIsShownAndRefusingDoesNotRunIt() {
        StickFolder stick;
        PanelFixture panel(stick.options());
        panel.window->showScreen("nc-options");
        auto* list = child<QListView>(panel, "nc-options", "ncoList");
        const QString row = list->model()->index(1, 0).data().toString();
        QVERIFY2(row.contains("asks before it runs"), qPrintable(row));

        Answer no;
        answerWhenAsked(no);
        pickProgram(panel, 9);
        panel.press(Qt::Key_F3);  // Compile
        QTRY_VERIFY(no.asked);
        QCOMPARE(no.name, QString("userCompilerQuestion"));
        QVERIFY2(no.text.contains(stick.command()), qPrintable(no.text));
        QVERIFY2(no.text.contains(stick.dir.path()), qPrintable(no.text));
        QTRY_VERIFY2(directoryRow(panel, 9).contains("[E]"), qPrintable(directoryRow(panel, 9)));
        QVERIFY(!QFile::exists(stick.marker()));
        QVERIFY(!QFile::exists(stick.path("N1010009.NCO")));
        const QStringList errors = errorTexts(panel);
        QVERIFY2(errors.join('\n').contains("not approved"), qPrintable(errors.join('\n')));
        QVERIFY(!panel.session->ncOptions().userCompilerApproved(1));
    }

    void anApprovalIsRememberedForTheFolder() {
        StickFolder stick;
        {
            PanelFixture panel(stick.options());
            Answer yes;
            yes.yes = true;
            answerWhenAsked(yes);
            pickProgram(panel, 9);
            panel.press(Qt::Key_F3);
            QTRY_VERIFY(yes.asked);
            QCOMPARE(yes.name, QString("userCompilerQuestion"));
            QTRY_VERIFY2(directoryRow(panel, 9).contains("[C]"),
                         qPrintable(directoryRow(panel, 9)));
            QVERIFY(QFile::exists(stick.marker()));
        }
        QFile::remove(stick.marker());
        PanelFixture panel(stick.options());  // the next start of the panel
        QVERIFY(panel.session->ncOptions().userCompilerApproved(1));
        bool asked = false;
        QTimer watch;  // a question now would be a failure
        QObject::connect(&watch, &QTimer::timeout, [&asked] {
            if (auto* box = QApplication::activeModalWidget()) {
                asked = true;
                box->close();
            }
        });
        watch.start(10);
        pickProgram(panel, 9);
        panel.press(Qt::Key_F3);
        // The .NCO of the first start says C already; the compile runs in
        // the background (D-019) and leaves its marker when done.
        QTRY_VERIFY(!panel.session->cell().compilation(0).anyCompiling());
        QVERIFY(QFile::exists(stick.marker()));
        QVERIFY2(directoryRow(panel, 9).contains("[C]"), qPrintable(directoryRow(panel, 9)));
        QVERIFY(!asked);
    }

    void anotherCommandInTheSameFolderAsksAgainATypedOneDoesNot() {
        StickFolder stick;
        QFile options(stick.path("NC_OPTIONS.CFG"));
        QVERIFY(options.open(QIODevice::WriteOnly));
        options.write("COMPILER_ACTIVE = YES\nUSER_COMPILER_2 = sh -c 'exit 0'\n");
        options.close();
        PanelFixture panel(stick.options());
        QVERIFY(!panel.session->ncOptions().userCompilerApproved(2));
        // Typed on the NC options screen at this desk (user compiler 3): no question.
        panel.window->showScreen("nc-options");
        for (int i = 0; i < 4; ++i)
            panel.press(Qt::Key_Down);  // rows: active, 1, 2, INDRAMAT, 3
        panel.press(Qt::Key_Return);
        auto* editor = child<QLineEdit>(panel, "nc-options", "ncoEditor");
        QTRY_VERIFY(editor->hasFocus());
        QTest::keyClicks(editor, "true");
        QTest::keyClick(editor, Qt::Key_Return);
        QTRY_COMPARE(mtc::core::userCompilerCommand(panel.session->ncOptions().userCompilers(), 3),
                     std::string("true"));
        QVERIFY(panel.session->ncOptions().userCompilerApproved(3));
        QVERIFY(!panel.session->ncOptions().userCompilerApproved(2));
    }
    void thePanelStaysUsableWhileAUserCompilerRuns() {
        // D-019: the user compiler waits until the test opens its gate; the
        // panel meanwhile takes keys, refuses Start with a reason, and shows
        // status C once the compiler is done.
        StickFolder stick;
        const QString gate = stick.path("GATE");
        QFile options(stick.path("NC_OPTIONS.CFG"));
        QVERIFY(options.open(QIODevice::WriteOnly));
        options.write(QString("COMPILER_ACTIVE = YES\nUSER_COMPILER_1 = sh -c 'while [ ! -e "
                              "%1 ]; do sleep 0.01; done' gate\n")
                          .arg(gate)
                          .toUtf8());
        options.close();
        mtc::hmi::UserCompilerTrust::trustFolder(QDir(stick.dir.path()).canonicalPath());
        PanelFixture panel(stick.options());
        pickProgram(panel, 9);
        panel.press(Qt::Key_F3);  // Compile: returns at once
        auto* message = child<QLabel>(panel, "programs", "programsMessage");
        QVERIFY2(message->text().contains("user compilers run"), qPrintable(message->text()));
        QVERIFY2(directoryRow(panel, 9).contains("[N]"), qPrintable(directoryRow(panel, 9)));
        panel.session->selectProgram(0, 9);
        QVERIFY(!panel.session->station(0).press(mtc::core::ControlKey::Start));
        QVERIFY2(QString::fromStdString(panel.session->station(0).control().alarm())
                     .contains("being compiled"),
                 panel.session->station(0).control().alarm().c_str());
        panel.window->showScreen("errors");  // the panel goes on working
        QCOMPARE(panel.window->currentScreenName(), QString("errors"));
        QFile open(gate);
        QVERIFY(open.open(QIODevice::WriteOnly));
        open.close();
        QTRY_VERIFY2(directoryRow(panel, 9).contains("[C]"), qPrintable(directoryRow(panel, 9)));
    }
};

QTEST_MAIN(UserCompilerTrustTest)
#include "test_user_compiler_trust.moc"
