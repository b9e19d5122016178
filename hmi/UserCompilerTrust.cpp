#include "hmi/UserCompilerTrust.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QStringList>

namespace mtc::hmi {
namespace {

constexpr const char* kApproved = "userCompilers/approved";
constexpr const char* kTrustedFolders = "userCompilers/trustedFolders";

QString canonical(const QString& folder) {
    const QString path = QFileInfo(folder).canonicalFilePath();
    return path.isEmpty() ? QDir::cleanPath(QFileInfo(folder).absoluteFilePath()) : path;
}

}  // namespace

bool UserCompilerTrust::approved(const QString& folder, int slot, const QString& command) {
    if (folder.isEmpty() || command.isEmpty()) return true;
    if (folderTrusted(folder)) return true;
    const QString path = canonical(folder);
    QSettings settings;
    const int count = settings.beginReadArray(kApproved);
    bool found = false;
    for (int i = 0; i < count && !found; ++i) {
        settings.setArrayIndex(i);
        found = settings.value("folder").toString() == path &&
                settings.value("slot").toInt() == slot &&
                settings.value("command").toString() == command;
    }
    settings.endArray();
    return found;
}

void UserCompilerTrust::approve(const QString& folder, int slot, const QString& command) {
    if (folder.isEmpty() || command.isEmpty() || approved(folder, slot, command)) return;
    QSettings settings;
    const int count = settings.beginReadArray(kApproved);
    settings.endArray();
    settings.beginWriteArray(kApproved, count + 1);
    settings.setArrayIndex(count);
    settings.setValue("folder", canonical(folder));
    settings.setValue("slot", slot);
    settings.setValue("command", command);
    settings.endArray();
    settings.sync();
}

bool UserCompilerTrust::folderTrusted(const QString& folder) {
    const QString path = canonical(folder);
    const QStringList trusted = QSettings().value(kTrustedFolders).toStringList();
    for (const QString& entry : trusted) {
        const QString root = canonical(entry);
        if (path == root || path.startsWith(root + "/")) return true;
    }
    return false;
}

void UserCompilerTrust::trustFolder(const QString& folder) {
    QSettings settings;
    QStringList trusted = settings.value(kTrustedFolders).toStringList();
    trusted << canonical(folder);
    trusted.removeDuplicates();
    settings.setValue(kTrustedFolders, trusted);
    settings.sync();
}

}  // namespace mtc::hmi
