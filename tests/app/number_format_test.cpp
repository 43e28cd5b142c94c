// How the panel writes numbers (a light particle's 0.00000407 kg read "0.00" g and a damping
// of 0.00025 read "0.0003"). Truths: the values themselves, written out by hand, and for every
// magnitude a text that reads back within half a unit of its last significant digit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "app/number_format.h"

namespace weft::app {
namespace {

TEST(NumberFormat, ALightParticlesMassShowsItsDigits) {
    const double mass_kg = 0.00000407;
    EXPECT_EQ(significant_text(mass_kg * 1e3, 3, decimals_to_reach(0.1)), "0.00407");  // g
}

TEST(NumberFormat, ASmallDampingShowsItsDigits) {
    EXPECT_EQ(significant_text(0.00025, 3, decimals_to_reach(1e-4)), "0.000250");
}

TEST(NumberFormat, OrdinaryValuesKeepAPlainLook) {
    EXPECT_EQ(significant_text(800.0, 3), "800");
    EXPECT_EQ(significant_text(12345.0, 3), "12345");  // every integer digit, no exponent
    EXPECT_EQ(significant_text(9.81, 3), "9.81");
    EXPECT_EQ(significant_text(-9.81, 3), "-9.81");
    EXPECT_EQ(significant_text(1.0, 3), "1.00");
    EXPECT_EQ(significant_text(0.5, 3, 4), "0.5000");  // the slider's low end wants 4 decimals
    EXPECT_EQ(significant_text(0.0, 3, 2), "0.00");
}

TEST(NumberFormat, ExtremeValuesUseAnExponentNotARowOfZeros) {
    EXPECT_EQ(significant_text(1e-300, 3), "1e-300");
    EXPECT_EQ(significant_text(4.07e-7, 3), "4.07e-07");
    EXPECT_EQ(significant_text(2.5e12, 3), "2.5e+12");
    // Exponent notation still carries the decimals a slider's low end needs.
    EXPECT_EQ(significant_format(4.07e-7, 3, 4), "%.4g");
}

TEST(NumberFormat, EveryMagnitudeReadsBackWithinItsLastDigit) {
    for (double exponent = -12.0; exponent <= 12.0; exponent += 0.173) {
        for (double sign : {1.0, -1.0}) {
            const double value = sign * std::pow(10.0, exponent);
            const std::string text = significant_text(value, 3);
            const double read = std::strtod(text.c_str(), nullptr);
            EXPECT_LE(std::fabs(read - value), 0.005 * std::fabs(value)) << value << " " << text;
        }
    }
}

TEST(NumberFormat, TheSuffixFollowsAndAPercentSignIsEscaped) {
    EXPECT_EQ(significant_format(1.6, 3, 2, " x rest"), "%.2f x rest");
    EXPECT_EQ(significant_format(37.6, 3, 0, " %"), "%.1f %%");
}

// Dear ImGui 1.86 reads the digits after "%." as the format's precision and takes 10^-precision
// as the smallest value a logarithmic slider reaches: whatever the value, the format must
// keep at least the decimals the slider's low end needs.
TEST(NumberFormat, EveryFormatKeepsTheDecimalsTheSlidersLowEndNeeds) {
    for (int least : {0, 1, 2, 4}) {
        for (double exponent = -320.0; exponent <= 300.0; exponent += 0.37) {
            const std::string format = significant_format(std::pow(10.0, exponent), 3, least);
            ASSERT_EQ(format.substr(0, 2), "%.") << format;
            EXPECT_GE(std::atoi(format.c_str() + 2), least) << format;
        }
    }
}

TEST(NumberFormat, DecimalsToReachASlidersLowEnd) {
    EXPECT_EQ(decimals_to_reach(1e-4), 4);
    EXPECT_EQ(decimals_to_reach(0.002), 3);
    EXPECT_EQ(decimals_to_reach(0.005), 3);
    EXPECT_EQ(decimals_to_reach(0.01), 2);
    EXPECT_EQ(decimals_to_reach(0.1), 1);
    EXPECT_EQ(decimals_to_reach(1.0), 0);
    EXPECT_EQ(decimals_to_reach(20.0), 0);
}

}  // namespace
}  // namespace weft::app
