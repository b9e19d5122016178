#pragma once

#include <QMap>
#include <QObject>
#include <QPair>
#include <memory>

#include "hmi/Screen.h"

namespace mtc::screens {

/// Which screen the toolpath view of one station is linked to, and where the
/// program editor's cursor is (docs/decisions/toolpath.md TP-012). The
/// screens never see each other: the screen catalog connects the editor's
/// cursor signal here and lets the link watch the screens it names; the
/// toolpath model reads the link and asks it to move the editor.
class ToolpathLink : public QObject {
    Q_OBJECT
  public:
    /// The screen whose cursor the toolpath view follows and moves.
    enum class Partner { Restart, Editor };

    /// The restart screen until the operator shows one of the watched screens.
    Partner partner() const { return partner_; }
    /// Each time `screen` is shown it becomes the partner (`partner`).
    void watch(QWidget* screen, Partner partner);
    /// Program the editor shows (0 = none) and the 1-based line of its cursor.
    int editorProgram() const { return editorProgram_; }
    int editorLine() const { return editorLine_; }

    /// The editor's cursor is on `line` of program `program` (from the editor).
    void setEditorCursor(int program, int line);
    /// A pick while the editor is the partner: the editor is to show
    /// `program` at `line` (emits editorLineRequested).
    void requestEditorLine(int program, int line);

  signals:
    /// partner() changed.
    void partnerChanged();
    /// The editor's cursor moved (setEditorCursor).
    void editorCursorChanged();
    /// The toolpath view asks the editor to show `program` at `line`.
    void editorLineRequested(int program, int line);

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    Partner partner_ = Partner::Restart;
    QMap<QObject*, Partner> watched_;
    int editorProgram_ = 0;
    int editorLine_ = 0;
};

/// One ToolpathLink per station, shared by the screens that hold it (like
/// RestartControllers): it goes with the last of them.
class ToolpathLinks {
  public:
    /// The link of the context's station; created on first use.
    std::shared_ptr<ToolpathLink> forStation(const mtc::hmi::ScreenContext& context);
    /// The link of `screen`'s station, kept as long as `screen` lives, with
    /// `screen` watched as `partner` (ToolpathLink::watch).
    std::shared_ptr<ToolpathLink> attach(mtc::hmi::Screen* screen, ToolpathLink::Partner partner);

  private:
    QMap<QPair<const void*, int>, std::weak_ptr<ToolpathLink>> links_;
};

}  // namespace mtc::screens
