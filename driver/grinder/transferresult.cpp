// The texts of a transfer's outcome: error ids, the inner-block summary, the time left.
#include "driver/grinder/transfersession.h"

namespace frezka::grinder {

const char *transferErrorId(TransferError error)
{
    switch (error) {
    case TransferError::None:
        return "ok";
    case TransferError::NotOpen:
        return "not-open";
    case TransferError::Busy:
        return "busy";
    case TransferError::InvalidInput:
        return "invalid-input";
    case TransferError::Timeout:
        return "timeout";
    case TransferError::Rejected:
        return "rejected";
    case TransferError::ChecksumFailed:
        return "checksum";
    case TransferError::UnexpectedReply:
        return "unexpected-reply";
    case TransferError::Transport:
        return "transport";
    case TransferError::Cancelled:
        return "cancelled";
    }
    return "unknown";
}

QString familyName(Family family)
{
    switch (family) {
    case Family::Anc:
        return QStringLiteral("ANC");
    case Family::K51:
        return QStringLiteral("K51");
    case Family::HardChrome:
        return QStringLiteral("HEDIT");
    case Family::Table:
        return QStringLiteral("K51 (table)");
    }
    return {};
}

double estimateSecondsLeft(qint64 doneBytes, qint64 totalBytes, qint64 elapsedUs, int baud)
{
    const qint64 left = std::max<qint64>(0, totalBytes - doneBytes);
    double bytesPerSecond = baud > 0 ? baud / 10.0 : 960.0;
    if (doneBytes > 0 && elapsedUs > 500000)
        bytesPerSecond = doneBytes * 1e6 / double(elapsedUs);
    return left / bytesPerSecond;
}

QString TransferSession::describeImage(const ImageReport &report)
{
    if (!report.hasBlocks)
        return tr("no inner blocks (%1 bytes)").arg(report.size);
    const std::size_t bad = report.badBlocks();
    if (bad == 0)
        return tr("%1 blocks, all valid").arg(report.blocks.size());
    QStringList problems;
    for (const BlockReport &block : report.blocks) {
        if (block.ok())
            continue;
        const QString id =
            QStringLiteral("0x") +
            QString::number(block.id, 16).rightJustified(2, QLatin1Char('0')).toUpper();
        problems << (!block.startOk ? tr("%1 (no AA)").arg(id)
                     : !block.idOk  ? tr("%1 (wrong block id)").arg(id)
                                    : tr("%1 (checksum)").arg(id));
    }
    return tr("%1 of %2 blocks invalid: %3 (the data are kept unchanged)")
        .arg(bad)
        .arg(report.blocks.size())
        .arg(problems.join(QLatin1String(", ")));
}

} // namespace frezka::grinder
