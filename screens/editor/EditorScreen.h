#pragma once

#include <memory>

#include "cnc_core/language/Program.h"
#include "hmi/Screen.h"

class QLabel;

namespace mtc::hmi {
class ProgramWorkspace;
}

namespace mtc::screens {

class NcCodeEdit;

/// Full-screen program editor (seed 001): the NC source of one program with
/// syntax highlighting and line numbers, the block under the cursor, Save
/// (atomic, through the workspace), Compile, Ctrl+E error display, the GNE
/// soft key and the runtime view. Which program it shows comes from the
/// workspace (program directory, error window).
class EditorScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    EditorScreen(const mtc::hmi::ScreenContext& context,
                 std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace);
    QString screenName() const override { return "editor"; }
    QString title() const override;
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

    /// Program shown (0 = none).
    int program() const { return program_; }
    /// Milliseconds the last open took (text into the editor).
    qint64 lastOpenMs() const { return lastOpenMs_; }

  signals:
    /// The cursor is on 1-based `line` of program `program` (the toolpath
    /// view highlights that block when it is linked to the editor).
    void cursorLineChanged(int program, int line);

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void open(int number);
    bool save();
    void compile();
    void showErrors();
    void openGne();
    void reload();
    bool gneAvailable() const;
    void showMessage(const QString& text, bool error = false);
    void updateStatus();
    void updateCursorLine();

    std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace_;
    NcCodeEdit* edit_;
    QLabel* heading_;
    QLabel* status_;
    QLabel* message_;
    int program_ = 0;
    mtc::core::ProgramPtr loadedSource_;  ///< the program the text came from
    qint64 lastOpenMs_ = 0;
};

}  // namespace mtc::screens
