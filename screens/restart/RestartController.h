#pragma once

#include <QObject>
#include <QString>
#include <memory>
#include <vector>

#include "cnc_core/restart/RestartSequence.h"
#include "cnc_core/restart/SearchPointer.h"
#include "screens/restart/RestartCollisions.h"

namespace mtc::hmi {
class CellSession;
}

namespace mtc::screens {

class ProgramListingModel;
class RestartRun;
class RestartVerification;

/// A line the restart screens show under their content.
struct RestartMessage {
    enum class Level { None, Info, Warning, Error };
    Level level = Level::None;
    QString text;
    /// The diagnostics the text was made from, as data (the error window
    /// takes them; empty for the screen's own texts).
    std::vector<mtc::core::Diagnostic> diagnostics;
};

/// The model behind the restart screens of one station: the search pointer
/// (seed 000, 2.3-2.6) on the station's selected program, the listing it
/// shows, and the operator's messages. Screens forward keys here and render
/// what it says; it never touches widgets. One per station, shared by the
/// restart, restart-result and repos screens (RestartControllers).
class RestartController : public QObject {
    Q_OBJECT
  public:
    /// The controller of station `slot` of `session` (which must outlive it).
    RestartController(mtc::hmi::CellSession* session, int slot, QObject* parent = nullptr);
    ~RestartController() override;

    int slot() const { return slot_; }
    mtc::hmi::CellSession* session() const { return session_; }
    const mtc::core::SearchPointer& pointer() const { return pointer_; }
    ProgramListingModel* listing() const { return listing_; }
    const RestartMessage& message() const { return message_; }
    /// The last accepted selection (valid after accept() returned true).
    const mtc::core::AcceptResult& accepted() const { return accepted_; }
    /// The restart of the station after Enter (computing process, ADJUST, REPOS).
    RestartRun* run() const { return run_; }
    /// The restart verifier of the station (restart.md R-028).
    RestartVerification* verification() const { return verification_; }
    /// The way back checked against the part at the target (D-021).
    const RestartCollisions& collisions() const { return collisions_; }
    /// Soft key of the restart screen: verifies every arrival of the displayed
    /// main program as a target (in slices; the message line shows the
    /// coverage line when it is done). Refused while a restart is active.
    void verifyProgram();
    /// The result review: the accepted target as the CLI's verify-restart
    /// checks it (a normal run to it, ADJUST and REPOS on private copies),
    /// and the way back against the part at the target.
    void verifyAcceptedTarget();
    /// "P1 N0020 (line 37)" of the accepted target; "" before the first Enter.
    QString acceptedTarget() const;
    /// What the restart is doing now, for the operator ("" before the first Enter).
    QString phaseText() const;

    /// Entry into the restart screen (seed 000, 2.2): the search starts in
    /// the selected program, number of runs 1 (2.6), the cursor on N0000 or
    /// on the block preselected since the last entry (toolpath pick, TP-006).
    /// Says why when it cannot (no program selected, not in automatic mode,
    /// program active).
    void enter();
    /// The toolpath view picked block `block` of program `program`: the next
    /// entry puts the cursor there when it is a block of the selected program.
    void preselect(int program, std::uint32_t block);
    /// True when a program is displayed (enter() succeeded).
    bool active() const { return pointer_.active(); }

    // ---- keys of the selection (each emits changed())
    /// Cursor one block up.
    void up();
    /// Cursor one block down.
    void down();
    /// Cursor `rows` blocks up (the rows the listing shows).
    void pageUp(int rows);
    /// Cursor `rows` blocks down.
    void pageDown(int rows);
    /// Cursor on N0000.
    void home();
    /// Cursor on the block before the end of the program.
    void end();
    /// Mouse: cursor on the block shown on listing row `row`.
    void clickRow(int row);
    /// Follows the jump or call of the cursor block (or opens its window);
    /// a refusal becomes the error message.
    void planePlus();
    /// Back to the calling point; refused on the first level.
    void planeMinus();
    /// Event window: follow with the event `set` / not set.
    void confirmEvent(bool set);
    /// Variable window: follow with the program number typed as `text`.
    /// Returns false (window stays open) when refused.
    bool confirmVariable(const QString& text);
    /// Closes the event / variable window without jumping.
    void cancelWindow();
    /// Search string; false when not found (cursor stays).
    bool search(const QString& text);
    const QString& lastSearch() const { return lastSearch_; }
    /// Number of runs from the operator's text; false (old value kept) if refused.
    bool setRuns(const QString& text);
    /// Switches "restart from last primary block" (refused without one).
    void toggleFromLastPrimary();
    /// <Enter>: validates the selection and hands it to the NC (PxxSBPACT;
    /// the SPS starts the computing process). True when accepted (accepted()).
    bool accept();
    /// Abort soft key: ends the computing process (or ADJUST/REPOS).
    void abort();

    /// "P1 COVER PLATE ▸ N0012 BSR .CONTUR ▸ P1 .CONTUR": the levels.
    QString breadcrumb() const;
    /// "Target P1 N0042 (line 50) · start N0000 · runs 1".
    QString status() const;
    /// Text for a core diagnostic: "P1 N0014 line 15: message".
    static QString describe(const mtc::core::Diagnostic& diagnostic);

  signals:
    /// Anything the screens show changed.
    void changed();

  private:
    void reply(const mtc::core::SearchReply& reply);
    void setMessage(RestartMessage::Level level, const QString& text,
                    std::vector<mtc::core::Diagnostic> diagnostics = {});
    /// An error message made of `diagnostics` (describe() each, joined).
    void setErrors(const mtc::core::DiagnosticList& diagnostics);
    void showLevel();
    void cursorMoved();
    QString refusalReason() const;
    QString heldText() const;
    void phaseChanged(mtc::core::RestartPhase phase);

    mtc::hmi::CellSession* session_;
    int slot_;
    mtc::core::SearchPointer pointer_;
    ProgramListingModel* listing_;
    const mtc::core::Program* shownProgram_ = nullptr;
    RestartMessage message_;
    QString lastSearch_;
    int preselectedProgram_ = 0;  ///< 0 = no pick since the last entry
    std::uint32_t preselectedBlock_ = 0;
    mtc::core::AcceptResult accepted_;
    RestartRun* run_;
    RestartVerification* verification_;
    RestartCollisions collisions_;
};

}  // namespace mtc::screens
