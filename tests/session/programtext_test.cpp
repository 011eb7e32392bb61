// ProgramText: the program file and its index of line starts (issue 17: 32-bit starts, reserved
// at the file's line count).
#include "session/programtext.h"

#include <gtest/gtest.h>

using frezka::session::ProgramText;

TEST(ProgramText, LinesReadBackWithoutTheirEnds)
{
    const ProgramText text(QByteArray("G0 X1\r\n\nG1 X2 (cut)\nM2"));
    ASSERT_EQ(text.lineCount(), 4);
    EXPECT_EQ(text.line(0), QStringLiteral("G0 X1"));
    EXPECT_EQ(text.line(1), QString());
    EXPECT_EQ(text.line(2), QStringLiteral("G1 X2 (cut)"));
    EXPECT_EQ(text.line(3), QStringLiteral("M2"));
    EXPECT_EQ(text.line(4), QString());
    EXPECT_EQ(text.comment(3), QStringLiteral("cut"));
    EXPECT_EQ(ProgramText(QByteArray("G0\n")).lineCount(), 1);
    EXPECT_EQ(ProgramText(QByteArray()).lineCount(), 0);
}

// A file under 4 GB: 4 bytes a line, reserved once (8 a line and up to twice the lines before).
TEST(ProgramText, IndexTakesFourBytesALine)
{
    QByteArray data;
    constexpr int kLines = 100000;
    for (int i = 0; i < kLines; ++i)
        data += "G1 X" + QByteArray::number(i % 977) + " Y" + QByteArray::number(i % 31) + "\n";
    const ProgramText text(data);
    ASSERT_EQ(text.lineCount(), kLines);
    EXPECT_EQ(text.line(kLines - 1), QStringLiteral("G1 X") + QString::number((kLines - 1) % 977) +
                                         QStringLiteral(" Y") + QString::number((kLines - 1) % 31));
    EXPECT_EQ(text.indexBytes(), std::size_t(kLines) * 4);
}
