#include "driver/grinder/controllerheader.h"

namespace frezka::grinder {

ControllerHeader ControllerHeader::fromText(const QString &typed)
{
    ControllerHeader result;
    for (const QChar c : typed) {
        if (c.unicode() >= 0x20 && c.unicode() <= 0x7E) {
            result.text += c;
            continue;
        }
        // Canonical decomposition: the base letter first, then combining marks (háček, čárka,
        // kroužek), which are dropped.
        const QString base = QString(c).normalized(QString::NormalizationForm_D);
        const QChar first = base.isEmpty() ? QChar() : base.at(0);
        if (base.size() > 1 && first.unicode() >= 0x20 && first.unicode() <= 0x7E) {
            result.text += first;
            result.mapped = true;
            continue;
        }
        result.error = tr("The header \"%1\" holds '%2', which the controller cannot show (it "
                          "shows letters without diacritics, digits and signs). Replace it.")
                           .arg(typed, QString(c));
        return result;
    }
    result.text = result.text.left(int(kHeaderSize));
    return result;
}

QString ControllerHeader::mappingNote(const QString &typed, const ControllerHeader &header)
{
    if (!header.ok() || !header.mapped)
        return {};
    return tr("The header \"%1\" is sent as \"%2\": the controller has no Czech letters, so "
              "they become their base letters.")
        .arg(typed, header.text);
}

} // namespace frezka::grinder
