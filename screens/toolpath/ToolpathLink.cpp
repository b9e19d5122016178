#include "screens/toolpath/ToolpathLink.h"

#include <QEvent>

namespace mtc::screens {

namespace {
/// Keeps a station's link alive as long as its parent screen lives.
class LinkHolder : public QObject {
  public:
    LinkHolder(QObject* parent, std::shared_ptr<ToolpathLink> link)
        : QObject(parent), link_(std::move(link)) {}

  private:
    std::shared_ptr<ToolpathLink> link_;
};
}  // namespace

void ToolpathLink::watch(QWidget* screen, Partner partner) {
    watched_.insert(screen, partner);
    screen->installEventFilter(this);
    connect(screen, &QObject::destroyed, this, [this, screen] { watched_.remove(screen); });
}

bool ToolpathLink::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Show && watched_.contains(watched)) {
        const Partner partner = watched_.value(watched);
        if (partner != partner_) {
            partner_ = partner;
            emit partnerChanged();
        }
    }
    return QObject::eventFilter(watched, event);
}

void ToolpathLink::setEditorCursor(int program, int line) {
    if (program == editorProgram_ && line == editorLine_) return;
    editorProgram_ = program;
    editorLine_ = line;
    emit editorCursorChanged();
}

void ToolpathLink::requestEditorLine(int program, int line) {
    emit editorLineRequested(program, line);
}

std::shared_ptr<ToolpathLink> ToolpathLinks::forStation(const mtc::hmi::ScreenContext& context) {
    std::weak_ptr<ToolpathLink>& slot = links_[{context.session, context.process}];
    std::shared_ptr<ToolpathLink> link = slot.lock();
    if (!link) {
        link = std::make_shared<ToolpathLink>();
        slot = link;
    }
    return link;
}

std::shared_ptr<ToolpathLink> ToolpathLinks::attach(mtc::hmi::Screen* screen,
                                                    ToolpathLink::Partner partner) {
    std::shared_ptr<ToolpathLink> link = forStation(screen->context());
    link->watch(screen, partner);
    new LinkHolder(screen, link);
    return link;
}

}  // namespace mtc::screens
