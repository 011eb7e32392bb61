// LinuxCNC dialect the interpreter suite exercises: EXISTS of numbered parameters, computed
// O numbers, coordinate-system rotation, top-level return. Each case checked against what
// `rs274 -g` gives for the same text (its values noted beside each).
#include "gcode/interpreter.h"

#include <gtest/gtest.h>

using namespace frezka::gcode;

namespace {

Result run(const std::string &text)
{
    return interpretText(text);
}

} // namespace

// rs274: EXISTS[#n] is 1 for any integer value n naming #1..#5601 (##1, #[1+1] too), 0 for the
// others, with no error; EXISTS[#<name>] is 1 when the name has a value.
TEST(Dialect, ExistsOfNumberedAndNamedParameters)
{
    const Result r = run("#<a>=1\n#1=2\n#2=99999\n"
                         "G0 X EXISTS[#1] Y EXISTS[#5602] Z EXISTS[#0] A EXISTS[#5601]\n"
                         "G0 X EXISTS[##2] Y EXISTS[#[1+1]] Z EXISTS[#<A>] A EXISTS[#<b>]\n"
                         "M2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    EXPECT_EQ(r.toolpath.end(0), (Point4{1, 0, 0, 1}));
    EXPECT_EQ(r.toolpath.end(1), (Point4{0, 1, 1, 0}));
    for (const char *bad :
         {"G0 X EXISTS[1]\nM2\n", "G0 X EXISTS[#1+1]\nM2\n", "G0 X EXISTS[#1.5]\nM2\n"}) {
        const Result e = run(bad);
        EXPECT_FALSE(e.ok()) << bad;
    }
}

// rs274: the O number of a call may be any integer value; a computed O word inside a block
// being skipped is not evaluated (its parameters need not exist yet).
TEST(Dialect, ComputedSubroutineNumbers)
{
    const Result r = run("o2 sub\nG0 X2\no2 endsub\n"
                         "o3 sub\n#<n> = 2\no#<n> call\no3 endsub\n"
                         "o[1+1] call\nG0 X0\no3 call\n#1=2\no#1 call\nM2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    ASSERT_EQ(r.toolpath.size(), 5u); // X2, X0, X2, X2, M2
    EXPECT_EQ(r.toolpath.end(0).x, 2);
    EXPECT_EQ(r.toolpath.end(1).x, 0);
    EXPECT_EQ(r.toolpath.end(2).x, 2);
    EXPECT_EQ(r.toolpath.end(3).x, 2);
    const Result half = run("o2 sub\nG0 X2\no2 endsub\no[2.5] call\nM2\n");
    ASSERT_EQ(half.errors.size(), 1u);
    EXPECT_EQ(half.errors[0].code, ErrorCode::NonIntegerValue);
    EXPECT_EQ(half.errors[0].line, 4u);
    const Result undefined = run("o#<nope> call\nM2\n");
    ASSERT_EQ(undefined.errors.size(), 1u);
    EXPECT_EQ(undefined.errors[0].code, ErrorCode::NamedParameterUndefined);
}

// rs274: return and endsub end the running call whatever their O label (the suite's
// return-value returns with the label of the if it stands in), set #<_value> (0 for a plain
// return); outside a call they are an error.
TEST(Dialect, ReturnEndsTheRunningCallWhateverItsLabel)
{
    const Result r = run("o1 sub\no2 if [#1 GT 0]\no2 return [5]\no2 endif\no1 endsub [7]\n"
                         "o4 sub\no4 return\no4 endsub\n"
                         "o1 call [1]\nG0 X#<_value> Y#<_value_returned>\n"
                         "o1 call [0]\nG0 X#<_value>\no4 call\nG0 X#<_value> Y#<_value_returned>\n"
                         "M2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    EXPECT_EQ(r.toolpath.end(0), (Point4{5, 1, 0, 0}));
    EXPECT_EQ(r.toolpath.end(1), (Point4{7, 1, 0, 0}));
    EXPECT_EQ(r.toolpath.end(2), (Point4{0, 0, 0, 0}));
    // A definition ends at its own label's endsub only; an endsub of another label returns.
    const Result other = run("o1 sub\nG0 X1\no2 endsub\nG0 X5\no1 endsub\no1 call\nG0 X3\nM2\n");
    ASSERT_TRUE(other.ok()) << englishMessage(other.errors[0]);
    ASSERT_EQ(other.toolpath.size(), 3u); // X1, X3, M2
    EXPECT_EQ(other.toolpath.end(1).x, 3);
    const Result top = run("G0 X1\no2 return\nG0 X3\nM2\n");
    ASSERT_EQ(top.errors.size(), 1u);
    EXPECT_EQ(top.errors[0].code, ErrorCode::ReturnOutsideSub);
    EXPECT_EQ(top.errors[0].line, 2u);
}
