#include "screens/runtime/RuntimeScreen.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QTextBlock>
#include <QVBoxLayout>
#include <algorithm>

#include "cnc_core/language/Parser.h"
#include "hmi/CellSession.h"
#include "hmi/ProgramWorkspace.h"
#include "screens/editor/NcCodeEdit.h"
#include "screens/runtime/VelocityPlot.h"

namespace mtc::screens {

RuntimeScreen::RuntimeScreen(const mtc::hmi::ScreenContext& context,
                             std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace)
    : Screen(context), workspace_(std::move(workspace)) {
    heading_ = new QLabel(this);
    heading_->setObjectName("runtimeHeading");
    source_ = new NcCodeEdit(this);
    source_->setObjectName("runtimeSource");
    source_->setReadOnly(true);
    source_->setFocusPolicy(Qt::NoFocus);
    source_->setWindowing(true);  // ED-009: large programs through a window
    compiled_ = new NcCodeEdit(this);
    compiled_->setObjectName("runtimeCompiled");
    compiled_->setReadOnly(true);
    compiled_->setTextInteractionFlags(Qt::TextSelectableByKeyboard | Qt::TextSelectableByMouse);
    compiled_->setWindowing(true);
    note_ = new QLabel(this);
    note_->setObjectName("runtimeNote");
    note_->setWordWrap(true);
    auto* panes = new QHBoxLayout;
    panes->addWidget(source_, 1);
    panes->addWidget(compiled_, 1);
    plot_ = new VelocityPlot(this);
    plot_->setObjectName("velocityPlot");
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(heading_);
    layout->addLayout(panes, 3);
    layout->addWidget(plot_, 1);
    layout->addWidget(note_);
    setFocusProxy(compiled_);
    connect(compiled_, &QPlainTextEdit::cursorPositionChanged, this,
            [this] { followCompiledCursor(); });
    connect(workspace_.get(), &mtc::hmi::ProgramWorkspace::programChanged, this, [this](int n) {
        if (isVisible() && (n == 0 || n == program_)) showProgram();
    });
}

void RuntimeScreen::activated() {
    showProgram();
}

void RuntimeScreen::showProgram() {
    program_ = workspace_->editProgram();
    if (program_ == 0) program_ = context().session->control(context().process).selectedProgram();
    const auto program = context().session->program(context().process, program_);
    const auto result = workspace_->runtimeResult(program_);
    const auto status = workspace_->status(program_);
    heading_->setText(tr("Program %1  %2   source  |  runtime program   status [%3]")
                          .arg(program_, 3, 10, QChar('0'))
                          .arg(program ? QString::fromStdString(program->name) : tr("(none)"))
                          .arg(QChar(mtc::core::statusLetter(status))));
    source_->load(program ? program->source.str() : std::string());
    showSegment(segment_);
    listing_ = {};
    const mtc::core::ProgramPtr runtime = runtimeProgram(program, result.get(), status);
    const std::vector<mtc::core::InsertedBlock> inserted =
        runtime ? insertedBlocks(runtime) : std::vector<mtc::core::InsertedBlock>();
    const QString arrows = inserted.empty()
                               ? QString()
                               : " " + tr("%1 marks the blocks tool compensation inserts while "
                                          "the program runs.")
                                           .arg(kIntermediateArrow.trimmed());
    if (result && result->status == mtc::core::CompileStatus::Compiled) {
        listing_ = buildRuntimeListing(*result, runtime.get(), inserted);
        compiled_->load(listing_.text);
        note_->setText(tr("%1 blocks inserted by the compiler (N....:0001, ...).")
                           .arg(listing_.intermediateBlocks) +
                       arrows);
    } else if (status == mtc::core::CompileStatus::NotNeeded && program) {
        if (inserted.empty()) {
            compiled_->load(program->source.str());
        } else {
            listing_ = buildSourceListing(*program, inserted);
            compiled_->load(listing_.text);
        }
        note_->setText(tr("The program needs no compilation: it runs as written.") + arrows);
    } else {
        compiled_->load(QString());
        note_->setText(status == mtc::core::CompileStatus::Error
                           ? tr("The program has compile errors (error display: Ctrl+E in the "
                                "editor).")
                           : tr("The program is not compiled yet (Compile in the editor or the "
                                "program directory)."));
    }
}

mtc::core::ProgramPtr RuntimeScreen::runtimeProgram(const mtc::core::ProgramPtr& source,
                                                    const mtc::core::CompileResult* result,
                                                    mtc::core::CompileStatus status) const {
    if (result && result->status == mtc::core::CompileStatus::Compiled) {
        // The object program as the station would run it (ProgramWorkspace::prepareRuntime).
        mtc::core::ParseOptions options;
        options.programNumber = program_;
        options.name = source ? source->name : std::string();
        return std::make_shared<mtc::core::Program>(
            mtc::core::parseProgram(result->objectText, options));
    }
    return status == mtc::core::CompileStatus::NotNeeded ? source : nullptr;
}

std::vector<mtc::core::InsertedBlock> RuntimeScreen::insertedBlocks(
    const mtc::core::ProgramPtr& runtime) const {
    // The runtime program exists while the program runs (seed 001 ch. 1): the
    // blocks tool compensation inserts come from a check run of it, with the
    // station's tool list and zero offsets, on a copy of the program store.
    if (!mtc::core::usesRadiusCompensation(*runtime)) return {};
    const auto* session = context().session;
    const auto& config = session->processConfig(context().process);
    mtc::core::ProgramStore store = session->store();
    store.putRuntime(config.index, program_, runtime);
    auto blocks = mtc::core::insertedBlocks(config, store, program_, kInsertionBudget,
                                            session->setupData().tools(config.index),
                                            session->setupData().offsets(config.index))
                      .blocks;
    blocks.erase(std::remove_if(blocks.begin(), blocks.end(),
                                [this](const auto& b) { return b.program != program_; }),
                 blocks.end());
    return blocks;
}

void RuntimeScreen::showSegment(int index) {
    const mtc::hmi::VelocityProfile profile = workspace_->velocityProfile(program_);
    if (profile.empty()) {
        segment_ = 0;
        plot_->setSegment({}, tr("No look-ahead segment (LA_ON ... LA_OFF) in the last compile"));
        return;
    }
    segment_ = (index % int(profile.segments.size()) + int(profile.segments.size())) %
               int(profile.segments.size());
    const auto& segment = profile.segments[size_t(segment_)];
    plot_->setSegment(segment, tr("LA segment %1 of %2 (line %3): %4 blocks")
                                   .arg(segment_ + 1)
                                   .arg(profile.segments.size())
                                   .arg(segment.sourceLine)
                                   .arg(segment.blocks));
}

void RuntimeScreen::followCompiledCursor() {
    const int row = compiled_->cursorLine() - 1;
    if (row < 0 || row >= listing_.sourceLine.size()) return;
    const int line = listing_.sourceLine[row];
    if (line <= 0) return;
    QTextEdit::ExtraSelection mark;
    mark.format.setBackground(QColor(255, 236, 150));
    mark.format.setProperty(QTextFormat::FullWidthSelection, true);
    source_->goToLine(line);  // moves the source's window when needed
    mark.cursor = source_->textCursor();
    source_->setExtraSelections({mark});
}

mtc::hmi::SoftKeys RuntimeScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    keys[0] = {tr("Compile"),
               [this] {
                   QString error;
                   if (!workspace_->compile(program_, error)) note_->setText(error);
               },
               workspace_->compilerActive()};
    keys[1] = {tr("Next LA\nsegment"), [this] { showSegment(segment_ + 1); },
               workspace_->velocityProfile(program_).segments.size() > 1};
    keys[6] = {tr("Editor"), [this] {
                   workspace_->requestEdit(program_, 0);
                   emit navigateTo("editor");
               }};
    keys[7] = {tr("Back"), [this] { emit navigateTo("programs"); }};
    return keys;
}

}  // namespace mtc::screens
