#include "screens/gne/GneTexts.h"

#include <QCoreApplication>

#include "cnc_core/text/Messages.h"
#include "hmi/PanelLanguage.h"

namespace mtc::screens {

namespace {
constexpr const char* kContext = "GneModel";
constexpr const char* kEmptyMeans = QT_TRANSLATE_NOOP("GneModel", "%1 (empty = %2)");

/// `form` with %1..%9 replaced by `args` in one pass (a value that holds
/// "%2" itself stays as typed).
QString filled(const QString& form, const std::vector<QString>& args) {
    QString out;
    for (int i = 0; i < form.size(); ++i) {
        const int index = i + 1 < form.size() && form[i] == '%' ? form[i + 1].digitValue() - 1 : -1;
        if (index >= 0 && index < static_cast<int>(args.size())) {
            out += args[static_cast<std::size_t>(index)];
            ++i;
        } else {
            out += form[i];
        }
    }
    return out;
}

// The parameter meanings of the core's GNE calls (cnc_core/contour/GneSchema.cpp)
// as lupdate sees them: the core has no Qt. They must stay equal to the
// core's texts; test_gne_screen checks every parameter of every call against
// the German catalogue.
[[maybe_unused]] const char* const kSchemaMeanings[] = {
    QT_TRANSLATE_NOOP("GneModel", "number of the contour or form to machine"),
    QT_TRANSLATE_NOOP("GneModel", "tool number"),
    QT_TRANSLATE_NOOP("GneModel", "feed (mm/rev or mm/min as programmed)"),
    QT_TRANSLATE_NOOP("GneModel", "spindle speed, 0 = leave unchanged"),
    QT_TRANSLATE_NOOP("GneModel", "cutting edge orientation assumed (0..9)"),
    QT_TRANSLATE_NOOP("GneModel", "tool nose radius assumed"),
    QT_TRANSLATE_NOOP("GneModel", "corner angle of the insert assumed (degrees)"),
    QT_TRANSLATE_NOOP("GneModel", "setting angle of the tool assumed (degrees)"),
    QT_TRANSLATE_NOOP("GneModel", "safety clearance for approach and retract"),
    QT_TRANSLATE_NOOP("GneModel", "left end of the blank"),
    QT_TRANSLATE_NOOP("GneModel", "right end of the blank"),
    QT_TRANSLATE_NOOP("GneModel", "outer radius of the blank"),
    QT_TRANSLATE_NOOP("GneModel", "bore radius"),
    QT_TRANSLATE_NOOP("GneModel", "blank corner X"),
    QT_TRANSLATE_NOOP("GneModel", "blank corner Y"),
    QT_TRANSLATE_NOOP("GneModel", "opposite corner X"),
    QT_TRANSLATE_NOOP("GneModel", "opposite corner Y"),
    QT_TRANSLATE_NOOP("GneModel", "top face of the blank"),
    QT_TRANSLATE_NOOP("GneModel", "bottom face of the blank"),
    QT_TRANSLATE_NOOP("GneModel", "geometry number"),
    QT_TRANSLATE_NOOP("GneModel", "right flank of the recess"),
    QT_TRANSLATE_NOOP("GneModel", "radius the recess starts from"),
    QT_TRANSLATE_NOOP("GneModel", "width of the recess"),
    QT_TRANSLATE_NOOP("GneModel", "depth of the recess"),
    QT_TRANSLATE_NOOP("GneModel", "centre of the 1st end"),
    QT_TRANSLATE_NOOP("GneModel", "centre of the 2nd end"),
    QT_TRANSLATE_NOOP("GneModel", "width of the hole"),
    QT_TRANSLATE_NOOP("GneModel", "centre of the arc"),
    QT_TRANSLATE_NOOP("GneModel", "radius of the middle line"),
    QT_TRANSLATE_NOOP("GneModel", "start angle (degrees)"),
    QT_TRANSLATE_NOOP("GneModel", "end angle (degrees, counter-clockwise from A1)"),
    QT_TRANSLATE_NOOP("GneModel", "centre"),
    QT_TRANSLATE_NOOP("GneModel", "radius"),
    QT_TRANSLATE_NOOP("GneModel", "radius of the circumscribed circle"),
    QT_TRANSLATE_NOOP("GneModel", "number of corners"),
    QT_TRANSLATE_NOOP("GneModel", "angle of the first corner (degrees)"),
    QT_TRANSLATE_NOOP("GneModel", "start of the base line"),
    QT_TRANSLATE_NOOP("GneModel", "character height"),
    QT_TRANSLATE_NOOP("GneModel", "angle of the base line (degrees)"),
    QT_TRANSLATE_NOOP("GneModel", "centre of the base circle"),
    QT_TRANSLATE_NOOP("GneModel", "radius of the base circle"),
    QT_TRANSLATE_NOOP("GneModel", "angle of the first character (degrees)"),
    QT_TRANSLATE_NOOP("GneModel", "corner"),
    QT_TRANSLATE_NOOP("GneModel", "opposite corner"),
    QT_TRANSLATE_NOOP("GneModel", "corner radius"),
    QT_TRANSLATE_NOOP("GneModel", "length along the angle"),
    QT_TRANSLATE_NOOP("GneModel", "width"),
    QT_TRANSLATE_NOOP("GneModel", "angle of the length side (degrees)"),
    QT_TRANSLATE_NOOP("GneModel", "depth of cut per pass (radius)"),
    QT_TRANSLATE_NOOP("GneModel", "allowance in X (radius)"),
    QT_TRANSLATE_NOOP("GneModel", "allowance in Z"),
    QT_TRANSLATE_NOOP("GneModel", "uniform allowance left for the contour cut"),
    QT_TRANSLATE_NOOP("GneModel", "feed (mm/min)"),
    QT_TRANSLATE_NOOP("GneModel", "tool radius assumed"),
    QT_TRANSLATE_NOOP("GneModel", "0 on the contour, 1 left (G41), 2 right (G42)"),
    QT_TRANSLATE_NOOP("GneModel", "safety plane"),
    QT_TRANSLATE_NOOP("GneModel", "cutting depth (absolute Z)"),
    QT_TRANSLATE_NOOP("GneModel", "plunge feed, 0 = F"),
};
}  // namespace

QString gneText(const gnefields::ModelText& text) {
    std::vector<QString> args;
    for (const std::string& arg : text.args)
        args.push_back(QString::fromStdString(arg));
    const std::string_view german = text.diagnosticCode.empty() || args.empty() ||
                                            hmi::installedCoreLanguage() != core::Language::German
                                        ? std::string_view{}
                                        : core::germanMessage(text.diagnosticCode);
    if (!german.empty())
        args.back() = QString::fromStdString(std::string(german)) + " - " + args.back();
    return filled(QCoreApplication::translate(kContext, text.form), args);
}

QString gneLines(const std::vector<gnefields::ModelText>& texts) {
    QStringList lines;
    for (const gnefields::ModelText& text : texts)
        lines << gneText(text);
    return lines.join('\n');
}

QString gneMeaning(const gnefields::Field& field) {
    const QString meaning = QCoreApplication::translate(kContext, field.meaning.c_str());
    if (field.emptyValue.empty()) return meaning;
    return filled(QCoreApplication::translate(kContext, kEmptyMeans),
                  {meaning, QString::fromStdString(field.emptyValue)});
}

}  // namespace mtc::screens
