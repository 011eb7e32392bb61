#pragma once
// Header text in the controller's character set. The controller's display shows printable
// ASCII only; Czech letters become their base letters (Ř -> R, č -> c, ů -> u), and the
// caller shows the operator what will be sent — nothing is dropped silently. A character with
// no base letter in ASCII (€, ß, a Cyrillic letter) is refused by name.

#include "driver/grinder/frame.h"

#include <QCoreApplication>
#include <QString>

namespace frezka::grinder {

struct ControllerHeader
{
    Q_DECLARE_TR_FUNCTIONS(ControllerHeader)
public:
    QString text;        // as sent: printable ASCII, at most 16 characters
    bool mapped = false; // some letters were replaced by their base letters
    QString error;       // translated; set when a character cannot be shown
    bool ok() const { return error.isEmpty(); }
    Header header() const { return headerFromText(text.toStdString()); }

    // From what the operator typed (or a file name), cut to 16 characters after mapping.
    static ControllerHeader fromText(const QString &typed);
    // "HŘÍDEL č.5" is sent as "HRIDEL c.5" (the controller has no Czech letters) — or empty
    // when nothing was mapped.
    static QString mappingNote(const QString &typed, const ControllerHeader &header);
};

} // namespace frezka::grinder
