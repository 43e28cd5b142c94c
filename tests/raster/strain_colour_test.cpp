// The strain colour map: neutral at zero, warm when stretched, cool when compressed,
// continuous, saturating at the stated strain.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "raster/strain_colour.h"

namespace weft::raster {
namespace {

TEST(StrainColour, ZeroStrainIsNeutralGrey) {
    const glm::vec3 c = colour_for_strain(0.0f);
    EXPECT_GT(c.r, 0.7f);
    EXPECT_NEAR(c.r, c.g, 0.03f);
    EXPECT_NEAR(c.g, c.b, 0.03f);
}

TEST(StrainColour, StretchIsWarmAndCompressionIsCool) {
    // Slight strains are slightly tinted (the map is continuous); from half saturation on
    // the tint is unmistakable.
    for (float strain : {0.005f, 0.02f, 0.05f, 0.08f, 0.1f, 0.5f}) {
        const glm::vec3 c = colour_for_strain(strain);
        EXPECT_GT(c.r, c.b + (strain >= 0.05f ? 0.4f : 0.0f)) << strain;
        const glm::vec3 compressed = colour_for_strain(-strain);
        EXPECT_GT(compressed.b, compressed.r + (strain >= 0.05f ? 0.3f : 0.0f)) << -strain;
    }
    // Half saturation is orange, full saturation red.
    const glm::vec3 orange = colour_for_strain(0.05f), red = colour_for_strain(0.1f);
    EXPECT_GT(orange.g, 0.4f);
    EXPECT_LT(red.g, 0.15f);
}

TEST(StrainColour, SaturatesAtTheStatedStrain) {
    EXPECT_EQ(colour_for_strain(0.1f), colour_for_strain(3.0f));
    EXPECT_EQ(colour_for_strain(-0.1f), colour_for_strain(-0.9f));
    EXPECT_NE(colour_for_strain(0.09f), colour_for_strain(0.1f));
    EXPECT_EQ(colour_for_strain(0.2f, 0.2f), colour_for_strain(0.1f));
    EXPECT_EQ(colour_for_strain(0.1f, -1.0f), colour_for_strain(0.1f));  // bad saturation: default
}

TEST(StrainColour, IsContinuous) {
    glm::vec3 previous = colour_for_strain(-0.15f);
    for (int i = 1; i <= 3000; ++i) {
        const glm::vec3 c = colour_for_strain(-0.15f + 0.3f * static_cast<float>(i) / 3000.0f);
        EXPECT_LT(glm::length(c - previous), 0.01f) << i;
        previous = c;
    }
    const glm::vec3 nan = colour_for_strain(std::nanf(""));
    EXPECT_EQ(nan, colour_for_strain(0.0f));
}

}  // namespace
}  // namespace weft::raster
