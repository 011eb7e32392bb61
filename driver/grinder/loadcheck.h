#pragma once
// The check of a file before a load: nothing is sent unless it passes (issue 22). Each family
// has its length (ANC 0x5500 or 0x5506, K51 0x5507, HEDIT 0x2E) and program images their 20
// inner blocks (imagecheck.h). A refusal names what is wrong and what to do.
//
// "Send anyway" is deliberate and narrow: it lets through a length only when this controller
// itself reported it (a save in the same session received data of that length), and inner
// blocks whose checksum alone is wrong (the controller keeps such data and sends it back as
// it is). Missing block markers are never sent: the file is not a program image.

#include "driver/grinder/family.h"
#include "driver/grinder/imagecheck.h"

#include <QCoreApplication>
#include <QString>

#include <set>

namespace frezka::grinder {

struct LoadCheck
{
    Q_DECLARE_TR_FUNCTIONS(LoadCheck)
public:
    QString refusal; // translated; empty when the data may be sent
    QString warning; // translated; what "send anyway" let through, or block problems
    bool ok() const { return refusal.isEmpty(); }

    // `reportedSizes`: lengths the controller sent in this session.
    static LoadCheck check(Family family, const QByteArray &data, const ImageReport &image,
                           bool sendAnyway, const std::set<qsizetype> &reportedSizes);
};

} // namespace frezka::grinder
