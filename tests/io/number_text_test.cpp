// io::parseNumber, the one reader of a numeric word shared by the Gmsh, STL/OBJ, triangle and
// particle-file readers: whole words only, nearest double, no locale.

#include "io/number_text.h"

#include <gtest/gtest.h>

#include <cmath>

namespace veridem::io
{
namespace
{

TEST(NumberText, ReadsDecimalAndScientificWordsToTheNearestDouble)
{
    EXPECT_EQ(parseNumber("0.1"), 0.1);
    EXPECT_EQ(parseNumber("-2.5e-3"), -2.5e-3);
    EXPECT_EQ(parseNumber("+7"), 7.0);
    EXPECT_EQ(parseNumber("1E3"), 1000.0);
    EXPECT_EQ(parseNumber(".5"), 0.5);
}

TEST(NumberText, RefusesWordsThatAreNotWholeNumbers)
{
    for (const char* word :
         {"", "+", "-", "1.0x", "1,5", "0x10", "+-1", "++1", "1e", " 1", "1 ", "e5", "one"})
        EXPECT_FALSE(parseNumber(word).has_value()) << "'" << word << "'";
    EXPECT_FALSE(parseNumber("1e400").has_value()); // beyond the double range
}

TEST(NumberText, FiniteNumbersRefuseInfinityAndNan)
{
    ASSERT_TRUE(parseNumber("inf").has_value());
    EXPECT_TRUE(std::isinf(*parseNumber("inf")));
    EXPECT_TRUE(std::isnan(*parseNumber("nan")));
    EXPECT_FALSE(parseFiniteNumber("inf").has_value());
    EXPECT_FALSE(parseFiniteNumber("-inf").has_value());
    EXPECT_FALSE(parseFiniteNumber("nan").has_value());
    EXPECT_EQ(parseFiniteNumber("3.25"), 3.25);
}

} // namespace
} // namespace veridem::io
