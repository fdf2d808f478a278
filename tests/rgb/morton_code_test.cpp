// MortonFrame::code (canonical_order.h, a byte at a time from a table) against the definition bit by
// bit: each axis's cell position clamped to [0, 65535] and truncated, then the 16 bits of the three
// interleaved from the highest down, x's bit first. Every key of the LOD driver holds this code, so
// a budget's result depends on its every bit.
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <random>

#include <gtest/gtest.h>
#include <glm/vec3.hpp>

#include "rgb/lod/canonical_order.h"

namespace rgbtest {
namespace {

std::uint64_t code_by_definition(const rgb::MortonFrame& frame, const glm::dvec3& point) {
    std::array<std::uint64_t, 3> cell{};
    for (int axis = 0; axis < 3; ++axis) {
        const double position = (point[axis] - frame.lo[axis]) * frame.scale[axis];
        cell[static_cast<std::size_t>(axis)] = static_cast<std::uint64_t>(std::clamp(position, 0.0, 65535.0));
    }
    std::uint64_t code = 0;
    for (int bit = 15; bit >= 0; --bit)
        for (std::size_t axis = 0; axis < 3; ++axis) code = (code << 1) | ((cell[axis] >> bit) & 1u);
    return code;
}

// A box whose cell positions are the coordinates themselves (the default frame), so that a test
// point lies exactly on the cell it names; and an ordinary box, whose cells are inexact.
const rgb::MortonFrame kUnit{};
const rgb::MortonFrame kFrame = rgb::MortonFrame::of_box({-1.5, 0.25, 3.0}, {2.5, 0.75, 1003.0});

TEST(MortonCode, EqualsTheDefinitionOnEveryGridCoordinateOfEachAxis) {
    std::mt19937_64 random(20261205);
    std::uniform_int_distribution<int> other(0, 65535);
    for (int c = 0; c <= 65535; ++c)
        for (int axis = 0; axis < 3; ++axis) {
            glm::dvec3 cell(other(random), other(random), other(random));
            cell[axis] = c;
            ASSERT_EQ(kUnit.code(cell), code_by_definition(kUnit, cell)) << "axis " << axis << " cell " << c;
        }
}

TEST(MortonCode, EqualsTheDefinitionInsideAndAroundTheBox) {
    std::mt19937_64 random(5122026);
    std::uniform_real_distribution<double> around(-0.25, 1.25);  // a quarter of the box past each side
    for (int i = 0; i < 1'000'000; ++i) {
        const glm::dvec3 cell(65535.0 * around(random), 65535.0 * around(random), 65535.0 * around(random));
        const glm::dvec3 p = kFrame.lo + cell / kFrame.scale;
        ASSERT_EQ(kFrame.code(p), code_by_definition(kFrame, p)) << p.x << ' ' << p.y << ' ' << p.z;
    }
}

TEST(MortonCode, ClampsAtTheGridsEnds) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const std::array<double, 12> cells{-inf, -1e300, -1.0, -0.5, -0.0, 0.0, 0.5, 65534.999, 65535.0, 65535.5, 1e300, inf};
    for (double x : cells)
        for (double y : cells)
            for (double z : cells) ASSERT_EQ(kUnit.code({x, y, z}), code_by_definition(kUnit, {x, y, z})) << x << ' ' << y << ' ' << z;
    EXPECT_EQ(kUnit.code(glm::dvec3(0.0)), 0u);
    EXPECT_EQ(kUnit.code(glm::dvec3(65535.0)), (std::uint64_t(1) << 48) - 1);
    EXPECT_EQ(kUnit.code({1.0, 0.0, 0.0}), 4u);  // x in the highest bit of each triple
    EXPECT_EQ(kUnit.code({0.0, 0.0, 32768.0}), std::uint64_t(1) << 45);
    EXPECT_EQ(kUnit.code({0.0, 256.0, 0.0}), std::uint64_t(1) << 25);  // the high byte's lowest bit
}

}  // namespace
}  // namespace rgbtest
