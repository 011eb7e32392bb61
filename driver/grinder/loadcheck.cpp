#include "driver/grinder/loadcheck.h"

#include <QStringList>

namespace frezka::grinder {

namespace {

QString blockId(const BlockReport &block)
{
    return QStringLiteral("0x") +
           QString::number(block.id, 16).rightJustified(2, QLatin1Char('0')).toUpper();
}

bool sizeFits(Family family, qsizetype size)
{
    switch (family) {
    case Family::Anc:
        return std::size_t(size) == kProgramImageSize ||
               std::size_t(size) == kAncImageSizeWithWheel;
    case Family::K51:
        return std::size_t(size) == kK51ImageSize;
    case Family::HardChrome:
        return std::size_t(size) == kHardChromeSize;
    case Family::Table:
        return true; // the manual gives no table length: APROXTAB's files are sent as they are
    }
    return false;
}

// The family whose files have this length, when it is another one (a wrong system selected).
QString otherFamilyOfSize(Family family, qsizetype size)
{
    if (family != Family::Anc && sizeFits(Family::Anc, size))
        return LoadCheck::tr("ANC");
    if (family != Family::K51 && sizeFits(Family::K51, size))
        return LoadCheck::tr("K51");
    if (family != Family::HardChrome && sizeFits(Family::HardChrome, size))
        return LoadCheck::tr("HEDIT");
    return {};
}

QString expectedLength(Family family)
{
    switch (family) {
    case Family::Anc:
        return LoadCheck::tr("ANC program data have 21760 or 21766 bytes (0x5500 or 0x5506)");
    case Family::K51:
        return LoadCheck::tr("K51 program data have 21767 bytes (0x5507)");
    case Family::HardChrome:
        return LoadCheck::tr("HEDIT data have 46 bytes (0x2E)");
    case Family::Table:
        return {};
    }
    return {};
}

} // namespace

LoadCheck LoadCheck::check(Family family, const QByteArray &data, const ImageReport &image,
                           bool sendAnyway, const std::set<qsizetype> &reportedSizes)
{
    LoadCheck result;
    if (data.isEmpty()) {
        result.refusal = tr("The file is empty; there is nothing to send.");
        return result;
    }
    if (!sizeFits(family, data.size())) {
        const bool reported = reportedSizes.count(data.size()) > 0;
        if (sendAnyway && reported) {
            result.warning =
                tr("Sent anyway: %1 bytes, the length this controller reported.").arg(data.size());
        } else {
            const QString other = otherFamilyOfSize(family, data.size());
            result.refusal =
                other.isEmpty()
                    ? tr("%1; the file has %2, so nothing was sent. Choose a file saved from "
                         "this controller.")
                          .arg(expectedLength(family))
                          .arg(data.size())
                    : tr("%1; the file has %2, the length of %3 data: is the wrong system "
                         "selected? Nothing was sent.")
                          .arg(expectedLength(family))
                          .arg(data.size())
                          .arg(other);
            if (reported)
                result.refusal +=
                    QLatin1Char(' ') + tr("This controller reported this length: choose \"Send "
                                          "anyway\" to send it.");
            return result;
        }
    }
    if (!image.hasBlocks || family == Family::Table)
        return result; // a table has no program blocks
    QStringList unmarked, badSum;
    for (const BlockReport &block : image.blocks) {
        if (!block.startOk || !block.idOk)
            unmarked << blockId(block);
        else if (!block.checksumOk)
            badSum << blockId(block);
    }
    if (!unmarked.isEmpty()) {
        result.refusal = tr("%1 of the %2 inner program blocks lack their AA and block number "
                            "marker (%3): the file is not a program image of this system or it "
                            "was changed. Nothing was sent.")
                             .arg(unmarked.size())
                             .arg(image.blocks.size())
                             .arg(unmarked.join(QLatin1String(", ")));
        return result;
    }
    if (badSum.isEmpty())
        return result;
    const QString blocks =
        tr("inner blocks with a wrong checksum: %1").arg(badSum.join(QLatin1String(", ")));
    if (!sendAnyway) {
        result.refusal =
            tr("The file has %1. Nothing was sent. If the controller itself gave you this file, "
               "choose \"Send anyway\": it gets the data unchanged.")
                .arg(blocks);
        return result;
    }
    result.warning = tr("Sent anyway: %1.").arg(blocks);
    return result;
}

} // namespace frezka::grinder
